// Stereo calibration from ROS camera_info files, on a synthetic rig whose answer is known: K, D,
// and the pose of the right camera (R, T) go through OpenCV's stereoRectify into two camera_info
// files, which are written, read back and used to rectify. Rectified epipolar lines must agree
// within 0.1 px, and the focal length and baseline must come back.
#include <gmock/gmock.h>

#include <filesystem>
#include <fstream>
#include <kestrel/error.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "kestrel/stereo_calibration/camera_info.hpp"
#include "kestrel/stereo_calibration/chessboard_calibration.hpp"
#include "kestrel/stereo_calibration/stereo_rectifier.hpp"
#include "kestrel/testing/scratch_path.hpp"

using namespace kestrel;
using namespace kestrel::calibration;

namespace {

// A 640x480 pair 0.12 m apart, slightly toed in and rolled, with barrel distortion, as a real
// rig is; its camera_info pair as camera_calibration would write it.
struct Rig {
  cv::Matx33d k_left{470, 0, 318, 0, 468, 243, 0, 0, 1}, k_right{465, 0, 324, 0, 466, 238, 0, 0, 1};
  cv::Mat d_left = (cv::Mat_<double>(1, 5) << -0.30, 0.10, 0.0005, -0.0004, 0.0);
  cv::Mat d_right = (cv::Mat_<double>(1, 5) << -0.28, 0.09, -0.0003, 0.0002, 0.0);
  cv::Vec3d rotation{0.004, -0.012, 0.006};  // right camera, Rodrigues
  cv::Vec3d translation{-0.12, 0.001, -0.0005};
  CameraInfo left, right;

  Rig() {
    cv::Matx33d r;
    cv::Rodrigues(rotation, r);
    cv::Mat r1, r2, p1, p2, q;
    cv::stereoRectify(k_left, d_left, k_right, d_right, {640, 480}, r, translation, r1, r2, p1, p2, q,
                      cv::CALIB_ZERO_DISPARITY, 0);
    left = info("left", k_left, d_left, r1, p1);
    right = info("right", k_right, d_right, r2, p2);
  }
  static CameraInfo info(const std::string& name, const cv::Matx33d& k, const cv::Mat& d, const cv::Mat& r,
                         const cv::Mat& p) {
    CameraInfo c;
    c.width = 640;
    c.height = 480;
    c.camera_name = "rig/" + name;
    std::copy(k.val, k.val + 9, c.k.begin());
    c.d.assign(d.begin<double>(), d.end<double>());
    for (int i = 0; i < 9; ++i) c.r[static_cast<std::size_t>(i)] = r.at<double>(i / 3, i % 3);
    for (int i = 0; i < 12; ++i) c.p[static_cast<std::size_t>(i)] = p.at<double>(i / 4, i % 4);
    return c;
  }
};

std::filesystem::path write(const std::string& name, const std::string& text) {
  const auto dir = kestrel::testing::scratch_path("kestrel-stereo-calibration");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

}  // namespace

TEST(CameraInfoYaml, WrittenAndReadBackToTheLastBit) {
  const Rig rig;
  const auto file = write("left.yaml", to_yaml(rig.left));
  const CameraInfo back = load_camera_info(file);
  EXPECT_EQ(back.width, 640);
  EXPECT_EQ(back.camera_name, "rig/left");
  EXPECT_EQ(back.distortion_model, "plumb_bob");
  EXPECT_EQ(back.k, rig.left.k);
  EXPECT_EQ(back.d, rig.left.d);
  EXPECT_EQ(back.r, rig.left.r);
  EXPECT_EQ(back.p, rig.left.p);
}

TEST(CameraInfoYaml, ReadsTheLayoutCameraCalibrationWrites) {
  const CameraInfo c = parse_camera_info(R"(image_width: 640
image_height: 480
camera_name: narrow_stereo/left
camera_matrix:
  rows: 3
  cols: 3
  data: [485.8, 0.0, 316.2, 0.0, 483.9, 235.3, 0.0, 0.0, 1.0]
distortion_model: plumb_bob
distortion_coefficients:
  rows: 1
  cols: 5
  data: [-0.42, 0.167, 0.00045, -0.00049, 0.0]
rectification_matrix:
  rows: 3
  cols: 3
  data: [1, 0, 0, 0, 1, 0, 0, 0, 1]
projection_matrix:
  rows: 3
  cols: 4
  data: [452.1, 0.0, 322.3, 0.0, 0.0, 452.1, 242.5, 0.0, 0.0, 0.0, 1.0, 0.0]
binning_x: 0
binning_y: 0
roi: {x_offset: 0, y_offset: 0, height: 0, width: 0, do_rectify: false}
)",
                                         "left.yaml");
  EXPECT_EQ(c.k[2], 316.2);
  EXPECT_EQ(c.d.size(), 5u);
  EXPECT_EQ(c.p[6], 242.5);
  EXPECT_FALSE(c.rectified());
}

TEST(CameraInfoYaml, ABadFileSaysWhereAndWhat) {
  auto error_of = [](const std::string& text) {
    try {
      parse_camera_info(text, "cam.yaml");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string head = "image_width: 640\nimage_height: 480\n";
  const std::string k = "camera_matrix: {rows: 3, cols: 3, data: [400, 0, 320, 0, 400, 240, 0, 0, 1]}\n";
  const std::string d = "distortion_coefficients: {rows: 1, cols: 5, data: [0, 0, 0, 0, 0]}\n";
  const std::string r = "rectification_matrix: {rows: 3, cols: 3, data: [1, 0, 0, 0, 1, 0, 0, 0, 1]}\n";
  const std::string p = "projection_matrix: {rows: 3, cols: 4, data: [400, 0, 320, 0, 0, 400, 240, 0, 0, 0, 1, 0]}\n";
  EXPECT_EQ(error_of(head + k + d + r + p), "accepted");
  EXPECT_THAT(error_of(head + k + d + r), ::testing::HasSubstr("cam.yaml:1:1: no 'projection_matrix'"));
  EXPECT_THAT(
      error_of(head + "camera_matrix: {rows: 3, cols: 3, data: [400, 0, 320, 0, 400, 240, 0, 0]}\n" + d + r + p),
      ::testing::HasSubstr("cam.yaml:3:41: camera_matrix.data must hold 9 numbers"));
  EXPECT_THAT(error_of(head + k + d + r + "projection_matrix: {rows: 3, cols: 3, data: [1]}\n"),
              ::testing::HasSubstr("projection_matrix is 3x3, not 3x4"));
  EXPECT_THAT(
      error_of(head + "camera_matrix: {rows: 3, cols: 3, data: [400, 0, x, 0, 400, 240, 0, 0, 1]}\n" + d + r + p),
      ::testing::HasSubstr("cam.yaml:3:50: camera_matrix.data[2] 'x' is not a number"));
  EXPECT_THAT(error_of(head + k + "distortion_model: kannala\n" + d + r + p),
              ::testing::HasSubstr("cam.yaml:4:19: distortion_model 'kannala'"));
  EXPECT_THAT(error_of("image_width: [\n"), ::testing::HasSubstr("cam.yaml:"));
  EXPECT_THAT(error_of("- 1\n"), ::testing::HasSubstr("a camera_info file is a map"));
  EXPECT_THROW(load_camera_info("/nonexistent/left.yaml"), Error);
}

TEST(StereoRectifier, RecoversFocalLengthAndBaselineAndAlignsEpipolarLines) {
  const Rig rig;
  const StereoRectifier rectifier(load_camera_info(write("l.yaml", to_yaml(rig.left))),
                                  load_camera_info(write("r.yaml", to_yaml(rig.right))));
  EXPECT_FALSE(rectifier.passthrough());
  EXPECT_EQ(rectifier.calibration().fx, rig.left.p[0]);
  EXPECT_NEAR(rectifier.calibration().baseline_m, cv::norm(rig.translation), 1e-9);
  // Points 2 to 20 m ahead, seen by both raw cameras.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0), depth(2.0, 20.0);
  std::vector<cv::Point3d> world;
  for (int i = 0; i < 400; ++i) {
    const double z = depth(rng);
    world.push_back({u(rng) * 0.5 * z, u(rng) * 0.35 * z, z});
  }
  cv::Matx33d r;
  cv::Rodrigues(rig.rotation, r);
  std::vector<cv::Point2d> l, rr;
  cv::projectPoints(world, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), rig.k_left, rig.d_left, l);
  cv::projectPoints(world, rig.rotation, rig.translation, rig.k_right, rig.d_right, rr);
  std::vector<cv::Point2f> lf, rf;
  for (std::size_t i = 0; i < l.size(); ++i) {
    if (l[i].x < 0 || l[i].x > 639 || l[i].y < 0 || l[i].y > 479 || rr[i].x < 0 || rr[i].x > 639 || rr[i].y < 0 ||
        rr[i].y > 479)
      continue;
    lf.emplace_back(l[i]);
    rf.emplace_back(rr[i]);
  }
  ASSERT_GT(lf.size(), 200u);
  const EpipolarError e = epipolar_error(rig.left, rig.right, lf, rf);
  EXPECT_LT(e.max_px, 0.1);
  EXPECT_LT(e.mean_px, 0.02);
  // The raw points, taken as rectified, are far off: the test can tell.
  double raw_max = 0;
  for (std::size_t i = 0; i < lf.size(); ++i) raw_max = std::max(raw_max, std::abs(double(lf[i].y - rf[i].y)));
  EXPECT_GT(raw_max, 1.0);
}

TEST(StereoRectifier, RectifiesRawImagesBackOntoTheRectifiedPair) {
  const Rig rig;
  const StereoRectifier rectifier(rig.left, rig.right);
  // A rectified "scene": smoothed noise, the right image the left shifted by 8 px (a plane at
  // fx b / 8 m). The raw images are what each raw camera saw of it.
  cv::Mat texture(480, 640, CV_8UC1);
  cv::randu(texture, 0, 255);
  cv::GaussianBlur(texture, texture, {0, 0}, 2.0);
  const cv::Mat rect_left = texture;
  cv::Mat rect_right;
  cv::warpAffine(texture, rect_right, cv::Matx23d(1, 0, -8, 0, 1, 0), texture.size(), cv::INTER_LINEAR,
                 cv::BORDER_REFLECT);
  auto raw_of = [](const cv::Mat& rectified, const CameraInfo& c) {
    // For each raw pixel, where it lands in the rectified image.
    std::vector<cv::Point2f> pixels;
    for (int y = 0; y < 480; ++y)
      for (int x = 0; x < 640; ++x) pixels.emplace_back(static_cast<float>(x), static_cast<float>(y));
    std::vector<cv::Point2f> at;
    cv::undistortPoints(pixels, at, cv::Matx33d(c.k.data()), cv::Mat(c.d), cv::Matx33d(c.r.data()),
                        cv::Matx33d(c.p[0], c.p[1], c.p[2], c.p[4], c.p[5], c.p[6], c.p[8], c.p[9], c.p[10]));
    cv::Mat map(480, 640, CV_32FC2, at.data());
    cv::Mat raw;
    cv::remap(rectified, raw, map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_REFLECT);
    return raw;
  };
  cv::Mat left, right;
  rectifier.rectify(raw_of(rect_left, rig.left), raw_of(rect_right, rig.right), left, right);
  const cv::Rect inner(80, 60, 480, 360);
  cv::Mat a, b;
  left(inner).convertTo(a, CV_32F);
  rect_left(inner).convertTo(b, CV_32F);
  const cv::Point2d shift_left = cv::phaseCorrelate(a, b);
  right(inner).convertTo(a, CV_32F);
  rect_right(inner).convertTo(b, CV_32F);
  const cv::Point2d shift_right = cv::phaseCorrelate(a, b);
  EXPECT_LT(std::abs(shift_left.x), 0.1);
  EXPECT_LT(std::abs(shift_left.y), 0.1);
  EXPECT_LT(std::abs(shift_right.x), 0.1);
  EXPECT_LT(std::abs(shift_right.y), 0.1);  // the epipolar lines agree
  EXPECT_THROW(rectifier.rectify(left(inner), right(inner), a, b), Error);
}

TEST(StereoRectifier, RefusesFilesThatAreNotOneRectifiedPair) {
  const Rig rig;
  EXPECT_THROW(StereoRectifier(rig.right, rig.left), Error);  // swapped: the baseline is in the left P
  CameraInfo other = rig.right;
  other.p[0] *= 1.01;
  EXPECT_THROW(StereoRectifier(rig.left, other), Error);
  other = rig.right;
  other.width = 1280;
  EXPECT_THROW(StereoRectifier(rig.left, other), Error);
  CameraInfo rectified = rig.left;
  rectified.d.assign(5, 0.0);
  rectified.r = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  rectified.k = {rectified.p[0], 0, rectified.p[2], 0, rectified.p[5], rectified.p[6], 0, 0, 1};
  CameraInfo rectified_right = rectified;
  rectified_right.p[3] = -rectified.p[0] * 0.12;
  EXPECT_TRUE(StereoRectifier(rectified, rectified_right).passthrough());
}

namespace {

// What a raw camera (K, D) sees of a chessboard at pose (R, t) in its frame: each raw pixel
// undistorted to a ray, the ray met with the board's plane, the board's texture sampled there;
// 2 x 2 samples a pixel, averaged, as a sensor integrates light over it.
// The rays of a raw camera's 2 x 2 samples a pixel, in its normalised image plane.
std::vector<cv::Point2f> sample_rays(const cv::Matx33d& k, const cv::Mat& d) {
  std::vector<cv::Point2f> samples;
  for (int y = 0; y < 960; ++y)
    for (int x = 0; x < 1280; ++x)
      samples.emplace_back(static_cast<float>((x + 0.5) / 2 - 0.5), static_cast<float>((y + 0.5) / 2 - 0.5));
  std::vector<cv::Point2f> rays;
  cv::undistortPoints(samples, rays, k, d, cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-12));
  return rays;
}

cv::Mat view_of_board(const cv::Mat& texture, double metres_per_texel, const std::vector<cv::Point2f>& rays,
                      const cv::Matx33d& r, const cv::Vec3d& t) {
  // Plane z = 0 of the board: camera point = r * (X, Y, 0) + t, so the ray (x, y, 1) * s meets it
  // where [r1 r2 t] (X, Y, 1) = s (x, y, 1).
  const cv::Matx33d h(r(0, 0), r(0, 1), t[0], r(1, 0), r(1, 1), t[1], r(2, 0), r(2, 1), t[2]);
  const cv::Matx33d h_inv = h.inv();
  cv::Mat map(960, 1280, CV_32FC2);
  for (int i = 0; i < 960 * 1280; ++i) {
    const auto& ray = rays[static_cast<std::size_t>(i)];
    const cv::Vec3d p = h_inv * cv::Vec3d(ray.x, ray.y, 1);
    // texel k covers [k, k + 1) of the board, and remap samples a texel's centre at k
    map.at<cv::Vec2f>(i / 1280, i % 1280) = {static_cast<float>(p[0] / p[2] / metres_per_texel - 0.5),
                                             static_cast<float>(p[1] / p[2] / metres_per_texel - 0.5)};
  }
  cv::Mat fine, view;
  cv::remap(texture, fine, map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(128));
  cv::resize(fine, view, {640, 480}, 0, 0, cv::INTER_AREA);
  return view;
}

}  // namespace

TEST(ChessboardCalibration, RecoversAKnownRigFromRenderedBoardPairs) {
  const Rig rig;
  // A board of 9 x 7 squares of 25 mm (8 x 6 inner corners), 40 texels a square, white margin;
  // texel (0, 0) of the squares is the board's origin.
  const int px = 40;
  cv::Mat texture(7 * px + 2 * px, 9 * px + 2 * px, CV_8UC1, cv::Scalar(255));
  for (int r = 0; r < 7; ++r)
    for (int c = 0; c < 9; ++c)
      if ((r + c) % 2 == 0) texture(cv::Rect(px + c * px, px + r * px, px, px)).setTo(0);
  const double metres_per_texel = 0.025 / px;
  // The inner corner (0, 0) is at texel (2 px, 2 px): the board frame's origin there.
  const cv::Vec3d corner_origin(-2 * px * metres_per_texel, -2 * px * metres_per_texel, 0);
  cv::Matx33d r_lr;
  cv::Rodrigues(rig.rotation, r_lr);
  const auto left_rays = sample_rays(rig.k_left, rig.d_left), right_rays = sample_rays(rig.k_right, rig.d_right);
  std::vector<std::pair<cv::Mat, cv::Mat>> pairs;
  std::vector<std::string> names;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> tilt(-0.5, 0.5), along(-0.16, 0.16), depth(0.4, 0.8);
  for (int i = 0; i < 24; ++i) {
    cv::Matx33d r;
    cv::Rodrigues(cv::Vec3d(tilt(rng), tilt(rng), 0.3 * tilt(rng)), r);
    const cv::Vec3d t_corner(along(rng) - 0.09, along(rng) * 0.7 - 0.06, depth(rng));
    const cv::Vec3d t = t_corner + r * corner_origin;  // where texel (0, 0) lies
    const cv::Mat left = view_of_board(texture, metres_per_texel, left_rays, r, t);
    const cv::Mat right = view_of_board(texture, metres_per_texel, right_rays, r_lr * r, r_lr * t + rig.translation);
    pairs.emplace_back(left, right);
    names.push_back("view " + std::to_string(i));
  }
  const ChessboardCalibration c = calibrate_stereo(pairs, names, {{8, 6}, 0.025});
  EXPECT_GE(c.pairs_used, 10u) << ::testing::PrintToString(c.skipped);
  EXPECT_LT(c.rms_px, 0.3);
  EXPECT_NEAR(c.rig.k_left(0, 0), rig.k_left(0, 0), 0.01 * rig.k_left(0, 0));
  EXPECT_NEAR(c.rig.k_right(1, 1), rig.k_right(1, 1), 0.01 * rig.k_right(1, 1));
  EXPECT_NEAR(cv::norm(c.rig.t), cv::norm(rig.translation), 0.01 * cv::norm(rig.translation));
  EXPECT_NEAR(-c.right.p[3] / c.right.p[0], cv::norm(rig.translation), 0.01 * cv::norm(rig.translation));
  // What the pair's rotation must get right: rows that agree after rectifying (a turn about the
  // baseline itself is taken up by rectification, so R is not compared element by element).
  EXPECT_LT(c.epipolar.mean_px, 0.1);
  EXPECT_LT(c.epipolar.max_px, 0.5);
  // The files it makes build the rectifier the drivers use.
  EXPECT_NO_THROW(StereoRectifier(c.left, c.right));
  // Without enough views of the board, it says so.
  std::vector<std::pair<cv::Mat, cv::Mat>> blank(
      6, {cv::Mat(480, 640, CV_8UC1, cv::Scalar(90)), cv::Mat(480, 640, CV_8UC1, cv::Scalar(90))});
  EXPECT_THROW(calibrate_stereo(blank, {}, {{8, 6}, 0.025}), Error);
}

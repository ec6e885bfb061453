// `stereo_images` on pairs written from rendered frames: a 2 s run of graphs/paper_detection.yaml
// is recorded; its frames are written as PNG pairs, once rectified as they are and once as a
// distorting rig's raw cameras would have seen them, with each set's camera_info files. Each set
// replayed through stereo_images into the same chain, scored against the recorded truth, must
// give the rendered graph's detections: exactly for the rectified pairs, and to what two
// interpolations change for the raw ones.
#include <gmock/gmock.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <kestrel/messages/stereo_frame.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/stereo_calibration/camera_info.hpp"
#include "kestrel/stereo_calibration/stereo_rectifier.hpp"
#include "kestrel/stereo_images/pair_source.hpp"
#include "kestrel/testing/plugins.hpp"
#include "kestrel/testing/scratch_path.hpp"
#include "recorded_channels.hpp"

using namespace kestrel;
namespace fs = std::filesystem;

namespace {

PluginHost& plugins() { return kestrel::testing::built_plugins(); }

// Per process: ctest runs each test as its own process, in parallel, and each records its own run.
fs::path scratch(const std::string& name) {
  const auto dir = kestrel::testing::scratch_path("kestrel-stereo-images") / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

RunResult run(const GraphSource& graph, const std::vector<const GraphSource*>& fragments, double duration) {
  auto built = build_graph(graph, plugins().registry(), {}, fragments);
  EXPECT_TRUE(built.graph) << built.diagnostics.str();
  if (!built.graph) return {};
  RunOptions options;
  options.duration_s = duration;
  return run_graph(*built.graph, plugins().registry(), options);
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

// A raw camera's image of a rectified one: for each raw pixel, where it lands after rectifying.
cv::Mat raw_of(const cv::Mat& rectified, const calibration::CameraInfo& c) {
  std::vector<cv::Point2f> pixels;
  for (int y = 0; y < rectified.rows; ++y)
    for (int x = 0; x < rectified.cols; ++x) pixels.emplace_back(static_cast<float>(x), static_cast<float>(y));
  std::vector<cv::Point2f> at;
  cv::undistortPoints(pixels, at, cv::Matx33d(c.k.data()), cv::Mat(c.d), cv::Matx33d(c.r.data()),
                      cv::Matx33d(c.p[0], c.p[1], c.p[2], c.p[4], c.p[5], c.p[6], c.p[8], c.p[9], c.p[10]));
  const cv::Mat map(rectified.rows, rectified.cols, CV_32FC2, at.data());
  cv::Mat raw;
  cv::remap(rectified, raw, map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  return raw;
}

struct Recorded {
  fs::path dir, mcap;
  nlohmann::json detection;
  std::vector<msg::StereoFrame> frames;
};

const Recorded& recorded() {
  static const Recorded r = [] {
    Recorded out;
    out.dir = scratch("live");
    out.mcap = out.dir / "run.mcap";
    const auto graph = GraphSource::from_file(KESTREL_SOURCE_DIR "/graphs/paper_detection.yaml");
    const auto recorder = GraphSource::from_string(
        "nodes: [{id: recorder, type: recorder, params: {file: '" + out.mcap.string() + "'}}]", "--record");
    const RunResult live = run(graph, {&recorder}, 2.0);
    EXPECT_EQ(live.outcome, RunOutcome::completed) << (live.errors.empty() ? "" : live.errors.front());
    out.detection = live.report.at("detection");
    replay::RecordedChannels channels(out.mcap, {{"frame", "kestrel.StereoFrame", "/camera/frame"}});
    channels.replay(0, channels.end_time() + 1, [&](std::size_t, std::shared_ptr<const void> m) {
      out.frames.push_back(*static_cast<const msg::StereoFrame*>(m.get()));
    });
    return out;
  }();
  return r;
}

// The chain of graphs/paper_detection.yaml fed by stereo_images, scored against the recorded truth.
std::string replay_graph(const std::string& images_params) {
  return "kestrel: 1\nexecutor: {type: lockstep, default_policy: latest}\nseed: 1\n"
         "include: ['" KESTREL_SOURCE_DIR
         "/graphs/parts/detection_chain.yaml']\n"
         "nodes:\n"
         "  - {id: pairs, type: stereo_images, params: {" +
         images_params +
         "}}\n"
         "  - {id: truth, type: mcap_source, params: {file: '" +
         recorded().mcap.string() +
         "', truth_topic: /camera/truth}}\n"
         "connections:\n"
         "  - {from: pairs.frame, to: depth.frame}\n"
         "  - {from: pairs.frame, to: refine.frame, policy: fifo 16}\n"
         "  - {from: truth.truth, to: score.truth, policy: fifo 64}\n"
         "  - {from: truth.truth, to: plot.truth, policy: fifo 64}\n";
}

calibration::CameraInfo rectified_info(const msg::StereoCalibration& c, bool right) {
  calibration::CameraInfo i;
  i.width = c.width;
  i.height = c.height;
  i.k = {c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1};
  i.d.assign(5, 0.0);
  i.r = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  i.p = {c.fx, 0, c.cx, right ? -c.fx * c.baseline_m : 0.0, 0, c.fy, c.cy, 0, 0, 0, 1, 0};
  return i;
}

}  // namespace

TEST(StereoImages, RectifiedPairsWrittenFromRenderedFramesGiveTheRenderedGraphsDetections) {
  const Recorded& live = recorded();
  ASSERT_EQ(live.frames.size(), 60u);
  const auto dir = scratch("rectified");
  fs::create_directories(dir / "left");
  fs::create_directories(dir / "right");
  for (std::size_t k = 0; k < live.frames.size(); ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "%06zu.png", k);
    cv::imwrite((dir / "left" / name).string(), live.frames[k].left);
    cv::imwrite((dir / "right" / name).string(), live.frames[k].right);
  }
  const auto& c = live.frames[0].calibration;
  write(dir / "left.yaml", calibration::to_yaml(rectified_info(c, false)));
  write(dir / "right.yaml", calibration::to_yaml(rectified_info(c, true)));
  const auto graph = GraphSource::from_string(
      replay_graph("left: '" + (dir / "left").string() + "', right: '" + (dir / "right").string() + "', left_info: '" +
                   (dir / "left.yaml").string() + "', right_info: '" + (dir / "right.yaml").string() +
                   "', images: rectified"),
      (dir / "graph.yaml").string());
  const RunResult r = run(graph, {}, 2.0);
  ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  EXPECT_EQ(r.report.at("pairs").at("published"), 60);
  EXPECT_EQ(r.report.at("detection"), live.detection);  // lossless PNGs at the same times: the same figures
}

TEST(StereoImages, RawPairsOfADistortingRigAreRectifiedIntoTheRenderedGraphsDetections) {
  const Recorded& live = recorded();
  const auto& c = live.frames[0].calibration;
  // A rig whose rectified camera is the rendered one: raw cameras with barrel distortion, turned
  // a little from the rectified orientation, so that rectifying is a real remap.
  auto raw_camera = [&](bool right, double turn) {
    calibration::CameraInfo i = rectified_info(c, right);
    i.k = {c.fx * 1.03, 0, c.cx + 3, 0, c.fy * 1.03, c.cy - 2, 0, 0, 1};
    i.d = {-0.12, 0.03, 0.0004, -0.0003, 0.0};
    cv::Matx33d r;
    cv::Rodrigues(cv::Vec3d(0.003 * turn, -0.006 * turn, 0.002 * turn), r);
    std::copy(r.val, r.val + 9, i.r.begin());
    return i;
  };
  const auto left_info = raw_camera(false, 1.0), right_info = raw_camera(true, -1.0);
  const auto dir = scratch("raw");
  fs::create_directories(dir / "left");
  fs::create_directories(dir / "right");
  for (std::size_t k = 0; k < live.frames.size(); ++k) {
    cv::imwrite((dir / "left" / ("l" + std::to_string(k) + ".png")).string(), raw_of(live.frames[k].left, left_info));
    cv::imwrite((dir / "right" / ("r" + std::to_string(k) + ".png")).string(),
                raw_of(live.frames[k].right, right_info));
  }
  write(dir / "left.yaml", calibration::to_yaml(left_info));
  write(dir / "right.yaml", calibration::to_yaml(right_info));
  const std::string pattern_left = (dir / "left" / "l%d.png").string(),
                    pattern_right = (dir / "right" / "r%d.png").string();
  const auto graph = GraphSource::from_string(
      replay_graph("left: '" + pattern_left + "', right: '" + pattern_right + "', left_info: '" +
                   (dir / "left.yaml").string() + "', right_info: '" + (dir / "right.yaml").string() + "'"),
      (dir / "graph.yaml").string());
  const RunResult r = run(graph, {}, 2.0);
  ASSERT_EQ(r.outcome, RunOutcome::completed) << (r.errors.empty() ? "" : r.errors.front());
  EXPECT_EQ(r.report.at("pairs").at("rectified_here"), true);
  const auto& d = r.report.at("detection");
  EXPECT_EQ(d.at("tp"), live.detection.at("tp"));
  EXPECT_EQ(d.at("fp"), live.detection.at("fp"));
  // Two bilinear interpolations smooth the silhouette by under a pixel: 5 m / fx sideways, and
  // a tenth of a pixel of disparity in depth (docs/hardware.md).
  const double pixel_at_5m = 5.0 / c.fx, tenth_disparity = 0.1 * 25.0 / (c.fx * c.baseline_m);
  for (const char* axis : {"x", "y"})
    EXPECT_NEAR(d.at("rmse_m").at(axis).get<double>(), live.detection.at("rmse_m").at(axis).get<double>(), pixel_at_5m)
        << axis;
  EXPECT_NEAR(d.at("rmse_m").at("z").get<double>(), live.detection.at("rmse_m").at("z").get<double>(), tenth_disparity);
}

TEST(StereoImages, ASideBySideVideoSplitsIntoPairsAndBadSourcesSayWhy) {
  const auto dir = scratch("video");
  const auto file = (dir / "pairs.avi").string();
  {
    cv::VideoWriter out(file, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30, {128, 48});
    ASSERT_TRUE(out.isOpened());
    for (int k = 0; k < 5; ++k) {
      cv::Mat frame(48, 128, CV_8UC3, cv::Scalar(40, 40, 40));
      frame.colRange(64, 128).setTo(cv::Scalar(200, 200, 200));
      out.write(frame);
    }
  }
  stereo_images::PairSource video({"", "", file, 0});
  std::size_t n = 0;
  while (auto pair = video.next()) {
    ++n;
    EXPECT_EQ(pair->first.cols, 64);
    EXPECT_LT(cv::mean(pair->first)[0], 80);  // the left half
    EXPECT_GT(cv::mean(pair->second)[0], 160);
  }
  EXPECT_EQ(n, 5u);

  fs::create_directories(dir / "l");
  fs::create_directories(dir / "r");
  cv::imwrite((dir / "l" / "a.png").string(), cv::Mat(8, 8, CV_8UC1, cv::Scalar(1)));
  EXPECT_THROW(stereo_images::PairSource({(dir / "l").string(), (dir / "r").string(), "", 0}),
               Error);  // no right image
  cv::imwrite((dir / "r" / "a.png").string(), cv::Mat(8, 6, CV_8UC1, cv::Scalar(1)));
  stereo_images::PairSource mismatched({(dir / "l").string(), (dir / "r").string(), "", 0});
  EXPECT_THROW(mismatched.next(), Error);  // sizes differ
  EXPECT_THROW(stereo_images::PairSource({(dir / "l" / "%d.png").string(), (dir / "r" / "%s.png").string(), "", 0}),
               Error);
  EXPECT_THROW(stereo_images::PairSource({"", "", (dir / "missing.avi").string(), 0}), Error);
}

TEST(StereoImages, TwoImageFilesAreOnePair) {
  const auto dir = scratch("files");
  cv::imwrite((dir / "left.png").string(), cv::Mat(8, 8, CV_8UC1, cv::Scalar(10)));
  cv::imwrite((dir / "right.png").string(), cv::Mat(8, 8, CV_8UC1, cv::Scalar(20)));
  stereo_images::PairSource one({(dir / "left.png").string(), (dir / "right.png").string(), "", 0});
  EXPECT_EQ(one.size(), 1u);
  EXPECT_EQ(one.kind(), "one pair");
  const auto pair = one.next();
  ASSERT_TRUE(pair);
  EXPECT_EQ(pair->first.at<std::uint8_t>(0, 0), 10);
  EXPECT_EQ(pair->second.at<std::uint8_t>(0, 0), 20);
  EXPECT_FALSE(one.next());
  // A file beside a folder, or a file that is not an image, says which.
  try {
    stereo_images::PairSource({(dir / "left.png").string(), dir.string(), "", 0});
    ADD_FAILURE() << "a file and a folder made a source";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("two image files"));
  }
  std::ofstream(dir / "notes.png") << "not an image";
  stereo_images::PairSource text({(dir / "notes.png").string(), (dir / "right.png").string(), "", 0});
  try {
    (void)text.next();
    ADD_FAILURE() << "a text file read as an image";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("notes.png"));
  }
}

#include "kestrel/stereo_calibration/chessboard_calibration.hpp"

#include <algorithm>
#include <kestrel/error.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace kestrel::calibration {

namespace {

cv::Mat grey(const cv::Mat& m) {
  if (m.channels() == 1) return m;
  cv::Mat g;
  cv::cvtColor(m, g, cv::COLOR_BGR2GRAY);
  return g;
}

bool corners(const cv::Mat& image, const cv::Size& board, std::vector<cv::Point2f>& out) {
  const cv::Mat g = grey(image);
  if (!cv::findChessboardCorners(g, board, out, cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE))
    return false;
  // The refinement window must hold one corner only: under half the smallest square seen, which
  // shrinks with distance and tilt.
  double nearest = 1e9;
  for (int r = 0; r < board.height; ++r)
    for (int c = 0; c + 1 < board.width; ++c) {
      const auto i = static_cast<std::size_t>(r * board.width + c);
      nearest = std::min(nearest, static_cast<double>(cv::norm(out[i + 1] - out[i])));
    }
  const int half = std::clamp(static_cast<int>(nearest * 0.4), 2, 11);
  cv::cornerSubPix(g, out, {half, half}, {-1, -1},
                   cv::TermCriteria(cv::TermCriteria::EPS | cv::TermCriteria::COUNT, 50, 1e-3));
  return true;
}

}  // namespace

ChessboardCalibration calibrate_stereo(const std::vector<std::pair<cv::Mat, cv::Mat>>& pairs,
                                       const std::vector<std::string>& names, const ChessboardOptions& options) {
  if (pairs.empty()) throw Error("no image pairs to calibrate from");
  const cv::Size size = pairs.front().first.size();
  std::vector<cv::Point3f> board;
  for (int r = 0; r < options.inner_corners.height; ++r)
    for (int c = 0; c < options.inner_corners.width; ++c)
      board.emplace_back(static_cast<float>(c * options.square_m), static_cast<float>(r * options.square_m), 0.0f);
  std::vector<std::vector<cv::Point3f>> objects;
  std::vector<std::vector<cv::Point2f>> left_points, right_points;
  ChessboardCalibration out;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::string name = i < names.size() ? names[i] : "pair " + std::to_string(i);
    if (pairs[i].first.size() != size || pairs[i].second.size() != size) {
      out.skipped.push_back(name + ": another image size");
      continue;
    }
    std::vector<cv::Point2f> l, r;
    const bool in_left = corners(pairs[i].first, options.inner_corners, l);
    const bool in_right = in_left && corners(pairs[i].second, options.inner_corners, r);
    if (!in_left || !in_right) {
      out.skipped.push_back(name + ": the whole board is not seen in the " + (in_left ? "right" : "left") + " image");
      continue;
    }
    objects.push_back(board);
    left_points.push_back(l);
    right_points.push_back(r);
  }
  out.pairs_used = objects.size();
  if (objects.size() < 5)
    throw Error("the board was found in both images of " + std::to_string(objects.size()) +
                " pair(s); calibrating needs " +
                "at least 5, better 20 or more, near and far, tilted, over the whole image");
  cv::Mat k1, d1, k2, d2, r, t, e, f;
  std::vector<cv::Mat> rv, tv;
  cv::calibrateCamera(objects, left_points, size, k1, d1, rv, tv);
  cv::calibrateCamera(objects, right_points, size, k2, d2, rv, tv);
  out.rms_px = cv::stereoCalibrate(objects, left_points, right_points, k1, d1, k2, d2, size, r, t, e, f,
                                   cv::CALIB_FIX_INTRINSIC);
  out.rig.width = size.width;
  out.rig.height = size.height;
  out.rig.k_left = cv::Matx33d(k1);
  out.rig.k_right = cv::Matx33d(k2);
  out.rig.d_left.assign(d1.begin<double>(), d1.end<double>());
  out.rig.d_right.assign(d2.begin<double>(), d2.end<double>());
  out.rig.r = cv::Matx33d(r);
  out.rig.t = cv::Vec3d(t.at<double>(0), t.at<double>(1), t.at<double>(2));
  std::tie(out.left, out.right) = camera_infos(out.rig);
  std::vector<cv::Point2f> all_left, all_right;
  for (std::size_t i = 0; i < left_points.size(); ++i) {
    all_left.insert(all_left.end(), left_points[i].begin(), left_points[i].end());
    all_right.insert(all_right.end(), right_points[i].begin(), right_points[i].end());
  }
  out.epipolar = epipolar_error(out.left, out.right, all_left, all_right);
  return out;
}

}  // namespace kestrel::calibration

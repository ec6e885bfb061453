#include "disparity_score.hpp"

#include <algorithm>
#include <cmath>
#include <kestrel/error.hpp>
#include <opencv2/imgcodecs.hpp>
#include <vector>

namespace kestrel::stereo {

namespace {
bool known(float v) { return std::isfinite(v) && v > 0.0f; }
}  // namespace

DisparityScore score_disparity(const cv::Mat& estimate_px, const cv::Mat& truth_px) {
  if (estimate_px.type() != CV_32F || truth_px.type() != CV_32F || estimate_px.size() != truth_px.size())
    throw Error("score_disparity: two CV_32F maps of one size are needed");
  DisparityScore s;
  std::vector<float> errors;
  std::size_t over1 = 0, over2 = 0;
  for (int v = 0; v < truth_px.rows; ++v) {
    const float* t = truth_px.ptr<float>(v);
    const float* e = estimate_px.ptr<float>(v);
    for (int u = 0; u < truth_px.cols; ++u) {
      if (!known(t[u])) continue;
      ++s.known;
      if (!known(e[u])) continue;
      ++s.matched;
      const float error = std::abs(e[u] - t[u]);
      errors.push_back(error);
      over1 += error > 1.0f;
      over2 += error > 2.0f;
    }
  }
  if (s.matched) {
    const auto m = static_cast<double>(s.matched);
    s.bad1 = static_cast<double>(over1) / m;
    s.bad2 = static_cast<double>(over2) / m;
    auto middle = errors.begin() + static_cast<std::ptrdiff_t>(errors.size() / 2);
    std::nth_element(errors.begin(), middle, errors.end());
    s.median_error_px = *middle;
  }
  if (s.known) s.bad2_all = static_cast<double>(s.known - s.matched + over2) / static_cast<double>(s.known);
  return s;
}

cv::Mat disparity_in_pixels(const cv::Mat& disparity16) {
  if (disparity16.type() != CV_16S) throw Error("disparity_in_pixels: a CV_16S disparity is needed");
  cv::Mat px(disparity16.size(), CV_32F);
  for (int v = 0; v < px.rows; ++v) {
    const short* d = disparity16.ptr<short>(v);
    float* out = px.ptr<float>(v);
    for (int u = 0; u < px.cols; ++u) out[u] = d[u] < 0 ? NAN : static_cast<float>(d[u]) / 16.0f;
  }
  return px;
}

cv::Mat read_disparity_truth(const std::filesystem::path& file) {
  const cv::Mat raw = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
  if (raw.empty()) throw Error("cannot read a disparity map from " + file.string());
  cv::Mat truth;
  if (raw.type() == CV_32F) {
    truth = raw.clone();
  } else if (raw.type() == CV_8U) {
    raw.convertTo(truth, CV_32F);
  } else {
    throw Error(file.string() + ": a disparity map is one channel of float (PFM) or 8-bit (PNG)");
  }
  truth.setTo(NAN, truth <= 0.0f);
  return truth;
}

}  // namespace kestrel::stereo

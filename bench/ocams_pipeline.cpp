// The oCamS driver's cost per stereo pair: a raw frame unpacked into its two GRBG mosaics,
// demosaiced and rectified through distortion maps (a calibration with real lens distortion, so
// that remap does its full work), at 640x480 and 1280x960, grey and colour. docs/hardware.md's
// targets: under 3 ms and 10 ms a pair.
#include <benchmark/benchmark.h>

#include <opencv2/calib3d.hpp>

#include "frame_pipeline.hpp"

namespace {

using namespace kestrel;

// A 0.12 m rig with barrel distortion, scaled to the size (the oCamS's lenses at 640x480).
std::shared_ptr<calibration::StereoRectifier> rectifier(int width, int height) {
  const double s = width / 640.0;
  const cv::Matx33d k(470 * s, 0, 318 * s, 0, 468 * s, 243 * s, 0, 0, 1);
  const cv::Mat d = (cv::Mat_<double>(1, 5) << -0.30, 0.10, 0.0005, -0.0004, 0.0);
  cv::Matx33d r;
  cv::Rodrigues(cv::Vec3d(0.004, -0.012, 0.006), r);
  cv::Mat r1, r2, p1, p2, q;
  cv::stereoRectify(k, d, k, d, {width, height}, r, cv::Vec3d(-0.12, 0.001, 0), r1, r2, p1, p2, q,
                    cv::CALIB_ZERO_DISPARITY, 0);
  auto info = [&](const cv::Mat& rr, const cv::Mat& p) {
    calibration::CameraInfo c;
    c.width = width;
    c.height = height;
    std::copy(k.val, k.val + 9, c.k.begin());
    c.d.assign(d.begin<double>(), d.end<double>());
    for (int i = 0; i < 9; ++i) c.r[static_cast<std::size_t>(i)] = rr.at<double>(i / 3, i % 3);
    for (int i = 0; i < 12; ++i) c.p[static_cast<std::size_t>(i)] = p.at<double>(i / 4, i % 4);
    return c;
  };
  return std::make_shared<calibration::StereoRectifier>(info(r1, p1), info(r2, p2));
}

void BM_OcamsPipeline(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0)), height = width * 3 / 4;
  const bool color = state.range(1) != 0;
  const ocams::FramePipeline pipeline({width, height, color}, rectifier(width, height));
  cv::Mat left(height, width, CV_8UC1), right(height, width, CV_8UC1);
  cv::randu(left, 0, 255);
  cv::randu(right, 0, 255);
  const auto raw = ocams::pack(left, right, 1234);
  std::uint64_t k = 0;
  for (auto _ : state) {
    auto frame = pipeline.process(raw, Time(0), k++);
    benchmark::DoNotOptimize(frame.left.data);
  }
  state.counters["pairs_per_s"] = benchmark::Counter(static_cast<double>(k), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_OcamsPipeline)
    ->ArgNames({"width", "color"})
    ->Args({640, 0})
    ->Args({640, 1})
    ->Args({1280, 0})
    ->Args({1280, 1})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

#include "frame_pipeline.hpp"

#include <kestrel/error.hpp>
#include <opencv2/imgproc.hpp>

namespace kestrel::ocams {

cv::Mat demosaic_grbg(const cv::Mat& bayer, bool color) {
  cv::Mat out;
  cv::cvtColor(bayer, out, color ? cv::COLOR_BayerGB2BGR : cv::COLOR_BayerGB2GRAY);
  return out;
}

FramePipeline::FramePipeline(const PipelineOptions& options,
                             std::shared_ptr<const calibration::StereoRectifier> rectifier)
    : options_(options), rectifier_(std::move(rectifier)) {
  const auto& c = rectifier_->calibration();
  if (c.width != options.width || c.height != options.height)
    throw Error("the calibration is for " + std::to_string(c.width) + "x" + std::to_string(c.height) +
                " images, the camera streams " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                ": calibrate at the streamed size");
}

msg::StereoFrame FramePipeline::process(std::span<const std::uint8_t> raw, Time stamp, std::uint64_t frame_index,
                                        std::uint32_t* device_ms) const {
  const BayerPair pair = unpack(raw, options_.width, options_.height);
  if (device_ms) *device_ms = pair.device_ms;
  msg::StereoFrame frame;
  frame.stamp = stamp;
  frame.frame_index = frame_index;
  rectifier_->rectify(demosaic_grbg(pair.left, options_.color), demosaic_grbg(pair.right, options_.color), frame.left,
                      frame.right);
  frame.calibration = rectifier_->calibration();
  return frame;
}

}  // namespace kestrel::ocams

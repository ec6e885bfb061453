#pragma once
// From a raw oCamS frame to the StereoFrame every graph consumes, with no I/O: unpack the two
// mosaics, demosaic them (grey or BGR) and rectify them with the calibration's maps. The live
// driver (`ocams_stereo`) and raw replay (`ocams_replay`) run this same code, so that a replayed
// flight gives what the flight gave, bit for bit.
#include <kestrel/messages/stereo_frame.hpp>
#include <memory>
#include <span>

#include "kestrel/stereo_calibration/stereo_rectifier.hpp"
#include "raw_frame.hpp"

namespace kestrel::ocams {

struct PipelineOptions {
  int width = 640;
  int height = 480;
  bool color = false;  ///< BGR images instead of grey
};

class FramePipeline {
 public:
  /// Throws kestrel::Error if the calibration is not of the frame size.
  FramePipeline(const PipelineOptions& options, std::shared_ptr<const calibration::StereoRectifier> rectifier);

  /// The rectified pair of one raw frame, stamped `stamp`; `device_ms` is set to the frame's
  /// clock. Throws kestrel::Error on a frame of the wrong size.
  msg::StereoFrame process(std::span<const std::uint8_t> raw, Time stamp, std::uint64_t frame_index,
                           std::uint32_t* device_ms = nullptr) const;

  const msg::StereoCalibration& calibration() const { return rectifier_->calibration(); }
  const PipelineOptions& options() const { return options_; }

 private:
  PipelineOptions options_;
  std::shared_ptr<const calibration::StereoRectifier> rectifier_;
};

/// Demosaics an 8-bit GRBG mosaic. OpenCV names Bayer patterns by the second row's second and
/// third pixels, so GRBG is its "GB".
cv::Mat demosaic_grbg(const cv::Mat& bayer, bool color);

}  // namespace kestrel::ocams

#pragma once
// Renders a rectified stereo pair of a scene with MRPT's off-screen EGL renderer (CFBORender):
// the left image from the camera pose, the right one from the same pose shifted by the baseline
// along the optical x axis. Both share the pinhole calibration, as rectified images do.
#include <mrpt/opengl/COpenGLScene.h>

#include <memory>
#include <opencv2/core/mat.hpp>

#include "kestrel/geometry/frames.hpp"
#include "kestrel/geometry/pinhole.hpp"
#include "kestrel/messages/stereo_frame.hpp"

namespace mrpt::opengl {
class CFBORender;
}

namespace kestrel::sim {

class StereoRenderer {
 public:
  /// `supersample` k > 1 renders k times the resolution on each axis and averages each k x k
  /// block into one pixel, as a sensor integrates the light over a pixel's area: edges then fall
  /// between pixels, as they do in a real camera, rather than on whole pixels.
  explicit StereoRenderer(const msg::StereoCalibration& calibration, int supersample = 1);
  ~StereoRenderer();

  /// Renders BGR images. The EGL context is made on the first call, on the calling thread.
  void render(const mrpt::opengl::COpenGLScene& scene, const geometry::CameraPose& left, cv::Mat& left_bgr,
              cv::Mat& right_bgr);

  /// One view (BGR), for tests.
  cv::Mat render_view(const mrpt::opengl::COpenGLScene& scene, const geometry::CameraPose& camera);

  /// One view's depth (CV_32F, metres along the optical axis): the ground truth of every pixel,
  /// for measuring the detection chain against.
  cv::Mat render_depth(const mrpt::opengl::COpenGLScene& scene, const geometry::CameraPose& camera);

 private:
  void prepare(const mrpt::opengl::COpenGLScene& scene, const geometry::CameraPose& camera);

  msg::StereoCalibration calibration_;  // of the images returned
  msg::StereoCalibration rendered_;     // of the images drawn (supersampled)
  int supersample_;
  std::unique_ptr<mrpt::opengl::CFBORender> fbo_;
};

using geometry::focal_from_hfov;

}  // namespace kestrel::sim

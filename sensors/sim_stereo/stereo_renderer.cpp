#include "stereo_renderer.hpp"

#include <mrpt/img/CImage.h>
#include <mrpt/img/TCamera.h>
#include <mrpt/opengl/CFBORender.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>

#include "kestrel/error.hpp"

namespace kestrel::sim {

StereoRenderer::StereoRenderer(const msg::StereoCalibration& calibration) : calibration_(calibration) {}

StereoRenderer::~StereoRenderer() = default;

cv::Mat StereoRenderer::render_view(const mrpt::opengl::COpenGLScene& scene, const geometry::CameraPose& camera) {
  if (!fbo_) {
    mrpt::opengl::CFBORender::Parameters p(static_cast<unsigned>(calibration_.width),
                                           static_cast<unsigned>(calibration_.height));
    try {
      fbo_ = std::make_unique<mrpt::opengl::CFBORender>(p);
    } catch (const std::exception& e) {
      throw Error(std::string("cannot create the off-screen EGL renderer (is Mesa's EGL installed?): ") + e.what());
    }
    mrpt::img::TCamera intrinsics;
    intrinsics.ncols = static_cast<uint32_t>(calibration_.width);
    intrinsics.nrows = static_cast<uint32_t>(calibration_.height);
    intrinsics.fx(calibration_.fx);
    intrinsics.fy(calibration_.fy);
    intrinsics.cx(calibration_.cx);
    intrinsics.cy(calibration_.cy);
    auto& cam = fbo_->getCamera(scene);
    cam.setProjectiveFromPinhole(intrinsics);
    cam.set6DOFMode(true);
  }
  // MRPT's 6-DOF camera looks along its pose's +z with +y down: the optical frame.
  fbo_->getCamera(scene).setPose(mrpt::poses::CPose3D(camera.world_from_camera(), camera.position_world));
  mrpt::img::CImage image;
  fbo_->render_RGB(scene, image);
  // The image's pixels are a reference-counted cv::Mat inside CImage: shared, not copied.
  cv::Mat out = image.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
  if (out.rows != calibration_.height || out.cols != calibration_.width)
    throw Error("renderer returned a " + std::to_string(out.cols) + "x" + std::to_string(out.rows) + " image");
  return out;
}

void StereoRenderer::render(const mrpt::opengl::COpenGLScene& scene, const geometry::CameraPose& left,
                            cv::Mat& left_bgr, cv::Mat& right_bgr) {
  left_bgr = render_view(scene, left);
  geometry::CameraPose right = left;
  right.position_world = left.to_world(Eigen::Vector3d(calibration_.baseline_m, 0.0, 0.0));
  right_bgr = render_view(scene, right);
}

}  // namespace kestrel::sim

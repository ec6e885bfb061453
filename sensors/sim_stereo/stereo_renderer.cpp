#include "stereo_renderer.hpp"

#include <mrpt/img/CImage.h>
#include <mrpt/img/TCamera.h>
#include <mrpt/opengl/CFBORender.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "kestrel/error.hpp"

namespace kestrel::sim {

StereoRenderer::StereoRenderer(const msg::StereoCalibration& calibration, int supersample)
    : calibration_(calibration), rendered_(calibration), supersample_(supersample) {
  if (supersample < 1) throw Error("supersample must be at least 1");
  const double k = supersample;
  rendered_.width = calibration.width * supersample;
  rendered_.height = calibration.height * supersample;
  rendered_.fx = calibration.fx * k;
  rendered_.fy = calibration.fy * k;
  // Pixel u's centre covers the fine pixels k u .. k u + k - 1, whose centre is k u + (k - 1) / 2.
  rendered_.cx = calibration.cx * k + (k - 1) / 2;
  rendered_.cy = calibration.cy * k + (k - 1) / 2;
}

StereoRenderer::~StereoRenderer() = default;

void StereoRenderer::prepare(const mrpt::opengl::COpenGLScene& scene, const geometry::CameraPose& camera) {
  if (!fbo_) {
    mrpt::opengl::CFBORender::Parameters p(static_cast<unsigned>(rendered_.width),
                                           static_cast<unsigned>(rendered_.height));
    try {
      fbo_ = std::make_unique<mrpt::opengl::CFBORender>(p);
    } catch (const std::exception& e) {
      throw Error(std::string("cannot create the off-screen EGL renderer (is Mesa's EGL installed?): ") + e.what());
    }
    mrpt::img::TCamera intrinsics;
    intrinsics.ncols = static_cast<uint32_t>(rendered_.width);
    intrinsics.nrows = static_cast<uint32_t>(rendered_.height);
    intrinsics.fx(rendered_.fx);
    intrinsics.fy(rendered_.fy);
    intrinsics.cx(rendered_.cx);
    intrinsics.cy(rendered_.cy);
    auto& cam = fbo_->getCamera(scene);
    cam.setProjectiveFromPinhole(intrinsics);
    cam.set6DOFMode(true);
  }
  // MRPT's 6-DOF camera looks along its pose's +z with +y down: the optical frame.
  fbo_->getCamera(scene).setPose(mrpt::poses::CPose3D(camera.world_from_camera(), camera.position_world));
}

cv::Mat StereoRenderer::render_depth(const mrpt::opengl::COpenGLScene& scene, const geometry::CameraPose& camera) {
  prepare(scene, camera);
  mrpt::math::CMatrixFloat depth;
  fbo_->render_depth(scene, depth);
  cv::Mat out(static_cast<int>(depth.rows()), static_cast<int>(depth.cols()), CV_32F);
  for (int v = 0; v < out.rows; ++v)
    for (int u = 0; u < out.cols; ++u) out.at<float>(v, u) = depth(v, u);
  if (supersample_ > 1) cv::resize(out, out, {calibration_.width, calibration_.height}, 0, 0, cv::INTER_NEAREST);
  return out;
}

cv::Mat StereoRenderer::render_view(const mrpt::opengl::COpenGLScene& scene, const geometry::CameraPose& camera) {
  prepare(scene, camera);
  mrpt::img::CImage image;
  fbo_->render_RGB(scene, image);
  // The image's pixels are a reference-counted cv::Mat inside CImage: shared, not copied.
  cv::Mat out = image.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
  if (supersample_ > 1) cv::resize(out, out, {calibration_.width, calibration_.height}, 0, 0, cv::INTER_AREA);
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

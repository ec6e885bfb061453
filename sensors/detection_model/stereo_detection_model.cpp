#include "stereo_detection_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <kestrel/error.hpp>
#include <kestrel/geometry/pinhole.hpp>

namespace kestrel::sensors {

void check(const DetectionModelParams& p) {
  if (!(p.camera.fx > 0 && p.camera.fy > 0 && p.camera.baseline_m > 0 && p.camera.width > 0 && p.camera.height > 0))
    throw Error("detection model: the camera needs positive focal lengths, baseline and image size");
  if (!(p.min_depth_m > 0 && p.min_depth_m < p.max_depth_m))
    throw Error("detection model: need 0 < min_depth_m < max_depth_m");
  if (p.recall_depth_m.empty() || p.recall_depth_m.size() != p.recall.size())
    throw Error(
        fmt::format("detection model: recall_depth_m ({} values) and recall ({} values) must be non-empty "
                    "and of one length",
                    p.recall_depth_m.size(), p.recall.size()));
  for (std::size_t i = 0; i < p.recall.size(); ++i) {
    if (!(p.recall[i] >= 0.0 && p.recall[i] <= 1.0))
      throw Error(fmt::format("detection model: recall[{}] = {} is not a probability", i, p.recall[i]));
    if (i > 0 && !(p.recall_depth_m[i] > p.recall_depth_m[i - 1]))
      throw Error("detection model: recall_depth_m must increase");
  }
  if (!(p.centroid_sigma_px.minCoeff() >= 0 && p.disparity_sigma_px >= 0 && p.object_sigma_m.minCoeff() >= 0))
    throw Error("detection model: noise sigmas must be >= 0");
}

StereoDetectionModel::StereoDetectionModel(DetectionModelParams params) : params_(std::move(params)) { check(params_); }

bool StereoDetectionModel::visible(const Eigen::Vector3d& p) const {
  return geometry::in_view(params_.camera, params_.min_depth_m, params_.max_depth_m, p);
}

double StereoDetectionModel::detection_probability(double depth) const {
  const auto& d = params_.recall_depth_m;
  const auto& r = params_.recall;
  if (depth <= d.front()) return r.front();
  if (depth >= d.back()) return r.back();
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(d.begin(), d.end(), depth) - d.begin());
  const double w = (depth - d[i - 1]) / (d[i] - d[i - 1]);
  return r[i - 1] + w * (r[i] - r[i - 1]);
}

std::optional<Eigen::Vector3d> StereoDetectionModel::observe(const Eigen::Vector3d& p, std::mt19937_64& rng) const {
  if (!visible(p)) return std::nullopt;
  // Every draw happens whatever the outcome, so that one object's miss does not shift the noise
  // of the next: runs that differ in one detection stay comparable.
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double draw = uniform(rng);
  // Each vector's z is drawn first, in sequence: the order GCC evaluated the old constructor calls'
  // unsequenced arguments in, so that every compiler draws the same stream.
  const double uz = normal(rng), uy = normal(rng), ux = normal(rng);
  const Eigen::Vector3d unit(ux, uy, uz);
  const double oz = normal(rng), oy = normal(rng), ox = normal(rng);
  const Eigen::Vector3d object(ox, oy, oz);
  if (draw >= detection_probability(p.z())) return std::nullopt;
  Eigen::Vector3d uvd = geometry::to_pixel_disparity(params_.camera, p);
  uvd.x() += params_.centroid_sigma_px.x() * unit.x();
  uvd.y() += params_.centroid_sigma_px.y() * unit.y();
  uvd.z() += params_.disparity_bias_px + params_.disparity_sigma_px * unit.z();
  if (!(uvd.z() > 0.0)) return std::nullopt;  // a disparity at or below zero triangulates to nothing
  return geometry::from_pixel_disparity(params_.camera, uvd) + params_.object_sigma_m.cwiseProduct(object);
}

}  // namespace kestrel::sensors

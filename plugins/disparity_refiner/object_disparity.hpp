#pragma once
// The disparity of a whole object, to a fraction of a pixel (issue: detection at range). SGBM
// gives each pixel its disparity to about a quarter of a pixel, with a bias towards whole
// pixels; a drone 25 px wide at 7.5 m is then placed to about 0.2 m in depth. Matched as a whole
// (hundreds of pixels, the drone's own texture against the right image along the epipolar
// line) its disparity comes out to a few hundredths of a pixel.
//
// The object's pixels come from the cluster: the stereo cloud's points inside the
// detection's box, projected back into the left image (each as the square of pixels it stands
// for), then eroded so that the pixels that bleed from the silhouette onto the background do
// not vote.
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>
#include <optional>

#include "kestrel/messages/stereo_frame.hpp"

namespace kestrel::refine {

/// An object's pixels in the left image.
struct ObjectMask {
  cv::Rect roi;               ///< bounding rectangle of the pixels, in the image
  cv::Mat pixels;             ///< CV_8U, roi-sized: 255 on the object
  cv::Mat disparity;          ///< CV_32F, roi-sized: each pixel's own (SGBM) disparity, 0 where none
  double sgbm_disparity = 0;  ///< median of the object's pixels' own disparities
  int count = 0;              ///< pixels on the object
};

/// The pixels of the points of `cloud` (camera frame, image samples as stereo_depth makes them,
/// each standing for a square of `pixels_per_point` pixels a side) that lie in the box
/// centre ± half_extent + margin, small holes closed, then eroded by `erode_px`. None when fewer
/// than `min_pixels` remain.
std::optional<ObjectMask> object_mask(const pcl::PointCloud<pcl::PointXYZ>& cloud, const msg::StereoCalibration& c,
                                      const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extent,
                                      double margin_m, int erode_px, int min_pixels, int pixels_per_point = 1);

struct BackgroundOptions {
  double ratio = 0.85;  ///< background when a disparity behind explains a pixel at this share of the object's cost
  double gap_px = 1.5;  ///< candidates behind the object: from 0 up to its disparity minus this
  int radius_px = 2;    ///< the compared windows are (2 radius + 1) pixels square
};

/// Removes from the mask the pixels that a disparity behind the object explains clearly better
/// than the object's own (sum of absolute differences over a small window, the object's
/// disparity sampled bilinearly): background onto which the matcher's blocks spread the object,
/// such as the textured ground below a drone at the horizon. Smooth pixels (a plain sky), which
/// every disparity explains alike, stay. Returns how many pixels were removed.
/// `left` and `right` are CV_32F grey images.
int drop_background(const cv::Mat& left, const cv::Mat& right, ObjectMask& mask, const BackgroundOptions& options);

struct MatchOptions {
  double search_px = 2.0;  ///< around the SGBM disparity, each way
  int iterations = 10;     ///< Gauss-Newton steps after the whole-pixel search
};

/// The object's disparity: the whole-pixel disparity in sgbm_disparity ± search_px that
/// maximises the zero-mean normalised cross-correlation of its pixels in the left image with
/// the right image, refined by Gauss-Newton on the sum of squared differences of the
/// brightness-normalised pixels (right image interpolated bilinearly). None when the pixels
/// have no texture or the match leaves the image.
/// `left` and `right` are CV_32F grey images.
std::optional<double> match_disparity(const cv::Mat& left, const cv::Mat& right, const ObjectMask& mask,
                                      const MatchOptions& options);

/// The robust mean of the object's own (SGBM) disparities: the mean of those within 3 scaled
/// median absolute deviations of their median.
std::optional<double> robust_mean_disparity(const ObjectMask& mask);

/// Where the object's surface is: its disparity, at the mask's image centroid.
Eigen::Vector3d place(const msg::StereoCalibration& c, const ObjectMask& mask, double disparity);

/// The target model: its centre lies `metres` behind the surface point, along the line of sight.
Eigen::Vector3d centre_behind(const Eigen::Vector3d& surface, double metres);

}  // namespace kestrel::refine

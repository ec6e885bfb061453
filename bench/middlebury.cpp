// The stereo matcher on real pixels: a rectified pair with ground-truth disparity (Middlebury),
// matched as stereo_depth matches it (OpenCV SGBM with the node's defaults, in strips for two
// cores), as plain OpenCV SGBM with the same parameters on the whole image, and on the pair
// downscaled by 2 (stereo_depth's `downscale: 2`, compared at full resolution). Then the
// object-level refiner (disparity_refiner) on real texture: square patches where the truth is
// known and nearly flat in disparity are handed to it as objects, and its sub-pixel disparity is
// compared with the truth's mean there, beside the SGBM median and robust mean of the same
// pixels. Then stereo_depth's foreground segmentation (foreground_gap_m 0.5, as the graphs set it)
// on its disparity and on the truth's, with the pair's calibration (Middlebury calib.txt: doffs
// is added to each disparity, so that disparity gives depth), compared pixel by pixel where the
// truth is known. Prints one JSON object: per matcher bad-1, bad-2, the median error, density and
// ms per pair, the patches' errors and the foreground's agreement; writes the disparities, the
// bad-2 map and the two foreground masks as images to OUTDIR. scripts/middlebury runs it on both
// pairs.
//
// Usage: kestrel_middlebury NAME LEFT RIGHT TRUTH NUM_DISPARITIES OUTDIR REPEATS CALIB
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <kestrel/error.hpp>
#include <kestrel/stereo_calibration/middlebury_calibration.hpp>
#include <kestrel/stereo_calibration/stereo_rectifier.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "disparity_score.hpp"
#include "foreground_mask.hpp"
#include "object_disparity.hpp"
#include "stereo_matching.hpp"
#include "striped_matcher.hpp"

using namespace kestrel::stereo;

namespace {

// Median wall time of `repeats` runs, ms; the last result is kept.
double time_ms(int repeats, const std::function<void()>& run) {
  std::vector<double> ms;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    run();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(ms.begin(), ms.begin() + static_cast<std::ptrdiff_t>(ms.size() / 2), ms.end());
  return ms[ms.size() / 2];
}

nlohmann::json to_json(const DisparityScore& s, double ms) {
  return {
      {"bad1", s.bad1},         {"bad2", s.bad2},      {"bad2_all", s.bad2_all}, {"median_error_px", s.median_error_px},
      {"density", s.density()}, {"known_px", s.known}, {"ms_per_pair", ms}};
}

// Red where a matched pixel is off by more than 2 px, grey where it is within, black elsewhere.
cv::Mat bad2_map(const cv::Mat& estimate, const cv::Mat& truth) {
  cv::Mat out(truth.size(), CV_8UC3, cv::Scalar(0, 0, 0));
  for (int v = 0; v < truth.rows; ++v)
    for (int u = 0; u < truth.cols; ++u) {
      const float t = truth.at<float>(v, u), e = estimate.at<float>(v, u);
      if (!(std::isfinite(t) && t > 0) || !(std::isfinite(e) && e > 0)) continue;
      out.at<cv::Vec3b>(v, u) = std::abs(e - t) > 2.0f ? cv::Vec3b(0, 0, 255) : cv::Vec3b(160, 160, 160);
    }
  return out;
}

// Median and the spread (half the 16-84 % range, a robust standard deviation) of signed errors.
nlohmann::json error_summary(std::vector<double> errors) {
  if (errors.empty()) return nullptr;
  std::vector<double> absolute;
  for (double e : errors) absolute.push_back(std::abs(e));
  const auto quantile = [](std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5)];
  };
  return {{"median_abs_error_px", quantile(absolute, 0.5)},
          {"median_error_px", quantile(errors, 0.5)},
          {"spread_px", 0.5 * (quantile(errors, 0.84) - quantile(errors, 0.16))}};
}

// The refiner on patches of real texture: every `side` px square whose truth is known on every
// pixel and spans less than `flat_px` of disparity, with SGBM disparities on at least half.
nlohmann::json refine_patches(const cv::Mat& left, const cv::Mat& right, const cv::Mat& sgbm_px, const cv::Mat& truth,
                              int side, double flat_px) {
  cv::Mat left_f, right_f;
  left.convertTo(left_f, CV_32F);
  right.convertTo(right_f, CV_32F);
  std::vector<double> refined, sgbm_median, sgbm_mean;
  int patches = 0, unmatched = 0;
  for (int y = 0; y + side <= truth.rows; y += side)
    for (int x = 0; x + side <= truth.cols; x += side) {
      const cv::Rect roi(x, y, side, side);
      const cv::Mat t = truth(roi);
      if (cv::countNonZero(t == t) != side * side) continue;  // NaN somewhere: not all known
      double lo = 0.0, hi = 0.0;
      cv::minMaxLoc(t, &lo, &hi);
      if (!std::isfinite(lo) || !std::isfinite(hi) || hi - lo > flat_px) continue;
      kestrel::refine::ObjectMask mask;
      mask.roi = roi;
      mask.pixels = cv::Mat(side, side, CV_8U, cv::Scalar(255));
      mask.count = side * side;
      mask.disparity = sgbm_px(roi).clone();
      mask.disparity.setTo(0.0f, mask.disparity != mask.disparity);
      std::vector<float> own;
      for (int v = 0; v < side; ++v)
        for (int u = 0; u < side; ++u)
          if (mask.disparity.at<float>(v, u) > 0.0f) own.push_back(mask.disparity.at<float>(v, u));
      if (own.size() * 2 < static_cast<std::size_t>(side * side)) continue;
      std::nth_element(own.begin(), own.begin() + static_cast<std::ptrdiff_t>(own.size() / 2), own.end());
      mask.sgbm_disparity = own[own.size() / 2];
      ++patches;
      const double truth_mean = cv::mean(t)[0];
      const auto match = kestrel::refine::match_disparity(left_f, right_f, mask, {});
      const auto robust = kestrel::refine::robust_mean_disparity(mask);
      if (!match || !robust) {
        ++unmatched;
        continue;
      }
      refined.push_back(*match - truth_mean);
      sgbm_median.push_back(mask.sgbm_disparity - truth_mean);
      sgbm_mean.push_back(*robust - truth_mean);
    }
  return {{"patch_px", side},
          {"flat_within_px", flat_px},
          {"patches", patches},
          {"unmatched", unmatched},
          {"refiner", error_summary(refined)},
          {"sgbm_median", error_summary(sgbm_median)},
          {"sgbm_robust_mean", error_summary(sgbm_mean)}};
}

// A disparity map (CV_16S, 1/16 px) of the raw pair as the pair moved onto a common principal
// point gives it: doffs added to every match, so that disparity gives depth.
cv::Mat with_doffs(const cv::Mat& disparity16, double doffs) {
  cv::Mat out = disparity16.clone();
  const int shift = static_cast<int>(std::lround(16.0 * doffs));
  out.forEach<short>([shift](short& d, const int*) {
    if (d > 0) d = static_cast<short>(d + shift);
  });
  return out;
}

// The left image in grey with the foreground in orange.
cv::Mat foreground_picture(const cv::Mat& left, const cv::Mat& mask) {
  cv::Mat grey, tinted;
  cv::cvtColor(left, grey, cv::COLOR_GRAY2BGR);
  cv::addWeighted(grey, 0.4, cv::Mat(grey.size(), grey.type(), cv::Scalar(0, 140, 255)), 0.6, 0.0, tinted);
  tinted.copyTo(grey, mask);
  return grey;
}

// The foreground segmentation on the matched disparity against the same segmentation on the
// truth, over the pixels the truth knows: how much of the picture each marks, and their overlap.
nlohmann::json foreground_agreement(const cv::Mat& matched, const cv::Mat& on_truth, const cv::Mat& known) {
  const cv::Mat a = matched & known, b = on_truth & known;
  const double both = cv::countNonZero(a & b), either = cv::countNonZero(a | b);
  const double n_a = cv::countNonZero(a), n_b = cv::countNonZero(b), n_known = cv::countNonZero(known);
  const auto ratio = [](double x, double y) -> nlohmann::json { return y > 0 ? nlohmann::json(x / y) : nullptr; };
  return {{"share_matched", ratio(n_a, n_known)},
          {"share_truth", ratio(n_b, n_known)},
          {"precision", ratio(both, n_a)},
          {"recall", ratio(both, n_b)},
          {"iou", ratio(both, either)}};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 9) {
    std::cerr << "usage: kestrel_middlebury NAME LEFT RIGHT TRUTH NUM_DISPARITIES OUTDIR REPEATS CALIB\n";
    return 2;
  }
  try {
    const std::string name = argv[1], out = argv[6];
    const cv::Mat left = cv::imread(argv[2], cv::IMREAD_GRAYSCALE), right = cv::imread(argv[3], cv::IMREAD_GRAYSCALE);
    if (left.empty() || right.empty()) throw kestrel::Error(fmt::format("cannot read {} or {}", argv[2], argv[3]));
    const cv::Mat truth = read_disparity_truth(argv[4]);
    if (truth.size() != left.size())
      throw kestrel::Error(
          fmt::format("the truth is {}x{}, the images {}x{}", truth.cols, truth.rows, left.cols, left.rows));
    MatcherOptions options;  // stereo_depth's defaults: the paper's SGBM, block 7
    options.num_disparities = std::stoi(argv[5]);
    const int repeats = std::stoi(argv[7]);
    const auto calib = kestrel::calibration::load_middlebury_calibration(argv[8]);

    cv::Mat plain16, striped16, coarse16;
    const cv::Ptr<cv::StereoMatcher> plain = make_matcher(options);
    const double plain_ms = time_ms(repeats, [&] { plain16 = compute_disparity(*plain, left, right); });
    StripedMatcher striped(options, 2, 48);
    const double striped_ms = time_ms(repeats, [&] { striped16 = striped.compute(left, right); });

    // Coarse: half the size, half the disparities, scaled back to full resolution.
    MatcherOptions half = options;
    half.num_disparities = std::max(16, options.num_disparities / 2 / 16 * 16);
    const cv::Ptr<cv::StereoMatcher> coarse = make_matcher(half);
    cv::Mat coarse_px;
    const double coarse_ms = time_ms(repeats, [&] {
      cv::Mat l, r;
      cv::resize(left, l, {}, 0.5, 0.5, cv::INTER_AREA);
      cv::resize(right, r, {}, 0.5, 0.5, cv::INTER_AREA);
      coarse16 = compute_disparity(*coarse, l, r);
      cv::resize(disparity_in_pixels(coarse16) * 2.0, coarse_px, left.size(), 0, 0, cv::INTER_NEAREST);
    });

    const cv::Mat plain_px = disparity_in_pixels(plain16), striped_px = disparity_in_pixels(striped16);
    nlohmann::json result{{"pair", name},
                          {"size", {left.cols, left.rows}},
                          {"num_disparities", options.num_disparities},
                          {"block_size", options.block_size},
                          {"opencv_sgbm", to_json(score_disparity(plain_px, truth), plain_ms)},
                          {"stereo_depth", to_json(score_disparity(striped_px, truth), striped_ms)},
                          {"stereo_depth_downscale_2", to_json(score_disparity(coarse_px, truth), coarse_ms)},
                          {"refiner_patches", refine_patches(left, right, plain_px, truth, 24, 1.0)}};

    // The foreground as the graphs segment it, on the matched disparity and on the truth's.
    const auto [left_info, right_info] = calib.camera_infos();
    const kestrel::msg::StereoCalibration camera =
        kestrel::calibration::StereoRectifier(left_info, right_info).calibration();
    ForegroundOptions foreground;
    foreground.gap_m = 0.5;
    foreground.unseen_left_columns = options.min_disparity + options.num_disparities;
    cv::Mat truth16;
    truth.convertTo(truth16, CV_16S, 16.0);
    truth16.setTo(-1, truth != truth);
    const cv::Mat known = truth == truth;  // only NaN (unknown) differs from itself
    const cv::Mat matched_mask = foreground_mask(with_doffs(striped16, calib.doffs), camera, foreground);
    const cv::Mat truth_mask = foreground_mask(with_doffs(truth16, calib.doffs), camera, foreground);
    result["foreground"] = foreground_agreement(matched_mask, truth_mask, known);
    result["foreground"]["gap_m"] = foreground.gap_m;
    cv::Mat pictures;
    cv::hconcat(foreground_picture(left, matched_mask), foreground_picture(left, truth_mask), pictures);
    cv::imwrite(out + "/" + name + "_foreground.png", pictures);
    cv::imwrite(out + "/" + name + "_stereo_depth.png", colourise_disparity(striped16, options.num_disparities));
    cv::imwrite(out + "/" + name + "_bad2.png", bad2_map(striped_px, truth));
    cv::imwrite(out + "/" + name + "_truth.png", colourise_disparity(truth16, options.num_disparities));
    std::cout << result.dump() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "kestrel_middlebury: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

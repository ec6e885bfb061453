// SGBM matched as strips in parallel against OpenCV's matcher on the whole image.
#include <gmock/gmock.h>

#include <opencv2/imgproc.hpp>

#include "kestrel/error.hpp"
#include "striped_matcher.hpp"

using namespace kestrel;
using namespace kestrel::stereo;

namespace {

// A layered scene: a textureless band of sky over a textured wall (disparity 8) with a textured
// box in front of it (disparity 30), and a wall that is weakly textured on its right, where SGBM's
// paths carry the most from the rows above.
std::pair<cv::Mat, cv::Mat> layered_pair() {
  cv::RNG rng(7);
  const int w = 640, h = 480;
  cv::Mat wall(h, w + 8, CV_8U), box(160, 200, CV_8U);
  rng.fill(wall, cv::RNG::UNIFORM, 0, 255);
  rng.fill(box, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(wall, wall, cv::Size(5, 5), 0);
  cv::GaussianBlur(box, box, cv::Size(3, 3), 0);
  cv::Mat weak = wall(cv::Rect(400, 0, w + 8 - 400, h));
  weak.convertTo(weak, CV_8U, 0.08, 120);  // low contrast
  cv::Mat left = wall(cv::Rect(0, 0, w, h)).clone(), right = wall(cv::Rect(8, 0, w, h)).clone();
  box.copyTo(left(cv::Rect(200, 220, 200, 160)));
  box.copyTo(right(cv::Rect(200 - 30, 220, 200, 160)));  // right(u - d) = left(u)
  left.rowRange(0, 120).setTo(200);                      // sky
  right.rowRange(0, 120).setTo(200);
  return {left, right};
}

MatcherOptions paper_options() {
  MatcherOptions o;
  o.num_disparities = 80;
  return o;
}

double fraction_differing(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat differ = a != b;
  return static_cast<double>(cv::countNonZero(differ)) / static_cast<double>(a.total());
}

}  // namespace

TEST(StripedMatcher, OneStripIsOpenCvsMatcherOnTheWholeImage) {
  const auto [left, right] = layered_pair();
  StripedMatcher one(paper_options(), 1, 48);
  const auto whole = make_matcher(paper_options());
  EXPECT_EQ(fraction_differing(one.compute(left, right), compute_disparity(*whole, left, right)), 0.0);
}

TEST(StripedMatcher, TheTopStripIsExactAndTheOthersAgreeOnAllButAFewPixels) {
  const auto [left, right] = layered_pair();
  const auto whole_matcher = make_matcher(paper_options());
  const cv::Mat whole = compute_disparity(*whole_matcher, left, right);
  // The scene is matched: the box at 30 px, the wall at 8.
  EXPECT_NEAR(whole.at<short>(300, 300) / 16.0, 30.0, 0.5);
  EXPECT_NEAR(whole.at<short>(200, 150) / 16.0, 8.0, 0.5);

  for (const int strips : {2, 3}) {
    StripedMatcher striped(paper_options(), strips, 48);
    const cv::Mat split = striped.compute(left, right);
    ASSERT_EQ(split.size(), whole.size());
    ASSERT_EQ(split.type(), CV_16S);
    // The first strip is matched with every row above it and the rows below that it needs.
    const int first = 480 / strips;
    EXPECT_EQ(fraction_differing(split.rowRange(0, first), whole.rowRange(0, first)), 0.0) << strips;
    EXPECT_LT(fraction_differing(split, whole), 0.0002) << strips;  // measured: 7.5e-5, 2.3e-5
  }
  // Without rows above them the strips start their paths afresh: the overlap is what agrees.
  StripedMatcher no_overlap(paper_options(), 2, 0);
  EXPECT_GT(fraction_differing(no_overlap.compute(left, right), whole),
            fraction_differing(StripedMatcher(paper_options(), 2, 48).compute(left, right), whole));
}

TEST(StripedMatcher, RefusesModesWhosePathsComeFromBelowAndBadImages) {
  MatcherOptions hh = paper_options();
  hh.mode = MatcherOptions::Mode::hh;
  EXPECT_THROW(StripedMatcher(hh, 2, 48), Error);
  EXPECT_NO_THROW(StripedMatcher(hh, 1, 48));
  MatcherOptions bm = paper_options();
  bm.algorithm = MatcherOptions::Algorithm::bm;
  bm.block_size = 9;
  EXPECT_THROW(StripedMatcher(bm, 2, 48), Error);
  EXPECT_THROW(StripedMatcher(paper_options(), 0, 48), Error);
  EXPECT_THROW(StripedMatcher(paper_options(), 2, -1), Error);
  StripedMatcher striped(paper_options(), 2, 48);
  EXPECT_THROW(striped.compute(cv::Mat(), cv::Mat()), Error);
  EXPECT_THROW(striped.compute(cv::Mat(10, 10, CV_8U), cv::Mat(12, 10, CV_8U)), Error);
  EXPECT_THROW(striped.compute(cv::Mat(10, 10, CV_32F), cv::Mat(10, 10, CV_32F)), Error);
}

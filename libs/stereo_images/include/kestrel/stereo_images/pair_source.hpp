#pragma once
// Where recorded stereo pairs come from: two folders of images (matched by sorted name), two
// numbered patterns (left/%06d.png), two image files (one pair), or one side-by-side video (left
// half, right half), with no graph around them so that tests read them directly.
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <optional>
#include <string>
#include <vector>

namespace kestrel::stereo_images {

struct PairSourceOptions {
  std::string left, right;  ///< folders, printf patterns with one integer ("left/%06d.png"), or two files
  std::string video;        ///< or a side-by-side video
  int start_index = 0;      ///< patterns: the first number
};

class PairSource {
 public:
  /// Finds the pairs. Throws kestrel::Error when the folders hold other numbers of images, a
  /// pattern matches nothing, or the video does not open.
  explicit PairSource(const PairSourceOptions& options);
  ~PairSource();

  /// The next pair, or nullopt after the last. Throws kestrel::Error naming the file that does
  /// not read as an image, or a pair whose sizes differ.
  std::optional<std::pair<cv::Mat, cv::Mat>> next();
  /// Pairs in all (folders and patterns; a video's frame count as it reports it).
  std::size_t size() const { return size_; }
  std::size_t position() const { return position_; }
  /// What the pairs are, for the report: "folders", "pattern", "one pair", "video".
  const std::string& kind() const { return kind_; }

 private:
  std::vector<std::string> left_files_, right_files_;
  std::unique_ptr<cv::VideoCapture> video_;
  std::string video_name_;
  std::size_t size_ = 0, position_ = 0;
  std::string kind_;
};

}  // namespace kestrel::stereo_images

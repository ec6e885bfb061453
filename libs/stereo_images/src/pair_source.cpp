#include "kestrel/stereo_images/pair_source.hpp"

#include <algorithm>
#include <filesystem>
#include <kestrel/error.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace kestrel::stereo_images {

namespace fs = std::filesystem;

namespace {

bool is_image(const fs::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e == ".png" || e == ".jpg" || e == ".jpeg" || e == ".bmp" || e == ".tif" || e == ".tiff" || e == ".pgm" ||
         e == ".ppm";
}

std::vector<std::string> images_in(const std::string& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw Error("'" + folder + "' is not a folder of images");
  std::vector<std::string> out;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.is_regular_file() && is_image(entry.path())) out.push_back(entry.path().string());
  std::sort(out.begin(), out.end());
  if (out.empty()) throw Error("'" + folder + "' holds no image (png, jpg, bmp, tif, pgm)");
  return out;
}

bool is_pattern(const std::string& s) { return s.find('%') != std::string::npos; }

std::string numbered(const std::string& pattern, int n) {
  char buffer[4096];
  const int length = std::snprintf(buffer, sizeof buffer, pattern.c_str(), n);
  if (length < 0 || static_cast<std::size_t>(length) >= sizeof buffer)
    throw Error("pattern '" + pattern + "' is too long");
  return buffer;
}

// A pattern must hold exactly one integer conversion, and nothing else printf would read.
void check_pattern(const std::string& p) {
  std::size_t conversions = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p[i] != '%') continue;
    if (i + 1 < p.size() && p[i + 1] == '%') {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < p.size() && (std::isdigit(static_cast<unsigned char>(p[j])) || p[j] == '0')) ++j;
    if (j >= p.size() || p[j] != 'd') throw Error("pattern '" + p + "' may hold only %d conversions (%06d, ...)");
    ++conversions;
    i = j;
  }
  if (conversions != 1) throw Error("pattern '" + p + "' needs one %d for the image's number");
}

std::vector<std::string> numbered_files(const std::string& pattern, int start) {
  check_pattern(pattern);
  std::vector<std::string> out;
  for (int n = start;; ++n) {
    const std::string f = numbered(pattern, n);
    if (!fs::exists(f)) break;
    out.push_back(f);
  }
  if (out.empty())
    throw Error("no image matches '" + pattern + "' from " + std::to_string(start) + " (" + numbered(pattern, start) +
                ")");
  return out;
}

cv::Mat read(const std::string& file) {
  cv::Mat m = cv::imread(file, cv::IMREAD_UNCHANGED);
  if (m.empty()) throw Error("'" + file + "' does not read as an image");
  if (m.depth() != CV_8U) throw Error("'" + file + "' is not 8-bit (stereo frames are 8-bit grey or colour)");
  if (m.channels() == 4) cv::cvtColor(m, m, cv::COLOR_BGRA2BGR);
  if (m.channels() != 1 && m.channels() != 3)
    throw Error("'" + file + "' has " + std::to_string(m.channels()) + " channels");
  return m;
}

}  // namespace

PairSource::PairSource(const PairSourceOptions& o) {
  if (!o.video.empty()) {
    if (!o.left.empty() || !o.right.empty()) throw Error("give either a video or left and right images, not both");
    // A file's decoders only: with any backend, OpenCV would also probe for cameras (gphoto2,
    // libusb) before it reads the file.
    for (const int backend : {cv::CAP_FFMPEG, cv::CAP_GSTREAMER, cv::CAP_OPENCV_MJPEG}) {
      video_ = std::make_unique<cv::VideoCapture>(o.video, backend);
      if (video_->isOpened()) break;
    }
    if (!video_->isOpened())
      throw Error("the video '" + o.video + "' does not open (FFmpeg, GStreamer and OpenCV's MJPEG reader tried)");
    video_name_ = o.video;
    const double n = video_->get(cv::CAP_PROP_FRAME_COUNT);
    size_ = n > 0 ? static_cast<std::size_t>(n) : 0;
    kind_ = "video";
    return;
  }
  if (o.left.empty() || o.right.empty()) throw Error("give left and right (folders or patterns), or a video");
  // Two image files: one pair (a still of a dataset such as Middlebury's).
  std::error_code ec;
  const bool left_file = fs::is_regular_file(o.left, ec), right_file = fs::is_regular_file(o.right, ec);
  if (left_file || right_file) {
    if (!left_file || !right_file)
      throw Error("left '" + o.left + "' and right '" + o.right +
                  "': give two image files, two folders or two patterns");
    left_files_ = {o.left};
    right_files_ = {o.right};
    kind_ = "one pair";
    size_ = 1;
    return;
  }
  if (is_pattern(o.left) != is_pattern(o.right)) throw Error("left and right must both be folders or both patterns");
  if (is_pattern(o.left)) {
    left_files_ = numbered_files(o.left, o.start_index);
    right_files_ = numbered_files(o.right, o.start_index);
    kind_ = "pattern";
  } else {
    left_files_ = images_in(o.left);
    right_files_ = images_in(o.right);
    kind_ = "folders";
  }
  if (left_files_.size() != right_files_.size())
    throw Error(std::to_string(left_files_.size()) + " left images but " + std::to_string(right_files_.size()) +
                " right ones: a pair needs both");
  size_ = left_files_.size();
}

PairSource::~PairSource() = default;

std::optional<std::pair<cv::Mat, cv::Mat>> PairSource::next() {
  if (video_) {
    cv::Mat both;
    if (!video_->read(both) || both.empty()) return std::nullopt;
    if (both.cols % 2 != 0)
      throw Error("the video '" + video_name_ + "' is " + std::to_string(both.cols) +
                  " wide: a side-by-side pair needs an even width");
    ++position_;
    const int half = both.cols / 2;
    return std::make_pair(both.colRange(0, half).clone(), both.colRange(half, both.cols).clone());
  }
  if (position_ >= left_files_.size()) return std::nullopt;
  cv::Mat left = read(left_files_[position_]), right = read(right_files_[position_]);
  if (left.size() != right.size() || left.type() != right.type())
    throw Error("'" + left_files_[position_] + "' and '" + right_files_[position_] + "' differ in size or channels");
  ++position_;
  return std::make_pair(std::move(left), std::move(right));
}

}  // namespace kestrel::stereo_images

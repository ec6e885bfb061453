#pragma once
// MOTChallenge text files, as `kestrel mot` reads them: one row per box, comma-separated
// frame, id, bb_left, bb_top, bb_width, bb_height[, conf, x, y, z].
#include <Eigen/Core>
#include <cstdint>
#include <istream>
#include <map>
#include <string>
#include <vector>

namespace kestrel::cli {

struct MotRow {
  std::uint64_t id = 0;
  double left = 0, top = 0, width = 0, height = 0, conf = 1;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

/// Rows by frame number.
using MotFrames = std::map<long, std::vector<MotRow>>;

/// Reads the rows of `in`; `label` names the file in error messages. Ground truth skips the rows
/// whose conf (MOTChallenge's "considered" flag) is 0. Throws kestrel::Error at a malformed row.
MotFrames read_mot(std::istream& in, const std::string& label, bool ground_truth);
/// The same for a file; throws kestrel::Error if it cannot be opened.
MotFrames read_mot(const std::string& file, bool ground_truth);

}  // namespace kestrel::cli

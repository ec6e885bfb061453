#include "mot_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "kestrel/error.hpp"

namespace kestrel::cli {

namespace {

// Frames and ids are whole numbers (some tools write them as "12.000"); beyond 2^53 a double
// no longer holds every integer.
constexpr double kLargestWhole = 9007199254740992.0;

bool whole(double v, double lo) { return v >= lo && v <= kLargestWhole && v == std::floor(v); }

// One optional field: absent is fine, present must be a number and nothing else.
bool optional_number(std::istream& fields, double& value, std::string& token) {
  if (!(fields >> token)) return true;
  std::istringstream in(token);
  return static_cast<bool>(in >> value) && (in >> std::ws).eof();
}

}  // namespace

MotFrames read_mot(std::istream& in, const std::string& label, bool ground_truth) {
  MotFrames frames;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    double frame = 0, id = 0;
    MotRow r;
    if (!(fields >> frame >> id >> r.left >> r.top >> r.width >> r.height))
      throw Error(SourceLocation{label, number, 0}, "expected frame,id,bb_left,bb_top,bb_width,bb_height[,conf,x,y,z]");
    std::string token;
    for (double* field : {&r.conf, &r.point.x(), &r.point.y(), &r.point.z()})
      if (!optional_number(fields, *field, token))
        throw Error(SourceLocation{label, number, 0}, "conf, x, y and z must be numbers, not '" + token + "'");
    if (!whole(frame, -kLargestWhole))
      throw Error(SourceLocation{label, number, 0}, fmt::format("the frame must be a whole number, not {}", frame));
    if (!whole(id, 0))
      throw Error(SourceLocation{label, number, 0},
                  fmt::format("the id must be a whole number >= 0, not {} (detections without an identity, id -1, "
                              "cannot be scored)",
                              id));
    // MOTChallenge ground truth marks entries to ignore with conf (the "considered" flag) = 0.
    if (ground_truth && r.conf == 0) continue;
    r.id = static_cast<std::uint64_t>(id);
    frames[static_cast<long>(frame)].push_back(r);
  }
  return frames;
}

MotFrames read_mot(const std::string& file, bool ground_truth) {
  std::ifstream in(file);
  if (!in) throw Error("cannot open " + file);
  return read_mot(in, file, ground_truth);
}

}  // namespace kestrel::cli

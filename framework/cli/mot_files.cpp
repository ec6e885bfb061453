#include "mot_files.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "kestrel/error.hpp"

namespace kestrel::cli {

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
    fields >> r.conf >> r.point.x() >> r.point.y() >> r.point.z();
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

#pragma once
// The formats the oCamS-1CGN-U streams with firmware R1811 (WithRobot's release notes): per-eye
// size and frame rates. 640x480 and 640x360 bin the sensor (full field of view), 320x240 crops
// it, 1280x720 crops 1280x960. Over USB 2.0 only the three smaller sizes stream.
#include <string>
#include <vector>

namespace kestrel::ocams {

struct OcamsMode {
  int width, height;
  std::vector<int> fps;
  bool usb2;  ///< also streams over USB 2.0
};

inline const std::vector<OcamsMode>& ocams_modes() {
  static const std::vector<OcamsMode> modes = {{1280, 960, {45, 30, 25, 20, 15, 10}, false},
                                               {1280, 720, {60, 50, 45, 30, 25, 20, 15, 10}, false},
                                               {640, 480, {45, 30, 25, 20, 15, 10}, true},
                                               {640, 360, {60, 50, 45, 30, 25, 20, 15, 10}, true},
                                               {320, 240, {60, 50, 45, 30, 25, 20, 15, 10}, true}};
  return modes;
}

/// Whether the camera streams width x height at fps.
inline bool ocams_streams(int width, int height, int fps) {
  for (const auto& m : ocams_modes())
    if (m.width == width && m.height == height)
      for (int f : m.fps)
        if (f == fps) return true;
  return false;
}

/// "1280x960 @ 45 30 25 20 15 10; ...", for errors.
inline std::string ocams_modes_text() {
  std::string s;
  for (const auto& m : ocams_modes()) {
    if (!s.empty()) s.append("; ");
    s.append(std::to_string(m.width)).append("x").append(std::to_string(m.height)).append(" @");
    for (int f : m.fps) s.append(" ").append(std::to_string(f));
  }
  return s;
}

}  // namespace kestrel::ocams

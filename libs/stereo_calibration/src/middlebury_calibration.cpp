#include "kestrel/stereo_calibration/middlebury_calibration.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <kestrel/error.hpp>
#include <map>
#include <sstream>

namespace kestrel::calibration {

namespace {

struct Entry {
  std::string value;
  int line = 0;
};

double number(const std::string& text, const std::string& where) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || !std::isfinite(v))
    throw Error(fmt::format("{}: '{}' is not a number", where, text));
  return v;
}

// "[f 0 cx; 0 f cy; 0 0 1]": nine numbers, rows split by ';'.
std::array<double, 9> matrix(std::string text, const std::string& where) {
  if (text.size() < 2 || text.front() != '[' || text.back() != ']')
    throw Error(fmt::format("{}: a camera matrix is written [f 0 cx; 0 f cy; 0 0 1], not '{}'", where, text));
  text = text.substr(1, text.size() - 2);
  for (char& c : text)
    if (c == ';') c = ' ';
  std::istringstream in(text);
  std::array<double, 9> m{};
  std::string token;
  std::size_t n = 0;
  while (in >> token) {
    if (n == 9) throw Error(fmt::format("{}: more than 9 numbers in the camera matrix", where));
    m[n++] = number(token, where);
  }
  if (n != 9) throw Error(fmt::format("{}: {} numbers in the camera matrix, not 9", where, n));
  if (m[0] <= 0.0 || m[4] <= 0.0 || m[1] != 0.0 || m[3] != 0.0 || m[6] != 0.0 || m[7] != 0.0 || m[8] != 1.0)
    throw Error(fmt::format("{}: not a camera matrix [fx 0 cx; 0 fy cy; 0 0 1] with positive focal lengths", where));
  return m;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

}  // namespace

std::pair<CameraInfo, CameraInfo> MiddleburyCalibration::camera_infos() const {
  // Both rectified cameras get cam0's intrinsics: the right image, taken with cx1, is moved by
  // doffs onto cam0's cx, so that a disparity d there is d + doffs here and gives depth as
  // baseline * f / d, as kestrel reprojects it.
  const auto camera = [&](const std::array<double, 9>& k, double tx, const char* name) {
    CameraInfo c;
    c.width = width;
    c.height = height;
    c.camera_name = name;
    c.k = k;
    c.d.assign(5, 0.0);
    c.r = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    c.p = {cam0[0], 0, cam0[2], tx, 0, cam0[4], cam0[5], 0, 0, 0, 1, 0};
    return c;
  };
  return {camera(cam0, 0.0, "middlebury_left"), camera(cam1, -cam0[0] * baseline_mm / 1000.0, "middlebury_right")};
}

MiddleburyCalibration parse_middlebury_calibration(const std::string& text, const std::string& name) {
  std::map<std::string, Entry> entries;
  std::istringstream in(text);
  std::string line;
  int number_of_line = 0;
  while (std::getline(in, line)) {
    ++number_of_line;
    line = trim(line);
    if (line.empty() || line.front() == '#') continue;
    const auto eq = line.find('=');
    if (eq == std::string::npos)
      throw Error(fmt::format("{}:{}: expected key=value, not '{}'", name, number_of_line, line));
    const std::string key = trim(line.substr(0, eq));
    if (entries.count(key))
      throw Error(
          fmt::format("{}:{}: '{}' given twice (first on line {})", name, number_of_line, key, entries[key].line));
    entries[key] = {trim(line.substr(eq + 1)), number_of_line};
  }
  const auto need = [&](const char* key) -> const Entry& {
    const auto it = entries.find(key);
    if (it == entries.end())
      throw Error(
          fmt::format("{}: no '{}' (a Middlebury calib.txt has cam0, cam1, doffs, "
                      "baseline, width and height)",
                      name, key));
    return it->second;
  };
  const auto where = [&](const char* key) { return fmt::format("{}:{}: {}", name, need(key).line, key); };
  const auto whole = [&](const char* key, double v, int least) {
    if (v != std::floor(v) || v < least || v > 100000)
      throw Error(fmt::format("{} = {} is not a whole number from {} to 100000", where(key), v, least));
    return static_cast<int>(v);
  };
  MiddleburyCalibration c;
  c.cam0 = matrix(need("cam0").value, where("cam0"));
  c.cam1 = matrix(need("cam1").value, where("cam1"));
  c.doffs = number(need("doffs").value, where("doffs"));
  c.baseline_mm = number(need("baseline").value, where("baseline"));
  if (c.baseline_mm <= 0.0) throw Error(fmt::format("{} must be positive (mm)", where("baseline")));
  c.width = whole("width", number(need("width").value, where("width")), 1);
  c.height = whole("height", number(need("height").value, where("height")), 1);
  if (entries.count("ndisp")) c.ndisp = whole("ndisp", number(entries["ndisp"].value, where("ndisp")), 0);
  if (c.cam0[0] != c.cam1[0] || c.cam0[4] != c.cam1[4] || c.cam0[5] != c.cam1[5])
    throw Error(fmt::format("{}: cam0 and cam1 differ in more than cx; the pair is not rectified", where("cam1")));
  if (std::abs(c.cam1[2] - c.cam0[2] - c.doffs) > 1e-3)
    throw Error(
        fmt::format("{} = {} is not cam1's cx - cam0's cx ({})", where("doffs"), c.doffs, c.cam1[2] - c.cam0[2]));
  return c;
}

MiddleburyCalibration load_middlebury_calibration(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw Error(fmt::format("cannot read Middlebury calibration {}", file.string()));
  std::stringstream text;
  text << in.rdbuf();
  return parse_middlebury_calibration(text.str(), file.string());
}

}  // namespace kestrel::calibration

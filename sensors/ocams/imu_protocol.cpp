#include "imu_protocol.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <vector>

namespace kestrel::ocams {

namespace {

constexpr double kDegToRad = M_PI / 180.0;
constexpr double kGravity = 9.80665;
// The BNO055's raw units, as WithRobot's oCamS driver scales them: quaternion 2^14 per unit,
// acceleration 100 per m/s^2, rate 900 per rad/s, magnetic field 16 per microtesla.
constexpr double kQuaternionScale = 16384.0;
constexpr double kAccelerationScale = 100.0;
constexpr double kRateScale = 900.0;
constexpr double kFieldScale = 16.0;
constexpr double kEulerScale = 16.0;  // per degree

constexpr std::array<std::string_view, 4> kOcamsFormats = {"AMGQUA", "AMGEUL", "LMGQUA", "LMGEUL"};

std::vector<std::string_view> split(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = s.find(',', start);
    out.push_back(s.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

std::string printable(std::string_view s) {
  std::string out;
  for (char c : s.substr(0, 80)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  return out;
}

template <class T>
T parse_number(std::string_view field, std::string_view format, std::size_t index) {
  T v{};
  const char* end = field.data() + field.size();
  auto [ptr, ec] = std::from_chars(field.data(), end, v);
  if (ec != std::errc() || ptr != end || field.empty())
    throw ImuLineError(std::string(format) + " field " + std::to_string(index) + " '" + printable(field) +
                       "' is not a number");
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(v))
      throw ImuLineError(std::string(format) + " field " + std::to_string(index) + " is not finite");
  return v;
}

class Fields {
 public:
  Fields(const std::vector<std::string_view>& f, std::string_view format) : f_(f), format_(format) {}
  double number(std::size_t i) const { return parse_number<double>(f_.at(i), format_, i); }
  // The BNO055's raw values are 16-bit integers.
  double raw(std::size_t i) const {
    const long v = parse_number<long>(f_.at(i), format_, i);
    if (v < -32768 || v > 65535)
      throw ImuLineError(std::string(format_) + " field " + std::to_string(i) + " is out of range");
    return static_cast<double>(v);
  }
  Eigen::Vector3d raw3(std::size_t i, double scale) const {
    return Eigen::Vector3d(raw(i), raw(i + 1), raw(i + 2)) / scale;
  }
  Eigen::Vector3d number3(std::size_t i, double scale) const {
    return Eigen::Vector3d(number(i), number(i + 1), number(i + 2)) * scale;
  }

 private:
  const std::vector<std::string_view>& f_;
  std::string_view format_;
};

void expect_fields(const std::vector<std::string_view>& f, std::size_t n, std::string_view format) {
  if (f.size() != n)
    throw ImuLineError(std::string(format) + " has " + std::to_string(f.size() - 1) + " values, not " +
                       std::to_string(n - 1));
}

Eigen::Quaterniond unit_quaternion(double w, double x, double y, double z, std::string_view format) {
  Eigen::Quaterniond q(w, x, y, z);
  const double n = q.norm();
  if (!(std::abs(n - 1.0) < 0.05)) throw ImuLineError(std::string(format) + " quaternion of norm " + std::to_string(n));
  q.normalize();
  return q;
}

ImuSample ocams_sample(const std::vector<std::string_view>& f, std::string_view format) {
  const bool quaternion = format.ends_with("QUA");
  expect_fields(f, quaternion ? 15 : 14, format);
  const Fields v(f, format);
  ImuSample s;
  s.format = std::string(format);
  s.device_ms = parse_number<std::uint32_t>(f[1], format, 1);
  s.acceleration_m_s2 = v.raw3(2, kAccelerationScale);
  s.gravity_removed = format.starts_with("LMG");
  s.magnetic_field_t = v.raw3(5, kFieldScale) * 1e-6;
  s.angular_rate_radps = v.raw3(8, kRateScale);
  if (quaternion)  // x, y, z, w on the wire
    s.orientation = unit_quaternion(v.raw(14) / kQuaternionScale, v.raw(11) / kQuaternionScale,
                                    v.raw(12) / kQuaternionScale, v.raw(13) / kQuaternionScale, format);
  else
    s.euler_deg = v.raw3(11, kEulerScale);
  return s;
}

ImuSample quatimu_sample(const std::vector<std::string_view>& f) {
  expect_fields(f, 16, "QUATIMU");
  const Fields v(f, "QUATIMU");
  ImuSample s;
  s.format = "QUATIMU";
  const auto seq = parse_number<std::uint32_t>(f[1], "QUATIMU", 1);
  if (seq > 255) throw ImuLineError("QUATIMU sequence " + std::to_string(seq) + " is over 255");
  s.sequence = seq;
  s.orientation = unit_quaternion(v.number(5), v.number(2), v.number(3), v.number(4), "QUATIMU");
  s.acceleration_m_s2 = v.number3(6, kGravity);
  s.angular_rate_radps = v.number3(9, kDegToRad);
  s.magnetic_field_t = v.number3(12, 1e-6);
  v.number(15);  // temperature: checked, not kept
  return s;
}

}  // namespace

std::uint8_t imu_checksum(std::string_view text) {
  std::uint8_t x = 0;
  for (char c : text) x ^= static_cast<std::uint8_t>(c);
  return x;
}

bool is_ocams_format(std::string_view format) {
  for (auto f : kOcamsFormats)
    if (f == format) return true;
  return false;
}

std::string ocams_format_command(std::string_view format) {
  if (!is_ocams_format(format))
    throw Error("'" + std::string(format) + "' is not an oCamS IMU format (AMGQUA, AMGEUL, LMGQUA, LMGEUL)");
  std::string command = "@";
  return command.append(format).append("\r\n");
}

std::string myahrs_command(std::string_view body) {
  std::string text = "@";
  text.append(body);
  char hex[3];
  std::snprintf(hex, sizeof hex, "%02X", imu_checksum(text));
  return text.append("*").append(hex).append("\r\n");
}

ImuLine parse_imu_line(std::string_view line) {
  while (!line.empty() && (line.back() == '\r' || line.back() == '\n' || line.back() == ' ')) line.remove_suffix(1);
  if (line.empty()) throw ImuLineError("an empty line");
  const char start = line.front();
  if (start != '$' && start != '~' && start != '@')
    throw ImuLineError("a line that starts with '" + printable(line.substr(0, 1)) + "', not $, ~ or @");
  // A checksum, where the line has one, covers everything before the '*'.
  if (const std::size_t star = line.rfind('*'); star != std::string_view::npos) {
    const std::string_view hex = line.substr(star + 1);
    unsigned expected = 0;
    auto [ptr, ec] = std::from_chars(hex.data(), hex.data() + hex.size(), expected, 16);
    if (hex.size() != 2 || ec != std::errc() || ptr != hex.data() + hex.size())
      throw ImuLineError("checksum '" + printable(hex) + "' is not two hex digits");
    const std::uint8_t got = imu_checksum(line.substr(0, star));
    if (got != expected)
      throw ImuLineError("bad checksum: the line gives " + printable(hex) + ", its bytes " +
                         std::to_string(static_cast<unsigned>(got)));
    line = line.substr(0, star);
  }
  ImuLine out;
  if (start != '$') {
    out.kind = line.find(",ERROR") != std::string_view::npos ? ImuLine::Kind::error_reply : ImuLine::Kind::reply;
    out.reply = printable(line);
    return out;
  }
  const auto fields = split(line);
  const std::string_view format = fields[0].substr(1);
  if (is_ocams_format(format))
    out.sample = ocams_sample(fields, format);
  else if (format == "QUATIMU")
    out.sample = quatimu_sample(fields);
  else
    throw ImuLineError("data of format '" + printable(format) +
                       "', which is not read here (AMGQUA, AMGEUL, LMGQUA, LMGEUL, QUATIMU)");
  return out;
}

}  // namespace kestrel::ocams

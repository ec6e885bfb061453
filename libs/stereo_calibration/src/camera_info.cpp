#include "kestrel/stereo_calibration/camera_info.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <kestrel/error.hpp>
#include <sstream>

namespace kestrel::calibration {

namespace {

SourceLocation where(const std::string& file, const YAML::Mark& m) {
  return {file, m.is_null() ? 0 : m.line + 1, m.is_null() ? 0 : m.column + 1};
}

class Reader {
 public:
  explicit Reader(std::string name) : name_(std::move(name)) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& message) const {
    throw Error(where(name_, at.Mark()), message);
  }

  YAML::Node field(const YAML::Node& map, const char* key) const {
    const YAML::Node n = map[key];
    if (!n) fail(map, std::string("no '") + key + "'");
    return n;
  }

  double number(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, what + " is not a number");
    double v = 0;
    if (!YAML::convert<double>::decode(n, v) || !std::isfinite(v))
      fail(n, what + " '" + n.Scalar() + "' is not a number");
    return v;
  }

  int size(const YAML::Node& map, const char* key) const {
    const YAML::Node n = field(map, key);
    const double v = number(n, key);
    if (v != std::floor(v) || v < 0 || v > 1 << 16) fail(n, std::string(key) + " must be a whole number of pixels");
    return static_cast<int>(v);
  }

  // A matrix as camera_calibration writes it: {rows: R, cols: C, data: [...]}.
  std::vector<double> matrix(const YAML::Node& map, const char* key, int rows, int cols) const {
    const YAML::Node m = field(map, key);
    if (!m.IsMap()) fail(m, std::string(key) + " must be a map of rows, cols and data");
    const int r = size(m, "rows"), c = size(m, "cols");
    if ((rows >= 0 && r != rows) || (cols >= 0 && c != cols))
      fail(m, std::string(key) + " is " + std::to_string(r) + "x" + std::to_string(c) + ", not " +
                  (rows >= 0 ? std::to_string(rows) : "1") + "x" + (cols >= 0 ? std::to_string(cols) : "N"));
    const YAML::Node data = field(m, "data");
    if (!data.IsSequence() || data.size() != static_cast<std::size_t>(r) * static_cast<std::size_t>(c))
      fail(data, std::string(key) + ".data must hold " + std::to_string(r * c) + " numbers");
    std::vector<double> out;
    for (std::size_t i = 0; i < data.size(); ++i)
      out.push_back(number(data[i], std::string(key) + ".data[" + std::to_string(i) + "]"));
    return out;
  }

 private:
  std::string name_;
};

template <std::size_t N>
std::array<double, N> as_array(const std::vector<double>& v) {
  std::array<double, N> a{};
  std::copy(v.begin(), v.end(), a.begin());
  return a;
}

std::size_t coefficients_of(const std::string& model) {
  if (model == "plumb_bob") return 5;
  if (model == "rational_polynomial") return 8;
  if (model == "equidistant") return 4;
  return 0;
}

}  // namespace

bool CameraInfo::rectified() const {
  for (double v : d)
    if (v != 0.0) return false;
  const std::array<double, 9> identity{1, 0, 0, 0, 1, 0, 0, 0, 1};
  return r == identity && k[0] == p[0] && k[2] == p[2] && k[4] == p[5] && k[5] == p[6];
}

CameraInfo parse_camera_info(const std::string& text, const std::string& name) {
  const Reader in(name);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw Error(where(name, e.mark), e.msg);
  }
  if (!root.IsMap()) in.fail(root, "a camera_info file is a map (image_width, camera_matrix, ...)");
  CameraInfo info;
  info.width = in.size(root, "image_width");
  info.height = in.size(root, "image_height");
  if (root["camera_name"]) info.camera_name = root["camera_name"].as<std::string>("");
  info.k = as_array<9>(in.matrix(root, "camera_matrix", 3, 3));
  // As camera_calibration_parsers reads it: without a model, plumb_bob.
  const YAML::Node model = root["distortion_model"] ? root["distortion_model"] : root;
  if (root["distortion_model"]) info.distortion_model = model.as<std::string>("");
  const std::size_t n = coefficients_of(info.distortion_model);
  if (n == 0)
    in.fail(model,
            "distortion_model '" + info.distortion_model + "' is not plumb_bob, rational_polynomial or equidistant");
  info.d = in.matrix(root, "distortion_coefficients", 1, -1);
  // camera_calibration writes 5 plumb_bob coefficients; OpenCV's rational model takes 8 and more.
  if (info.d.size() < n)
    in.fail(root["distortion_coefficients"], info.distortion_model + " needs " + std::to_string(n) + " coefficients");
  info.r = as_array<9>(in.matrix(root, "rectification_matrix", 3, 3));
  info.p = as_array<12>(in.matrix(root, "projection_matrix", 3, 4));
  if (info.width == 0 || info.height == 0) in.fail(root, "image_width and image_height must not be 0");
  if (!(info.k[0] > 0 && info.k[4] > 0)) in.fail(root["camera_matrix"], "camera_matrix needs positive fx and fy");
  if (!(info.p[0] > 0 && info.p[5] > 0))
    in.fail(root["projection_matrix"], "projection_matrix needs positive fx and fy");
  return info;
}

CameraInfo load_camera_info(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw Error("cannot read camera_info file " + file.string());
  std::stringstream text;
  text << in.rdbuf();
  return parse_camera_info(text.str(), file.string());
}

std::string to_yaml(const CameraInfo& info) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  auto matrix = [&](const char* key, int rows, int cols, const double* data, std::size_t n) {
    out << YAML::Key << key << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "rows" << YAML::Value << rows << YAML::Key << "cols" << YAML::Value << cols;
    out << YAML::Key << "data" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (std::size_t i = 0; i < n; ++i) out << data[i];
    out << YAML::EndSeq << YAML::EndMap;
  };
  out << YAML::BeginMap;
  out << YAML::Key << "image_width" << YAML::Value << info.width;
  out << YAML::Key << "image_height" << YAML::Value << info.height;
  out << YAML::Key << "camera_name" << YAML::Value << info.camera_name;
  matrix("camera_matrix", 3, 3, info.k.data(), 9);
  out << YAML::Key << "distortion_model" << YAML::Value << info.distortion_model;
  matrix("distortion_coefficients", 1, static_cast<int>(info.d.size()), info.d.data(), info.d.size());
  matrix("rectification_matrix", 3, 3, info.r.data(), 9);
  matrix("projection_matrix", 3, 4, info.p.data(), 12);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace kestrel::calibration

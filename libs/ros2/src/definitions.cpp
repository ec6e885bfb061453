#include "kestrel/ros2/definitions.hpp"

#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <sstream>

#include "kestrel/error.hpp"
#include "kestrel/ros2/ros2msg.hpp"

namespace kestrel::ros2 {

namespace {

// Field lines only (the ROS 2 files' comments left out); constants where a type declares them.
const std::map<std::string, std::string>& definitions() {
  static const std::map<std::string, std::string> defs = {
      {"builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"},
      {"builtin_interfaces/Duration", "int32 sec\nuint32 nanosec\n"},
      {"std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n"},
      {"std_msgs/ColorRGBA", "float32 r\nfloat32 g\nfloat32 b\nfloat32 a\n"},
      {"geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n"},
      {"geometry_msgs/Pose", "Point position\nQuaternion orientation\n"},
      {"geometry_msgs/PoseWithCovariance", "Pose pose\nfloat64[36] covariance\n"},
      {"geometry_msgs/Twist", "Vector3 linear\nVector3 angular\n"},
      {"geometry_msgs/TwistWithCovariance", "Twist twist\nfloat64[36] covariance\n"},
      {"geometry_msgs/Transform", "Vector3 translation\nQuaternion rotation\n"},
      {"geometry_msgs/TransformStamped", "std_msgs/Header header\nstring child_frame_id\nTransform transform\n"},
      {"nav_msgs/Odometry",
       "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
       "geometry_msgs/TwistWithCovariance twist\n"},
      {"tf2_msgs/TFMessage", "geometry_msgs/TransformStamped[] transforms\n"},
      {"sensor_msgs/Image",
       "std_msgs/Header header\nuint32 height\nuint32 width\nstring encoding\nuint8 is_bigendian\nuint32 step\n"
       "uint8[] data\n"},
      {"sensor_msgs/Imu",
       "std_msgs/Header header\ngeometry_msgs/Quaternion orientation\nfloat64[9] orientation_covariance\n"
       "geometry_msgs/Vector3 angular_velocity\nfloat64[9] angular_velocity_covariance\n"
       "geometry_msgs/Vector3 linear_acceleration\nfloat64[9] linear_acceleration_covariance\n"},
      {"sensor_msgs/MagneticField",
       "std_msgs/Header header\ngeometry_msgs/Vector3 magnetic_field\nfloat64[9] magnetic_field_covariance\n"},
      {"sensor_msgs/CompressedImage", "std_msgs/Header header\nstring format\nuint8[] data\n"},
      {"sensor_msgs/RegionOfInterest",
       "uint32 x_offset\nuint32 y_offset\nuint32 height\nuint32 width\nbool do_rectify\n"},
      {"sensor_msgs/CameraInfo",
       "std_msgs/Header header\nuint32 height\nuint32 width\nstring distortion_model\nfloat64[] d\nfloat64[9] k\n"
       "float64[9] r\nfloat64[12] p\nuint32 binning_x\nuint32 binning_y\nRegionOfInterest roi\n"},
      {"sensor_msgs/PointField",
       "uint8 INT8    = 1\nuint8 UINT8   = 2\nuint8 INT16   = 3\nuint8 UINT16  = 4\nuint8 INT32   = 5\n"
       "uint8 UINT32  = 6\nuint8 FLOAT32 = 7\nuint8 FLOAT64 = 8\nstring name\nuint32 offset\nuint8 datatype\n"
       "uint32 count\n"},
      {"sensor_msgs/PointCloud2",
       "std_msgs/Header header\nuint32 height\nuint32 width\nPointField[] fields\nbool is_bigendian\n"
       "uint32 point_step\nuint32 row_step\nuint8[] data\nbool is_dense\n"},
      {"visualization_msgs/UVCoordinate", "float32 u\nfloat32 v\n"},
      {"visualization_msgs/MeshFile", "string filename\nuint8[] data\n"},
      {"visualization_msgs/Marker",
       "int32 ARROW=0\nint32 CUBE=1\nint32 SPHERE=2\nint32 CYLINDER=3\nint32 LINE_STRIP=4\nint32 LINE_LIST=5\n"
       "int32 CUBE_LIST=6\nint32 SPHERE_LIST=7\nint32 POINTS=8\nint32 TEXT_VIEW_FACING=9\nint32 MESH_RESOURCE=10\n"
       "int32 TRIANGLE_LIST=11\nint32 ARROW_STRIP=12\nint32 ADD=0\nint32 MODIFY=0\nint32 DELETE=2\n"
       "int32 DELETEALL=3\nstd_msgs/Header header\nstring ns\nint32 id\nint32 type\nint32 action\n"
       "geometry_msgs/Pose pose\ngeometry_msgs/Vector3 scale\nstd_msgs/ColorRGBA color\n"
       "builtin_interfaces/Duration lifetime\nbool frame_locked\ngeometry_msgs/Point[] points\n"
       "std_msgs/ColorRGBA[] colors\nstring texture_resource\nsensor_msgs/CompressedImage texture\n"
       "UVCoordinate[] uv_coordinates\nstring text\nstring mesh_resource\nMeshFile mesh_file\n"
       "bool mesh_use_embedded_materials\n"},
      {"visualization_msgs/MarkerArray", "Marker[] markers\n"},
      // kestrel's own, composed of standard types (docs/recording.md).
      {"kestrel_msgs/Detection",
       "geometry_msgs/Point position\ngeometry_msgs/Vector3 extent\nint32 point_count\nfloat64 confidence\n"},
      {"kestrel_msgs/Detections", "std_msgs/Header header\nDetection[] detections\n"},
      {"kestrel_msgs/Track",
       "uint64 id\nint32 age\nint32 hits\nint32 misses\nfloat64[] state\nfloat64[] covariance\n"
       "geometry_msgs/Point detection\n"},
      {"kestrel_msgs/Tracks", "std_msgs/Header header\nTrack[] tracks\nbool has_selected\nuint64 selected_id\n"},
      {"kestrel_msgs/GroundTruthObject",
       "uint64 id\ngeometry_msgs/Point position_world\ngeometry_msgs/Point position_camera\n"
       "geometry_msgs/Vector3 velocity_world\nbool in_view\n"},
      {"kestrel_msgs/GroundTruth", "std_msgs/Header header\nGroundTruthObject[] objects\n"},
      {"kestrel_msgs/TrajectorySetpoint",
       "std_msgs/Header header\ngeometry_msgs/Point position\ngeometry_msgs/Vector3 velocity\n"
       "geometry_msgs/Vector3 acceleration\nfloat64 yaw\nfloat64 yaw_rate\n"},
      {"kestrel_msgs/ActuatorCommand",
       "std_msgs/Header header\nfloat64 thrust_n\ngeometry_msgs/Vector3 torque_nm\nfloat64[] rotor_speeds_rad_s\n"},
      {"kestrel_msgs/AttitudeTarget",
       "std_msgs/Header header\ngeometry_msgs/Quaternion orientation\ngeometry_msgs/Vector3 body_rates\n"
       "float64 thrust_n\nfloat64 hover_thrust_n\n"},
      {"kestrel_msgs/NetFire", "std_msgs/Header header\nuint64 target_id\ngeometry_msgs/Vector3 aim_error_m\n"},
      {"kestrel_msgs/NetCapture", "std_msgs/Header header\nuint64 object_id\ngeometry_msgs/Point position_world\n"},
      {"kestrel_msgs/NetLauncher",
       "std_msgs/Header header\nint64 nets_left\nint64 nets_used\nbuiltin_interfaces/Time ready_at\n"},
  };
  return defs;
}

// The types a definition names, "pkg/Type", in the order its fields name them.
std::vector<std::string> named_types(const std::string& type, const std::string& text) {
  const std::string package = type.substr(0, type.find('/'));
  std::vector<std::string> out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string word, name;
    if (!(words >> word >> name) || name.find('=') != std::string::npos || line.find('=') != std::string::npos)
      continue;
    word = word.substr(0, word.find('['));
    if (is_primitive(word)) continue;
    out.push_back(word.find('/') == std::string::npos ? package + "/" + word : word);
  }
  return out;
}

std::string compose(const std::string& type) {
  const auto& defs = definitions();
  std::string text = defs.at(type);
  std::set<std::string> seen;
  std::vector<std::string> order;
  const std::function<void(const std::string&)> visit = [&](const std::string& t) {
    for (const std::string& dep : named_types(t, defs.at(t)))
      if (seen.insert(dep).second) {
        order.push_back(dep);
        visit(dep);
      }
  };
  visit(type);
  for (const std::string& dep : order) text += std::string(80, '=') + "\nMSG: " + dep + "\n" + defs.at(dep);
  return text;
}

}  // namespace

const std::string& schema_text(const std::string& name) {
  static std::mutex mutex;
  static std::map<std::string, std::string> composed;
  const std::string type = MessageSchema::normalise(name);
  if (!definitions().count(type)) throw Error("no ROS 2 definition of " + name + " in kestrel");
  std::lock_guard lock(mutex);
  auto it = composed.find(type);
  if (it == composed.end()) it = composed.emplace(type, compose(type)).first;
  return it->second;
}

std::vector<std::string> defined_types() {
  std::vector<std::string> out;
  for (const auto& [type, _] : definitions()) {
    const auto slash = type.find('/');
    out.push_back(type.substr(0, slash) + "/msg" + type.substr(slash));
  }
  return out;
}

}  // namespace kestrel::ros2

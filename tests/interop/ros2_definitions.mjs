// Standard ROS 2 message definitions as rosbag2 stores them in a ros2msg schema: the type's .msg
// text, then each dependency after a line of 80 '=' and "MSG: pkg/Type".
const SEP = "=".repeat(80);
const msgs = {
  "builtin_interfaces/Time": "int32 sec\nuint32 nanosec\n",
  "std_msgs/Header": "builtin_interfaces/Time stamp\nstring frame_id\n",
  "std_msgs/String": "string data\n",
  "geometry_msgs/Point": "float64 x\nfloat64 y\nfloat64 z\n",
  "geometry_msgs/Quaternion": "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n",
  "geometry_msgs/Vector3": "float64 x\nfloat64 y\nfloat64 z\n",
  "geometry_msgs/Pose": "Point position\nQuaternion orientation\n",
  "geometry_msgs/PoseWithCovariance": "Pose pose\nfloat64[36] covariance\n",
  "geometry_msgs/Twist": "Vector3 linear\nVector3 angular\n",
  "geometry_msgs/TwistWithCovariance": "Twist twist\nfloat64[36] covariance\n",
  "geometry_msgs/Transform": "Vector3 translation\nQuaternion rotation\n",
  "geometry_msgs/TransformStamped": "std_msgs/Header header\nstring child_frame_id\nTransform transform\n",
  "nav_msgs/Odometry":
    "# Estimate of a position and velocity in free space.\nstd_msgs/Header header\nstring child_frame_id\n" +
    "geometry_msgs/PoseWithCovariance pose\ngeometry_msgs/TwistWithCovariance twist\n",
  "tf2_msgs/TFMessage": "geometry_msgs/TransformStamped[] transforms\n",
  "sensor_msgs/PointField":
    "uint8 INT8    = 1\nuint8 UINT8   = 2\nuint8 INT16   = 3\nuint8 UINT16  = 4\nuint8 INT32   = 5\n" +
    "uint8 UINT32  = 6\nuint8 FLOAT32 = 7\nuint8 FLOAT64 = 8\nstring name\nuint32 offset\nuint8  datatype\nuint32 count\n",
  "sensor_msgs/PointCloud2":
    "std_msgs/Header header\nuint32 height\nuint32 width\nPointField[] fields\nbool    is_bigendian\n" +
    "uint32  point_step\nuint32  row_step\nuint8[] data\nbool is_dense\n",
  "sensor_msgs/Image":
    "std_msgs/Header header # acquisition time\nuint32 height\nuint32 width\nstring encoding\n" +
    "uint8 is_bigendian\nuint32 step\nuint8[] data\n",
};

// The dependencies of `type`, depth first, each once.
function dependencies(type, seen = new Set()) {
  const pkg = type.split("/")[0];
  for (const line of msgs[type].split("\n")) {
    const word = line.replace(/#.*/, "").trim().split(/\s+/)[0];
    if (!word || line.includes("=")) continue;
    const base = word.replace(/\[.*\]$/, "");
    if (/^(bool|byte|char|u?int(8|16|32|64)|float(32|64)|string)$/.test(base)) continue;
    const full = base.includes("/") ? base : `${pkg}/${base}`;
    if (!seen.has(full)) {
      seen.add(full);
      dependencies(full, seen);
    }
  }
  return seen;
}

/** The ros2msg schema text of "pkg/msg/Type". */
export function schemaText(name) {
  const type = name.replace("/msg/", "/");
  let text = msgs[type];
  for (const dep of dependencies(type)) text += `${SEP}\nMSG: ${dep}\n${msgs[dep]}`;
  return text;
}

#pragma once
// The kestrel CLI's subcommands. Each returns the process exit code (see docs/cli.md).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace kestrel::cli {

enum ExitCode : int {
  kOk = 0,
  kRunFailed = 1,     // a node error under on_error: stop, or a node could not start
  kUsage = 2,         // bad command line
  kInvalidGraph = 3,  // the graph file is unreadable or fails validation
  kNotFound = 4,      // unknown type for inspect, or a plugin was refused
};

struct GraphFragment {
  std::string label;  // where its errors point: "--record"
  std::string yaml;   // a map with `nodes` (and `connections`) added to the graph
};

struct GraphArgs {
  std::string graph;
  std::vector<std::string> overrides;  // --set node.param=value
  std::vector<GraphFragment> fragments;
  std::string executor;  // "", "lockstep" or "realtime": replaces the graph's choice
};

struct RunArgs : GraphArgs {
  std::optional<double> duration_s;
  std::optional<std::uint64_t> seed;
  std::string report_dir;
  bool stats = false;
  bool progress = true;
  std::string record;                      // --record FILE.mcap: a recorder node is added
  std::optional<std::string> live;         // --live [ADDRESS:]PORT: a foxglove_bridge node is added
  std::optional<std::string> topics;       // --topics PATTERNS for them
  bool dds = false;                        // --dds: a dds_bridge node is added
  std::optional<std::int64_t> dds_domain;  // --dds-domain N (else ROS_DOMAIN_ID, else 0)
};

struct MotArgs {
  std::string ground_truth;
  std::string test;
  std::optional<double> iou;       // match 2D boxes with IoU >= this
  std::optional<double> distance;  // or 3D points within this distance
  std::string json;
};

struct PlotArgs {
  std::string csv;
  std::string x;
  std::vector<std::string> y;
  std::string output;
  std::string meta;  // a JSON file with metrics_meta; default: metrics_meta.json beside the CSV
};

/// Where the runs of sweep and ab go: here, as child processes, or to a Slurm cluster
/// (slurm_batch.hpp, docs/cluster.md).
struct BatchBackend {
  enum class Kind { local, slurm };
  Kind kind = Kind::local;
  std::string partition;                 ///< sbatch --partition (empty: the cluster's default)
  std::string time;                      ///< sbatch --time per task, e.g. 00:10:00 (empty: the partition's)
  int array_limit = 0;                   ///< at most this many tasks at once (%N; 0: no limit)
  std::vector<std::string> sbatch_args;  ///< more sbatch options, e.g. --account=lab
  bool wait = false;                     ///< block until the collector has written the results
};

struct SweepArgs {
  std::string graph;
  std::vector<std::string> params;     // node.param=start:stop:step (a grid), or
  std::string cases;                   // a CSV file of cases (see case_table.hpp)
  std::vector<std::string> overrides;  // fixed --set values
  std::optional<int> seeds;            // seeds 1..N per point; none: 1, or each case's own seed
  std::optional<double> duration;
  std::string report_dir;
  int jobs = 0;  // 0: one per core
  BatchBackend backend;
};

struct AbArgs {
  std::string graph_a, graph_b;
  std::vector<std::string> overrides;    ///< applied to both
  std::vector<std::string> overrides_a;  ///< applied to A only, after `overrides`
  std::vector<std::string> overrides_b;
  int seeds = 10;
  std::optional<double> duration;
  std::string report_dir;
  int jobs = 0;
  BatchBackend backend;
};

struct McapInfoArgs {
  std::string file;
  bool json = false;
  bool verify = false;  // read the whole file and check every CRC
};

struct McapCatArgs {
  std::string file;
  std::vector<std::string> topics;  // none: every topic
  std::optional<std::uint64_t> limit;
};

int run_command(const RunArgs& args);
/// `kestrel collect DIR`: the results of a batch submitted to Slurm, as sweep or ab writes them.
int collect_command(const std::string& dir);
/// `kestrel batch-task DIR I` (run by Slurm, not by people): task I of a submitted batch.
int batch_task_command(const std::string& dir, std::size_t index);
int sweep_command(const SweepArgs& args);
int ab_command(const AbArgs& args);
int plot_command(const PlotArgs& args);
int mot_command(const MotArgs& args);
int validate_command(const GraphArgs& args);
int dot_command(const GraphArgs& args, const std::string& output);
int plugins_command();
int inspect_command(const std::string& name);
int mcap_info_command(const McapInfoArgs& args);
int mcap_cat_command(const McapCatArgs& args);

/// `kestrel dds list` and `kestrel dds echo` (dds_commands.cpp, docs/ros2.md).
struct DdsArgs {
  std::optional<std::int64_t> domain;  // else ROS_DOMAIN_ID, else 0
  double wait_s = 2.0;                 // list: how long to listen to discovery; echo: for the topic's writer
  bool text = false;                   // list: `ros2 topic list -t` lines instead of JSON lines
  std::string topic;                   // echo: the ROS 2 topic
  std::optional<std::uint64_t> count;  // echo: stop after N messages
  std::optional<double> duration_s;    // echo: stop after this long
};
int dds_list_command(const DdsArgs& args);
int dds_echo_command(const DdsArgs& args);
/// `kestrel dds msg-package DIR`: DIR/kestrel_msgs, a ROS 2 package of kestrel's own message types.
int dds_msg_package_command(const std::string& dir);
/// The DDS domain: --domain/--dds-domain, else ROS_DOMAIN_ID (as ROS 2 reads it), else 0. Throws
/// kestrel::Error for an id out of range or a ROS_DOMAIN_ID that is not a number.
std::uint32_t dds_domain(std::optional<std::int64_t> given);

struct CalibrateArgs {
  std::string left, right;    // folders or numbered patterns of the chessboard pairs
  std::string board = "8x6";  // inner corners
  double square_m = 0.025;
  std::string out = ".";
  std::string name = "stereo";  // camera_name prefix
};
/// `kestrel calibrate`: camera_info files from chessboard pairs.
int calibrate_command(const CalibrateArgs& args);

/// `kestrel devices`: V4L2 devices and serial ports, and which look like an oCamS.
int devices_command();

struct MavlinkListenArgs {
  std::string connection;              // udpin://, udpout:// or serial:// URL
  std::optional<double> duration_s;    // stop after this long (default: at Ctrl-C)
  std::optional<std::uint64_t> count;  // stop after printing this many messages
  std::vector<std::string> only;       // print only these messages (all are counted)
  bool heartbeat = false;              // send a ground station's heartbeat at 1 Hz
};
/// `kestrel mavlink listen`: decoded messages, one line each, and their rates.
int mavlink_listen_command(const MavlinkListenArgs& args);

/// `kestrel mavlink keygen FILE`: a new signing key, readable by its owner only.
int mavlink_keygen_command(const std::string& file);

struct MavlinkSetupSigningArgs {
  std::string connection;   // the autopilot's link, as for listen
  std::string key_file;     // the key to hand over (kestrel mavlink keygen)
  double timeout_s = 10.0;  // how long to wait for the autopilot's heartbeat, then for its signed frames
};
/// `kestrel mavlink setup-signing URL --key FILE`: SETUP_SIGNING to the autopilot, then a check
/// that its frames come signed with that key.
int mavlink_setup_signing_command(const MavlinkSetupSigningArgs& args);

}  // namespace kestrel::cli

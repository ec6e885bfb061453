// kestrel: run, validate, inspect and draw dataflow graphs of plugins.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <map>

#include "commands.hpp"
#include "kestrel/abi.hpp"
#include "kestrel/version.hpp"

namespace {

// --backend and Slurm's options, the same on sweep and ab (docs/cluster.md).
void add_backend_options(CLI::App* cmd, kestrel::cli::BatchBackend& backend) {
  using Kind = kestrel::cli::BatchBackend::Kind;
  cmd->add_option("--backend", backend.kind, "where the runs go: local (child processes, the default) or slurm")
      ->transform(CLI::CheckedTransformer(std::map<std::string, Kind>{{"local", Kind::local}, {"slurm", Kind::slurm}}));
  cmd->add_option("--partition", backend.partition, "slurm: the partition (default: the cluster's)");
  cmd->add_option("--time", backend.time, "slurm: each task's time limit, e.g. 00:10:00");
  cmd->add_option("--array-limit", backend.array_limit, "slurm: at most N tasks at once")
      ->check(CLI::Range(1, 1000000));
  cmd->add_option("--sbatch", backend.sbatch_args,
                  "slurm: one more sbatch option, e.g. --sbatch=--account=lab (repeatable)")
      ->allow_extra_args(false);
  cmd->add_flag("--wait", backend.wait, "slurm: wait for the results (else print the job ids and return)");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace kestrel::cli;
  CLI::App app{
      "kestrel: perception-and-control dataflow runtime.\n"
      "Exit codes: 0 ok, 1 run failed, 2 bad command line, 3 invalid graph, 4 not found / plugin refused."};
  app.set_version_flag("--version", std::string("kestrel ") + KESTREL_VERSION_STRING + " (commit " + KESTREL_GIT_HASH +
                                        ")\nABI " + KESTREL_ABI_VERSION + ", plugin tag " + KESTREL_ABI_TAG);
  app.require_subcommand(1);
  std::string log_level = "info";
  app.add_option("--log-level", log_level, "debug, info, warn or error")
      ->check(CLI::IsMember({"debug", "info", "warn", "error"}));

  RunArgs run;
  auto* run_cmd = app.add_subcommand("run", "Validate a graph, then run it");
  run_cmd->add_option("graph", run.graph, "graph YAML file")->required();
  run_cmd->add_option("--set", run.overrides, "override a parameter: node.param=value (repeatable)");
  run_cmd->add_option("--duration", run.duration_s, "run length in seconds (sim time for lockstep)");
  run_cmd->add_option("--seed", run.seed, "random seed (overrides the graph's)");
  run_cmd->add_option("--report", run.report_dir, "write DIR/report.json and DIR/report.md");
  run_cmd
      ->add_option("--executor", run.executor,
                   "run with this executor instead of the graph's (realtime uses the wall clock)")
      ->check(CLI::IsMember({"lockstep", "realtime"}));
  run_cmd->add_flag("--stats", run.stats, "print per-node and per-connection statistics at the end");
  run_cmd->add_flag("!--no-progress", run.progress, "no status line on the terminal");
  run_cmd->add_option("--record", run.record,
                      "record the run into FILE.mcap (ROS 2 messages; a `recorder` node is added, docs/recording.md)");
  run_cmd->add_option("--live", run.live,
                      "serve the run live over the Foxglove WebSocket protocol on PORT of this machine (127.0.0.1), or "
                      "on ADDRESS:PORT (0.0.0.0:8765: every interface, with a warning) (a `foxglove_bridge` node is "
                      "added; open ws://HOST:PORT in Foxglove or Lichtblick, docs/recording.md)");
  run_cmd->add_flag("--dds", run.dds,
                    "publish the run on DDS topics as ROS 2 names them (rt/NODE/PORT; a `dds_bridge` node is added, "
                    "docs/ros2.md)");
  run_cmd->add_option("--dds-domain", run.dds_domain, "the DDS domain for --dds (default: ROS_DOMAIN_ID, else 0)");
  run_cmd->add_option("--topics", run.topics,
                      "what --record records and --dds publishes: topic patterns /NODE/PORT, '*' for all, "
                      "'!PATTERN' to leave out (default: every connection but point clouds)");

  GraphArgs validate;
  auto* validate_cmd = app.add_subcommand("validate", "Check a graph and report every problem with file:line:col");
  validate_cmd->add_option("graph", validate.graph, "graph YAML file")->required();
  validate_cmd->add_option("--set", validate.overrides, "override a parameter: node.param=value (repeatable)");
  validate_cmd
      ->add_option("--executor", validate.executor,
                   "check the graph as it would run with this executor instead of its own")
      ->check(CLI::IsMember({"lockstep", "realtime"}));

  GraphArgs dot;
  std::string dot_output;
  auto* dot_cmd = app.add_subcommand("dot", "Print a graph in Graphviz dot");
  dot_cmd->add_option("graph", dot.graph, "graph YAML file")->required();
  dot_cmd->add_option("--set", dot.overrides, "override a parameter: node.param=value (repeatable)");
  dot_cmd->add_option("-o,--output", dot_output, "write to this file instead of stdout");

  MotArgs mot;
  auto* mot_cmd = app.add_subcommand("mot", "CLEAR-MOT and IDF1 of MOTChallenge CSV files (as py-motmetrics)");
  mot_cmd
      ->add_option("ground_truth", mot.ground_truth,
                   "ground-truth file: frame,id,bb_left,bb_top,bb_width,bb_height,conf,x,y,z")
      ->required();
  mot_cmd->add_option("test", mot.test, "tracker output in the same format")->required();
  mot_cmd->add_option("--iou", mot.iou, "match 2D boxes whose IoU is at least this (default 0.5)")
      ->check(CLI::Range(0.0, 1.0));
  mot_cmd->add_option("--dist", mot.distance, "match 3D points (x,y,z columns) within this distance instead")
      ->check(CLI::PositiveNumber);
  mot_cmd->add_option("--json", mot.json, "also write the metrics to this JSON file");

  PlotArgs plot;
  auto* plot_cmd =
      app.add_subcommand("plot", "Plot columns of a CSV file as PNG (one panel per y entry; a+b overlays)");
  plot_cmd->add_option("csv", plot.csv, "CSV file with a header row")->required();
  plot_cmd->add_option("--x", plot.x, "column for the x axis")->required();
  plot_cmd->add_option("--y", plot.y, "columns to plot, one panel each; a+b overlays a and b in one panel")
      ->required()
      ->delimiter(',');
  plot_cmd->add_option("-o,--output", plot.output, "PNG file to write")->required();
  plot_cmd->add_option("--meta", plot.meta,
                       "units and directions from this JSON's metrics_meta (a report.json); default: "
                       "metrics_meta.json beside the CSV, as kestrel sweep writes it");

  SweepArgs sweep;
  auto* sweep_cmd = app.add_subcommand(
      "sweep", "Run a graph over a grid of parameter values, or a table of cases, and seeds, in parallel");
  sweep_cmd->add_option("graph", sweep.graph, "graph YAML file")->required();
  // --param or --cases, exactly one: plan_sweep says so, as it checks the rest.
  sweep_cmd->add_option("--param", sweep.params, "node.param=start:stop:step (repeatable: a grid)");
  sweep_cmd->add_option("--cases", sweep.cases,
                        "CSV file instead of --param: a node.param per column (and optionally seed), a case per row");
  sweep_cmd->add_option("--set", sweep.overrides, "fixed override node.param=value (repeatable)");
  sweep_cmd->add_option("--seeds", sweep.seeds, "seeds per grid point or case (1..N); not with a seed column")
      ->check(CLI::Range(1, 100000));
  sweep_cmd->add_option("--duration", sweep.duration, "run length in seconds");
  sweep_cmd->add_option("--report", sweep.report_dir, "write DIR/sweep.csv, sweep.md, sweep.png and every run's report")
      ->required();
  sweep_cmd->add_option("--jobs", sweep.jobs, "runs at once (default: one per core)");
  add_backend_options(sweep_cmd, sweep.backend);

  AbArgs ab;
  auto* ab_cmd =
      app.add_subcommand("ab", "Compare two graphs on the same seeds: paired differences with 95% intervals");
  ab_cmd->add_option("a", ab.graph_a, "graph A")->required();
  ab_cmd->add_option("b", ab.graph_b, "graph B")->required();
  ab_cmd->add_option("--set", ab.overrides, "override applied to both (repeatable)");
  ab_cmd->add_option("--set-a", ab.overrides_a, "override applied to A only (repeatable; A and B may be one graph)");
  ab_cmd->add_option("--set-b", ab.overrides_b, "override applied to B only (repeatable)");
  ab_cmd->add_option("--seeds", ab.seeds, "number of seeds (1..N), at least 2")->check(CLI::Range(2, 100000));
  ab_cmd->add_option("--duration", ab.duration, "run length in seconds");
  ab_cmd->add_option("--report", ab.report_dir, "write DIR/ab.md, ab.json and every run's report")->required();
  ab_cmd->add_option("--jobs", ab.jobs, "runs at once (default: one per core)");
  add_backend_options(ab_cmd, ab.backend);

  std::string collect_dir;
  auto* collect_cmd = app.add_subcommand(
      "collect", "Summarise a sweep or ab that ran on Slurm (its collector job does this; again at any time)");
  collect_cmd->add_option("dir", collect_dir, "the batch's --report folder")->required();
  std::string task_dir;
  std::size_t task_index = 0;
  // Run by Slurm for each task of a submitted batch, not by people: hidden from the help.
  auto* batch_task_cmd = app.add_subcommand("batch-task", "")->group("");
  batch_task_cmd->add_option("dir", task_dir)->required();
  batch_task_cmd->add_option("index", task_index)->required();

  auto* plugins_cmd = app.add_subcommand("plugins", "List every node type, component and message type");

  std::string inspect_name;
  auto* inspect_cmd = app.add_subcommand("inspect", "Show a node type's ports and parameters (or a component's)");
  inspect_cmd->add_option("type", inspect_name, "node type, component (kind/name or name) or message type")->required();

  auto* mcap_cmd = app.add_subcommand("mcap", "Inspect MCAP recordings")->require_subcommand(1);
  McapInfoArgs mcap_info;
  auto* mcap_info_cmd =
      mcap_cmd->add_subcommand("info", "Channels, schemas, message counts and rates, time range, compression");
  mcap_info_cmd->add_option("file", mcap_info.file, "MCAP file")->required();
  mcap_info_cmd->add_flag("--json", mcap_info.json, "print JSON instead of text");
  mcap_info_cmd->add_flag("--verify", mcap_info.verify, "read the whole file and check every CRC it carries");

  McapCatArgs mcap_cat;
  auto* mcap_cat_cmd = mcap_cmd->add_subcommand(
      "cat", "Print messages as JSON lines: {\"log_time\": NS, \"topic\": T, \"message\": {...}}");
  mcap_cat_cmd->add_option("file", mcap_cat.file, "MCAP file")->required();
  mcap_cat_cmd->add_option("--topic", mcap_cat.topics, "only this topic (repeatable; default: every topic)");
  mcap_cat_cmd->add_option("--limit", mcap_cat.limit, "print at most N messages");

  auto* dds_cmd = app.add_subcommand("dds", "Topics on DDS, as ROS 2 sees them (docs/ros2.md)")->require_subcommand(1);
  DdsArgs dds_list;
  auto* dds_list_cmd = dds_cmd->add_subcommand(
      "list",
      "Discover the ROS 2 topics of a DDS domain: one JSON line per topic with its types, publishers, subscribers and "
      "QoS");
  dds_list_cmd->add_option("--domain", dds_list.domain, "DDS domain (default: ROS_DOMAIN_ID, else 0)");
  dds_list_cmd->add_option("--wait", dds_list.wait_s, "seconds to listen to discovery (default 2)");
  dds_list_cmd->add_flag("--text", dds_list.text,
                         "one line per topic, as ros2 topic list -t prints it, instead of JSON lines");
  DdsArgs dds_echo;
  auto* dds_echo_cmd = dds_cmd->add_subcommand(
      "echo", "Print a topic's messages as JSON lines: {\"source_time\": NS, \"topic\": T, \"message\": {...}}");
  dds_echo_cmd->add_option("topic", dds_echo.topic, "ROS 2 topic, /NODE/PORT")->required();
  dds_echo_cmd->add_option("--domain", dds_echo.domain, "DDS domain (default: ROS_DOMAIN_ID, else 0)");
  dds_echo_cmd->add_option("--wait", dds_echo.wait_s, "seconds to wait for the topic's first writer (default 10)")
      ->default_val(10.0);
  dds_echo_cmd->add_option("--count", dds_echo.count, "stop after printing N messages");
  dds_echo_cmd->add_option("--duration", dds_echo.duration_s, "stop after this many seconds");

  std::string msg_package_dir;
  auto* dds_msg_package_cmd = dds_cmd->add_subcommand(
      "msg-package", "Write DIR/kestrel_msgs, the ROS 2 package of kestrel's own message types, for a ROS 2 workspace");
  dds_msg_package_cmd->add_option("dir", msg_package_dir, "the folder it goes in (a workspace's src/)")->required();

  auto* devices_cmd = app.add_subcommand(
      "devices", "List V4L2 cameras and serial ports, with their formats, and which look like an oCamS");

  CalibrateArgs calibrate;
  auto* calibrate_cmd =
      app.add_subcommand("calibrate", "Stereo camera_info files (left.yaml, right.yaml) from chessboard image pairs");
  calibrate_cmd->add_option("left", calibrate.left, "folder or pattern (left/%06d.png) of the left images")->required();
  calibrate_cmd->add_option("right", calibrate.right, "folder or pattern of the right images")->required();
  calibrate_cmd->add_option("--board", calibrate.board, "inner corners, COLSxROWS (default 8x6)");
  calibrate_cmd->add_option("--square", calibrate.square_m, "side of a square, metres (default 0.025)");
  calibrate_cmd->add_option("--out", calibrate.out, "folder the two files are written to (default .)");
  calibrate_cmd->add_option("--name", calibrate.name, "camera_name prefix (default stereo)");

  auto* mavlink_cmd =
      app.add_subcommand("mavlink", "Talk to an autopilot over MAVLink (docs/field.md)")->require_subcommand(1);
  MavlinkListenArgs mavlink_listen;
  auto* mavlink_listen_cmd = mavlink_cmd->add_subcommand(
      "listen", "Print each message received (its name, then its fields, one line each) and the rates at the end");
  mavlink_listen_cmd
      ->add_option("connection", mavlink_listen.connection,
                   "udpin://0.0.0.0:14540, udpout://HOST:PORT or serial:///dev/ttyACM0:921600")
      ->required();
  mavlink_listen_cmd->add_option("--duration", mavlink_listen.duration_s, "stop after this many seconds");
  mavlink_listen_cmd->add_option("--count", mavlink_listen.count, "stop after printing N messages");
  mavlink_listen_cmd->add_option("--only", mavlink_listen.only, "print only this message, e.g. HEARTBEAT (repeatable)");
  mavlink_listen_cmd->add_flag("--heartbeat", mavlink_listen.heartbeat,
                               "send a ground station's heartbeat at 1 Hz (some autopilots stream only then)");

  std::string keygen_file;
  auto* mavlink_keygen_cmd = mavlink_cmd->add_subcommand(
      "keygen", "Write a new MAVLink 2 signing key (64 hexadecimal characters, readable by its owner only)");
  mavlink_keygen_cmd->add_option("file", keygen_file, "where to write it (never overwritten)")->required();
  MavlinkSetupSigningArgs setup_signing;
  auto* mavlink_setup_signing_cmd = mavlink_cmd->add_subcommand(
      "setup-signing", "Send an autopilot its signing key (SETUP_SIGNING), then check that it signs with it");
  mavlink_setup_signing_cmd
      ->add_option("connection", setup_signing.connection,
                   "the autopilot's link, over a channel you trust (USB): serial:///dev/ttyACM0:115200, udpin://...")
      ->required();
  mavlink_setup_signing_cmd->add_option("--key", setup_signing.key_file, "the key file (kestrel mavlink keygen)")
      ->required();
  mavlink_setup_signing_cmd->add_option("--timeout", setup_signing.timeout_s,
                                        "seconds to wait for the autopilot's heartbeat, then for its signed frames "
                                        "(default 10)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kOk : kUsage;
  }
  spdlog::set_level(spdlog::level::from_str(log_level));
  spdlog::set_pattern("[%l] %v");

  if (*run_cmd) return run_command(run);
  if (*validate_cmd) return validate_command(validate);
  if (*dot_cmd) return dot_command(dot, dot_output);
  if (*plugins_cmd) return plugins_command();
  if (*mot_cmd) return mot_command(mot);
  if (*sweep_cmd) return sweep_command(sweep);
  if (*ab_cmd) return ab_command(ab);
  if (*collect_cmd) return collect_command(collect_dir);
  if (*batch_task_cmd) return batch_task_command(task_dir, task_index);
  if (*plot_cmd) return plot_command(plot);
  if (*inspect_cmd) return inspect_command(inspect_name);
  if (*mcap_info_cmd) return mcap_info_command(mcap_info);
  if (*mcap_cat_cmd) return mcap_cat_command(mcap_cat);
  if (*devices_cmd) return devices_command();
  if (*calibrate_cmd) return calibrate_command(calibrate);
  if (*mavlink_listen_cmd) return mavlink_listen_command(mavlink_listen);
  if (*dds_list_cmd) return dds_list_command(dds_list);
  if (*dds_echo_cmd) return dds_echo_command(dds_echo);
  if (*dds_msg_package_cmd) return dds_msg_package_command(msg_package_dir);
  if (*mavlink_keygen_cmd) return mavlink_keygen_command(keygen_file);
  if (*mavlink_setup_signing_cmd) return mavlink_setup_signing_command(setup_signing);
  return kUsage;
}

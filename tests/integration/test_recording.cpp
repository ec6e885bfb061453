// Recording runs (`kestrel run --record`, the `recorder` node): a lockstep recording of the
// paper's detection graph is a ROS 2 MCAP file, the same bytes wherever it is written, holding
// every message; under realtime the recorder never holds the graph up and counts what it drops.
#include <gmock/gmock.h>

#include <filesystem>
#include <fstream>

#include "kestrel/mcap/reader.hpp"
#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/run.hpp"
#include "kestrel/testing/plugins.hpp"
#include "kestrel/testing/scratch_path.hpp"

using namespace kestrel;
namespace fs = std::filesystem;

namespace {

PluginHost& plugins() { return kestrel::testing::built_plugins(); }

RunResult record(const fs::path& file, double duration, const std::string& extra_params = "",
                 const std::string& executor = "lockstep") {
  const auto graph = GraphSource::from_file(KESTREL_SOURCE_DIR "/graphs/paper_detection.yaml");
  const auto recorder = GraphSource::from_string(
      "nodes: [{id: recorder, type: recorder, params: {file: '" + file.string() + "'" + extra_params + "}}]",
      "--record");
  auto built = build_graph(graph, plugins().registry(), {}, {&recorder});
  EXPECT_TRUE(built.graph) << built.diagnostics.str();
  if (!built.graph) return {};
  if (executor == "realtime") {
    built.graph->executor = ExecutorKind::realtime;
    built.graph->clock = ClockKind::wall;
  }
  RunOptions options;
  options.duration_s = duration;
  return run_graph(*built.graph, plugins().registry(), options);
}

std::string bytes(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

fs::path scratch(const std::string& name) {
  const auto dir = kestrel::testing::scratch_path("kestrel-recording");
  fs::create_directories(dir);
  return dir / name;
}

}  // namespace

TEST(Recording, ALockstepRunIsAnRos2McapFileTheSameBytesWhereverItIsWritten) {
  const auto a = scratch("a.mcap"), b = scratch("elsewhere-b.mcap");
  const auto ra = record(a, 1.0);
  ASSERT_EQ(ra.outcome, RunOutcome::completed) << (ra.errors.empty() ? "" : ra.errors.front());
  const auto rb = record(b, 1.0);
  ASSERT_EQ(rb.outcome, RunOutcome::completed);
  EXPECT_TRUE(bytes(a) == bytes(b)) << "two identical runs gave different files";

  mcap::Reader reader(a);
  const auto& summary = reader.summary();
  EXPECT_TRUE(summary.indexed);
  EXPECT_EQ(summary.header.profile, "ros2");
  std::map<std::string, std::string> types;
  for (const auto& [id, channel] : summary.channels) {
    EXPECT_EQ(channel.message_encoding, "cdr") << channel.topic;
    const auto& schema = summary.schemas.at(channel.schema_id);
    EXPECT_EQ(schema.encoding, "ros2msg");
    types[channel.topic] = schema.name;
  }
  EXPECT_EQ(types["/camera/frame/left"], "sensor_msgs/msg/Image");
  EXPECT_EQ(types["/camera/frame/right/camera_info"], "sensor_msgs/msg/CameraInfo");
  EXPECT_EQ(types["/camera/truth"], "kestrel_msgs/msg/GroundTruth");
  EXPECT_EQ(types["/refine/detections"], "kestrel_msgs/msg/Detections");
  EXPECT_EQ(types["/refine/detections/markers"], "visualization_msgs/msg/MarkerArray");
  EXPECT_FALSE(types.count("/depth/cloud")) << "intermediate clouds are left out by default";

  // Every message the graph published on a recorded output is in the file: 30 frames in 1 s.
  std::map<std::string, std::uint64_t> counts;
  reader.read_messages({}, [&](const mcap::MessageView& m) { ++counts[m.channel.topic]; });
  EXPECT_EQ(counts["/camera/frame/left"], 30u);
  EXPECT_EQ(counts["/camera/truth"], 30u);
  EXPECT_EQ(counts["/refine/detections"], 30u);
  EXPECT_EQ(ra.report.at("recorder").at("dropped"), 0);
  EXPECT_EQ(ra.report.at("recorder").at("messages"), summary.statistics.message_count);

  std::map<std::string, mcap::KeyValues> metadata;
  for (const auto& m : reader.metadata()) metadata[m.name] = m.metadata;
  EXPECT_EQ(metadata["kestrel"]["seed"], "1");
  EXPECT_EQ(metadata["kestrel"]["duration_s"], "1.0");
  EXPECT_THAT(metadata["graph"]["text"], ::testing::HasSubstr("type: sim_stereo"));
  EXPECT_THAT(metadata["graph"]["resolved"], ::testing::HasSubstr("\"hfov_deg\""));
  EXPECT_THAT(metadata["graph"]["resolved"], ::testing::Not(::testing::HasSubstr(a.string())));
}

TEST(Recording, TopicPatternsChooseWhatIsRecordedAndUnmappedTypesAreCounted) {
  const auto f = scratch("topics.mcap");
  const auto r = record(f, 0.5, ", topics: '/depth/cloud, /camera/truth', compression: lz4");
  ASSERT_EQ(r.outcome, RunOutcome::completed);
  mcap::Reader reader(f);
  std::set<std::string> topics;
  for (const auto& [id, channel] : reader.summary().channels) topics.insert(channel.topic);
  EXPECT_THAT(topics, ::testing::ElementsAre("/camera/truth", "/camera/truth/markers", "/depth/cloud"));
  EXPECT_EQ(reader.summary().chunk_indexes.front().compression, "lz4");
}

TEST(Recording, UnderRealtimeTheRecorderWritesFromItsOwnThreadAndCountsDrops) {
  const auto f = scratch("realtime.mcap");
  const auto r = record(f, 1.5, ", queue_size: 4", "realtime");
  ASSERT_NE(r.outcome, RunOutcome::failed) << (r.errors.empty() ? "" : r.errors.front());
  const auto& section = r.report.at("recorder");
  mcap::Reader reader(f);
  EXPECT_EQ(section.at("messages"), reader.summary().statistics.message_count);
  EXPECT_GT(section.at("messages").get<std::uint64_t>(), 0u);
  std::map<std::string, mcap::KeyValues> metadata;
  for (const auto& m : reader.metadata()) metadata[m.name] = m.metadata;
  EXPECT_EQ(metadata["kestrel.recorder"]["dropped"], section.at("dropped").dump());
}

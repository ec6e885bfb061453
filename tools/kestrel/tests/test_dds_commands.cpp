// `kestrel dds list`, `kestrel dds echo` and `kestrel run --dds` as a user runs them, the other
// end of the domain played by the test through kestrel::dds on the loopback interface.
#include <gmock/gmock.h>

#include <atomic>
#include <filesystem>
#include <future>
#include <kestrel/dds/reader.hpp>
#include <kestrel/dds/writer.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/ros2_messages/message_mapping.hpp>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "kestrel/testing/dds_loopback.hpp"
#include "kestrel/testing/read_file.hpp"
#include "kestrel/testing/run_command.hpp"
#include "kestrel/testing/scratch_path.hpp"

using namespace kestrel;
using namespace std::chrono_literals;
using kestrel::testing::run_command;
using ::testing::HasSubstr;

namespace {

class DdsCommands : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { domain_ = kestrel::testing::use_dds_loopback(); }
  static std::string cli(const std::string& args) {
    return std::string(KESTREL_CLI) + " " + args + " --domain " + std::to_string(domain_);
  }
  static std::uint32_t domain_;
};
std::uint32_t DdsCommands::domain_ = 0;

std::vector<std::uint8_t> tracks_cdr(std::uint64_t id) {
  msg::Tracks t;
  t.stamp = Time(2'500'000'000);
  msg::Track a;
  a.id = id;
  a.state = Eigen::VectorXd::LinSpaced(3, 1.0, 3.0);
  a.covariance = Eigen::MatrixXd::Identity(3, 3);
  t.items = {a};
  return ros2::encode("kestrel.Tracks", &t, "/tracker/tracks").messages.at(0).cdr;
}

// Writes `cdr` every 20 ms until `stop`.
std::thread keep_writing(dds::Writer& writer, std::vector<std::uint8_t> cdr, std::atomic<bool>& stop) {
  return std::thread([&writer, cdr = std::move(cdr), &stop] {
    while (!stop) {
      writer.write(cdr);
      std::this_thread::sleep_for(20ms);
    }
  });
}

TEST_F(DdsCommands, ListShowsRosTwoTopicsWithTheirTypesAndEnds) {
  dds::Participant participant(domain_);
  dds::Writer writer(participant, "rt/hunter/tracks", "kestrel_msgs::msg::dds_::Tracks_", dds::Qos{});
  dds::Reader reader(participant, "rt/hunter/state", "nav_msgs::msg::dds_::Odometry_", dds::Qos{});
  dds::Writer other(participant, "NotRos", "Other", dds::Qos{});
  const auto out = run_command(cli("dds list --wait 1.5 --text"));
  EXPECT_EQ(out.status, 0) << out.text;
  EXPECT_THAT(out.text, HasSubstr("/hunter/tracks [kestrel_msgs/msg/Tracks] 1 publisher, 0 subscribers"));
  EXPECT_THAT(out.text, HasSubstr("/hunter/state [nav_msgs/msg/Odometry] 0 publishers, 1 subscriber"));
  EXPECT_THAT(out.text, ::testing::Not(HasSubstr("NotRos")));  // not a ROS 2 topic

  const auto json = run_command(cli("dds list --wait 1.5"));
  ASSERT_EQ(json.status, 0) << json.text;
  std::istringstream lines(json.text);
  std::string line;
  bool found = false;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] != '{') continue;
    const auto j = nlohmann::json::parse(line);
    if (j["topic"] != "/hunter/tracks") continue;
    found = true;
    EXPECT_EQ(j["dds_types"][0], "kestrel_msgs::msg::dds_::Tracks_");
    EXPECT_EQ(j["qos"][0], "reliable, keep last 10, volatile");
  }
  EXPECT_TRUE(found) << json.text;
}

TEST_F(DdsCommands, EchoPrintsMessagesAsJsonLinesDecodedByTheAnnouncedType) {
  dds::Participant participant(domain_);
  dds::Writer writer(participant, "rt/tracker/tracks", "kestrel_msgs::msg::dds_::Tracks_", dds::Qos{});
  std::atomic<bool> stop{false};
  auto thread = keep_writing(writer, tracks_cdr(7), stop);
  const auto out = run_command(cli("dds echo /tracker/tracks --count 2 2>/dev/null"));
  stop = true;
  thread.join();
  ASSERT_EQ(out.status, 0) << out.text;
  std::istringstream lines(out.text);
  std::string line;
  int printed = 0;
  while (std::getline(lines, line)) {
    const auto j = nlohmann::json::parse(line);
    EXPECT_EQ(j["topic"], "/tracker/tracks");
    EXPECT_GT(j["source_time"].get<std::int64_t>(), 0);
    EXPECT_EQ(j["message"]["header"]["stamp"]["sec"], 2);
    EXPECT_EQ(j["message"]["header"]["stamp"]["nanosec"], 500000000);
    EXPECT_EQ(j["message"]["tracks"][0]["id"], 7);
    EXPECT_EQ(j["message"]["tracks"][0]["state"], nlohmann::json::array({1.0, 2.0, 3.0}));
    ++printed;
  }
  EXPECT_EQ(printed, 2);
}

TEST_F(DdsCommands, EchoWithoutAWriterOrWithBytesThatAreNotTheTypeSaysSo) {
  const auto none = run_command(cli("dds echo /nobody/here --wait 0.5"));
  EXPECT_EQ(none.status, 4);
  EXPECT_THAT(none.text, HasSubstr("no writer of /nobody/here found in DDS domain"));

  const auto bad_name = run_command(cli("dds echo nobody --wait 0.5"));
  EXPECT_EQ(bad_name.status, 2);
  EXPECT_THAT(bad_name.text, HasSubstr("must start with '/'"));

  dds::Participant participant(domain_);
  dds::Writer writer(participant, "rt/rogue/tracks", "kestrel_msgs::msg::dds_::Tracks_", dds::Qos{});
  std::atomic<bool> stop{false};
  auto thread = keep_writing(writer, {0x00, 0x01, 0x00, 0x00, 0xff, 0xff, 0xff, 0x7f}, stop);
  const auto out = run_command(cli("dds echo /rogue/tracks --duration 1.5"));
  stop = true;
  thread.join();
  EXPECT_EQ(out.status, 1) << out.text;
  EXPECT_THAT(out.text, HasSubstr("is not a kestrel_msgs/msg/Tracks"));
}

TEST_F(DdsCommands, RunDdsPublishesEveryConnectedOutput) {
  // The realtime run publishes as it goes; echo catches its tracks.
  auto run = std::async(std::launch::async, [] {
    return run_command(std::string(KESTREL_CLI) +
                       " run " KESTREL_SOURCE_DIR
                       "/graphs/sim_intercept_fast.yaml --executor realtime --duration 6 --no-progress --dds "
                       "--dds-domain " +
                       std::to_string(domain_));
  });
  const auto echo = run_command(cli("dds echo /tracker/tracks --count 1 --wait 5"));
  const auto list = run_command(cli("dds list --wait 1 --text"));
  const auto ran = run.get();
  EXPECT_EQ(ran.status, 0) << ran.text;
  EXPECT_EQ(echo.status, 0) << echo.text;
  EXPECT_THAT(echo.text, HasSubstr("\"topic\":\"/tracker/tracks\""));
  EXPECT_THAT(list.text, HasSubstr("/hunter/state [nav_msgs/msg/Odometry]"));
  EXPECT_THAT(list.text, HasSubstr("/tf [tf2_msgs/msg/TFMessage]"));
}

TEST_F(DdsCommands, MsgPackageWritesTheRosTwoPackageOfKestrelsOwnTypes) {
  const auto dir = kestrel::testing::scratch_path("msg_package");
  std::filesystem::remove_all(dir);
  const auto out = run_command(std::string(KESTREL_CLI) + " dds msg-package " + dir.string());
  ASSERT_EQ(out.status, 0) << out.text;
  const auto root = dir / "kestrel_msgs";
  EXPECT_EQ(kestrel::testing::read_file(root / "msg" / "Tracks.msg"),
            "std_msgs/Header header\nTrack[] tracks\nbool has_selected\nuint64 selected_id\n");
  EXPECT_EQ(kestrel::testing::read_file(root / "msg" / "Track.msg"),
            "uint64 id\nint32 age\nint32 hits\nint32 misses\nfloat64[] state\nfloat64[] covariance\n"
            "geometry_msgs/Point detection\n");
  const std::string cmake = kestrel::testing::read_file(root / "CMakeLists.txt");
  EXPECT_THAT(cmake, HasSubstr("\"msg/Detections.msg\""));
  EXPECT_THAT(cmake, HasSubstr("DEPENDENCIES builtin_interfaces geometry_msgs std_msgs)"));
  EXPECT_THAT(kestrel::testing::read_file(root / "package.xml"),
              HasSubstr("<member_of_group>rosidl_interface_packages"));
  // Never over an existing package.
  EXPECT_EQ(run_command(std::string(KESTREL_CLI) + " dds msg-package " + dir.string()).status, 2);
}

TEST_F(DdsCommands, BadDomainsAreUsageErrors) {
  EXPECT_EQ(run_command(std::string(KESTREL_CLI) + " dds list --domain 233").status, 2);
  EXPECT_EQ(run_command("ROS_DOMAIN_ID=x " + std::string(KESTREL_CLI) + " dds list").status, 2);
  const auto alone = run_command(std::string(KESTREL_CLI) + " run " KESTREL_SOURCE_DIR
                                                            "/graphs/hover_step.yaml --dds-domain 3 --duration 0.1");
  EXPECT_EQ(alone.status, 2);
  EXPECT_THAT(alone.text, HasSubstr("--dds-domain goes with --dds"));
}

}  // namespace

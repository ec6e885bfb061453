// The message reference cannot drift from the code: every message type an in-tree plugin
// registers declares its fields (type, unit, frame, meaning), and docs/messages.md has a section
// for it that names each of them.
#include <gmock/gmock.h>

#include <fstream>
#include <kestrel/messages/actuator_command.hpp>
#include <kestrel/messages/attitude_target.hpp>
#include <kestrel/messages/autopilot_status.hpp>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/ground_truth.hpp>
#include <kestrel/messages/net_capture.hpp>
#include <kestrel/messages/net_fire.hpp>
#include <kestrel/messages/net_launcher.hpp>
#include <kestrel/messages/point_cloud.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/messages/tracks.hpp>
#include <kestrel/messages/trajectory_setpoint.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <map>
#include <sstream>

#include "kestrel/runtime/plugin_host.hpp"
#include "kestrel/testing/plugins.hpp"

using namespace kestrel;

namespace {

std::string read(const std::string& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The text of docs/messages.md from `### `NAME`` to the next section of the same level.
std::string section(const std::string& doc, const std::string& name) {
  const auto start = doc.find("### `" + name + "`");
  if (start == std::string::npos) return {};
  const auto end = doc.find("\n### ", start + 1);
  return doc.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

}  // namespace

TEST(MessageReference, EveryInTreeMessageDeclaresItsFieldsAndIsDocumented) {
  // Every type of kestrel::messages, and whatever else the shipped plugins register.
  std::map<std::string, MessageInfo> types;
  for (const MessageInfo& info :
       {message_info<msg::StereoFrame>(), message_info<msg::PointCloud>(), message_info<msg::Detections>(),
        message_info<msg::Tracks>(), message_info<msg::GroundTruth>(), message_info<msg::VehicleState>(),
        message_info<msg::TrajectorySetpoint>(), message_info<msg::ActuatorCommand>(),
        message_info<msg::AttitudeTarget>(), message_info<msg::NetFire>(), message_info<msg::NetCapture>(),
        message_info<msg::NetLauncher>(), message_info<msg::AutopilotStatus>()})
    types[info.name] = info;
  PluginHost& host = kestrel::testing::built_plugins();
  ASSERT_TRUE(host.errors().empty()) << host.errors().front().message;
  for (const auto& [name, entry] : host.registry().messages())
    if (name != "*") types[name] = entry.info;
  const std::string doc = read(KESTREL_SOURCE_DIR "/docs/messages.md");
  ASSERT_FALSE(doc.empty());
  for (const auto& [name, info] : types) {
    EXPECT_FALSE(info.fields.empty()) << name << " declares no fields (KESTREL_MESSAGE_FIELDS)";
    const std::string text = section(doc, name);
    EXPECT_FALSE(text.empty()) << "docs/messages.md has no section ### `" << name << "`";
    for (const auto& f : info.fields) {
      EXPECT_FALSE(f.type.empty()) << name << "." << f.name;
      EXPECT_FALSE(f.description.empty()) << name << "." << f.name;
      // The doc's tables name a nested field by its last part (`position` under `Detection`).
      const std::string leaf =
          f.name.substr(f.name.find_last_of(".]") == std::string::npos ? 0 : f.name.find_last_of(".]") + 1);
      EXPECT_THAT(text, ::testing::HasSubstr("`" + leaf + "`"))
          << name << "." << f.name << " is not in docs/messages.md";
    }
  }
}

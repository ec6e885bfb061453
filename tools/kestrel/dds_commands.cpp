// kestrel dds list | echo: a DDS domain's ROS 2 topics, as `ros2 topic list -t` and `ros2 topic
// echo` show them, from discovery alone: a topic's type is the type name its writers announce,
// decoded with kestrel's ROS 2 definitions, so no ROS 2 installation is needed (docs/ros2.md).
#include <signal.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <kestrel/dds/discovery.hpp>
#include <kestrel/dds/reader.hpp>
#include <kestrel/dds/ros2_names.hpp>
#include <kestrel/error.hpp>
#include <kestrel/version.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "command_errors.hpp"
#include "commands.hpp"
#include "kestrel/ros2/cdr_json.hpp"
#include "kestrel/ros2/definitions.hpp"

namespace kestrel::cli {
namespace {

std::atomic<bool> g_echo_stop{false};
void on_echo_signal(int) { g_echo_stop = true; }

std::chrono::milliseconds milliseconds(double seconds) {
  return std::chrono::milliseconds(static_cast<std::int64_t>(std::max(0.0, seconds) * 1000.0));
}

struct TopicSummary {
  std::string dds_topic;
  std::set<std::string> dds_types;
  std::size_t publishers = 0, subscribers = 0;
  std::set<std::string> qos;
};

std::string ros_type_or_dds(const std::string& dds_type) { return dds::ros2_type_of(dds_type).value_or(dds_type); }

}  // namespace

std::uint32_t dds_domain(std::optional<std::int64_t> given) {
  std::int64_t domain = 0;
  if (given) {
    domain = *given;
  } else if (const char* env = std::getenv("ROS_DOMAIN_ID"); env != nullptr && *env != '\0') {
    char* end = nullptr;
    domain = std::strtoll(env, &end, 10);
    if (*end != '\0') throw Error(std::string("ROS_DOMAIN_ID='") + env + "' is not a number");
  }
  if (domain < 0 || domain > 232) throw Error("DDS domain " + std::to_string(domain) + " is out of range (0 to 232)");
  return static_cast<std::uint32_t>(domain);
}

int dds_list_command(const DdsArgs& args) {
  return run_command_body("dds list", [&] {
    dds::Participant participant(dds_domain(args.domain));
    dds::Discovery discovery(participant);
    const auto endpoints = discovery.wait(milliseconds(args.wait_s), [](const auto&) { return false; });
    std::map<std::string, TopicSummary> topics;  // by ROS 2 name
    for (const auto& e : endpoints) {
      const auto ros_topic = dds::ros2_topic_of(e.dds_topic);
      if (!ros_topic) continue;  // DDS's own topics, services, other middleware
      TopicSummary& t = topics[*ros_topic];
      t.dds_topic = e.dds_topic;
      t.dds_types.insert(e.dds_type);
      (e.writer ? t.publishers : t.subscribers)++;
      t.qos.insert(to_string(e.qos));
    }
    for (const auto& [name, t] : topics) {
      std::vector<std::string> types;
      for (const auto& d : t.dds_types) types.push_back(ros_type_or_dds(d));
      if (!args.text) {
        nlohmann::ordered_json line;
        line["topic"] = name;
        line["types"] = types;
        line["dds_topic"] = t.dds_topic;
        line["dds_types"] = t.dds_types;
        line["publishers"] = t.publishers;
        line["subscribers"] = t.subscribers;
        line["qos"] = t.qos;
        std::printf("%s\n", line.dump().c_str());
      } else {
        std::string joined;
        for (const auto& type : types) joined += (joined.empty() ? "" : ", ") + type;
        std::printf("%s [%s] %zu publisher%s, %zu subscriber%s\n", name.c_str(), joined.c_str(), t.publishers,
                    t.publishers == 1 ? "" : "s", t.subscribers, t.subscribers == 1 ? "" : "s");
      }
    }
    std::fflush(stdout);
    return kOk;
  });
}

int dds_echo_command(const DdsArgs& args) {
  return run_command_body("dds echo", [&] {
    const std::string dds_topic = dds::ros2_dds_topic(args.topic);
    const std::uint32_t domain = dds_domain(args.domain);
    dds::Participant participant(domain);
    dds::Discovery discovery(participant);
    const auto is_writer = [&](const dds::DiscoveredEndpoint& e) { return e.writer && e.dds_topic == dds_topic; };
    const auto endpoints = discovery.wait(milliseconds(args.wait_s), [&](const auto& found) {
      return std::any_of(found.begin(), found.end(), is_writer);
    });
    // As `ros2 topic echo` does, the reader adapts to the writers: best effort if any of them is,
    // transient local only if all are (then it gets what they kept).
    std::string dds_type;
    dds::Qos qos;
    bool all_transient = true;
    for (const auto& e : endpoints) {
      if (!is_writer(e)) continue;
      if (!dds_type.empty() && e.dds_type != dds_type)
        throw Error(args.topic + " has writers of two types, " + dds_type + " and " + e.dds_type);
      dds_type = e.dds_type;
      if (e.qos.reliability == dds::Reliability::best_effort) qos.reliability = dds::Reliability::best_effort;
      all_transient = all_transient && e.qos.durability == dds::Durability::transient_local;
      qos.depth = std::max(qos.depth, e.qos.depth);
    }
    if (dds_type.empty())
      throw CommandError(kNotFound, "no writer of " + args.topic + " found in DDS domain " + std::to_string(domain) +
                                        " within " + std::to_string(args.wait_s) +
                                        " s (kestrel dds list shows what there is)");
    if (all_transient) qos.durability = dds::Durability::transient_local;
    const auto ros_type = dds::ros2_type_of(dds_type);
    if (!ros_type) throw Error(args.topic + " carries '" + dds_type + "', which is not a ROS 2 message type");
    const ros2::MessageSchema schema(*ros_type, ros2::schema_text(*ros_type));

    dds::Reader reader(participant, dds_topic, dds_type, qos);
    g_echo_stop = false;
    struct sigaction action {};
    action.sa_handler = on_echo_signal;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    const auto start = std::chrono::steady_clock::now();
    std::uint64_t printed = 0, undecodable = 0;
    const auto done = [&] {
      return g_echo_stop || (args.count && printed >= *args.count) ||
             (args.duration_s && std::chrono::steady_clock::now() - start >= milliseconds(*args.duration_s));
    };
    while (!done()) {
      reader.take([&](dds::ReceivedSample&& sample) {
        if (done()) return;
        nlohmann::ordered_json line;
        line["source_time"] = sample.source_time_ns;
        line["topic"] = args.topic;
        try {
          line["message"] = ros2::cdr_to_json(schema, sample.cdr);
        } catch (const Error& e) {
          ++undecodable;
          std::fprintf(stderr, "kestrel dds echo: a sample of %s is not a %s (%s): skipped\n", args.topic.c_str(),
                       ros_type->c_str(), e.what());
          return;
        }
        std::printf("%s\n", line.dump().c_str());
        std::fflush(stdout);
        ++printed;
      });
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return undecodable > 0 ? kRunFailed : kOk;
  });
}

namespace {

// A type's own fields: its schema text up to the first dependency's separator.
std::string own_definition(const std::string& type) {
  const std::string& text = ros2::schema_text(type);
  const auto separator = text.find("\n" + std::string(80, '=') + "\n");
  return separator == std::string::npos ? text : text.substr(0, separator + 1);
}

// The packages the fields name ("std_msgs/Header header": std_msgs).
void add_dependencies(const std::string& definition, std::set<std::string>& packages) {
  std::istringstream lines(definition);
  std::string line;
  while (std::getline(lines, line)) {
    const auto slash = line.find('/');
    const auto space = line.find(' ');
    if (slash != std::string::npos && slash < space) packages.insert(line.substr(0, slash));
  }
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw Error("cannot write " + path.string());
}

}  // namespace

int dds_msg_package_command(const std::string& dir) {
  return run_command_body("dds msg-package", [&] {
    const std::filesystem::path root = std::filesystem::path(dir) / "kestrel_msgs";
    if (std::filesystem::exists(root)) throw Error(root.string() + " exists already; give another folder");
    std::filesystem::create_directories(root / "msg");
    std::set<std::string> dependencies;
    std::string files;
    for (const std::string& type : ros2::defined_types()) {
      if (!type.starts_with("kestrel_msgs/")) continue;
      const std::string name = type.substr(type.rfind('/') + 1);
      const std::string definition = own_definition(type);
      add_dependencies(definition, dependencies);
      write_text(root / "msg" / (name + ".msg"), definition);
      files += "  \"msg/" + name + ".msg\"\n";
    }
    std::string depends, finds, depend_tags;
    for (const auto& d : dependencies) {
      depends += " " + d;
      finds += "find_package(" + d + " REQUIRED)\n";
      depend_tags += "  <depend>" + d + "</depend>\n";
    }
    write_text(root / "CMakeLists.txt",
               "# kestrel's own ROS 2 messages, as kestrel writes them (kestrel dds msg-package): build this package\n"
               "# in a ROS 2 workspace (colcon build) to echo, record or subscribe to kestrel's topics.\n"
               "cmake_minimum_required(VERSION 3.8)\nproject(kestrel_msgs)\nfind_package(ament_cmake REQUIRED)\n"
               "find_package(rosidl_default_generators REQUIRED)\n" +
                   finds + "rosidl_generate_interfaces(${PROJECT_NAME}\n" + files + "  DEPENDENCIES" + depends +
                   ")\nament_export_dependencies(rosidl_default_runtime)\nament_package()\n");
    write_text(
        root / "package.xml",
        "<?xml version=\"1.0\"?>\n<package format=\"3\">\n  <name>kestrel_msgs</name>\n"
        "  <version>" KESTREL_VERSION_STRING
        "</version>\n"
        "  <description>kestrel's messages as ROS 2 messages (generated by kestrel dds msg-package)</description>\n"
        "  <maintainer email=\"kestrel@localhost\">kestrel</maintainer>\n  <license>Apache-2.0</license>\n"
        "  <buildtool_depend>ament_cmake</buildtool_depend>\n"
        "  <buildtool_depend>rosidl_default_generators</buildtool_depend>\n" +
            depend_tags +
            "  <exec_depend>rosidl_default_runtime</exec_depend>\n"
            "  <member_of_group>rosidl_interface_packages</member_of_group>\n"
            "  <export>\n    <build_type>ament_cmake</build_type>\n  </export>\n</package>\n");
    std::printf("%s: the ROS 2 package kestrel_msgs (%s); in a ROS 2 workspace's src/, colcon build\n", root.c_str(),
                files.empty() ? "no messages" : "msg/*.msg, package.xml, CMakeLists.txt");
    return kOk;
  });
}

}  // namespace kestrel::cli

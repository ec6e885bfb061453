// `kestrel mavlink listen URL`: the messages an autopilot sends, one line each (name, then
// fields), and their rates at the end, like a minimal MAVProxy, for checks in the field.
#include <signal.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <kestrel/error.hpp>
#include <map>
#include <set>

#include "commands.hpp"
#include "kestrel/mavlink/frame_parser.hpp"
#include "kestrel/mavlink/message_text.hpp"
#include "kestrel/mavlink/messages.hpp"
#include "kestrel/mavlink/transport.hpp"

namespace kestrel::cli {

namespace {

std::atomic<bool> g_listen_stop{false};
void on_listen_signal(int) { g_listen_stop = true; }

void print_summary(const std::map<std::string, std::uint64_t>& counts, double seconds,
                   const mavlink::ParserCounts& parser) {
  std::fprintf(stderr, "%llu frames in %.1f s", static_cast<unsigned long long>(parser.frames), seconds);
  std::fprintf(stderr, " (bad checksum %llu, unknown id %llu, bad flags %llu, bytes skipped %llu)\n",
               static_cast<unsigned long long>(parser.bad_checksum), static_cast<unsigned long long>(parser.unknown_id),
               static_cast<unsigned long long>(parser.bad_flags),
               static_cast<unsigned long long>(parser.bytes_skipped));
  for (const auto& [name, n] : counts)
    std::fprintf(stderr, "  %-32s %8llu  %7.2f Hz\n", name.c_str(), static_cast<unsigned long long>(n),
                 seconds > 0 ? static_cast<double>(n) / seconds : 0.0);
}

}  // namespace

int mavlink_listen_command(const MavlinkListenArgs& args) {
  std::unique_ptr<mavlink::Transport> link;
  try {
    const auto url = mavlink::parse_connection_url(args.connection);
    try {
      link = mavlink::open_transport(url);
    } catch (const Error& e) {
      std::fprintf(stderr, "kestrel mavlink listen: %s\n", e.what());
      return kRunFailed;
    }
  } catch (const Error& e) {
    std::fprintf(stderr, "kestrel mavlink listen: %s\n", e.what());
    return kUsage;
  }
  const std::set<std::string> only(args.only.begin(), args.only.end());
  for (const std::string& name : only) {
    bool known = false;
    for (const auto* d : mavlink::known_definitions()) known = known || d->name() == name;
    if (!known) {
      std::fprintf(stderr, "kestrel mavlink listen: --only %s: not a message kestrel decodes\n", name.c_str());
      return kUsage;
    }
  }

  struct sigaction action {};
  action.sa_handler = on_listen_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);

  std::fprintf(stderr, "listening on %s (Ctrl-C stops)\n", link->describe().c_str());
  mavlink::FrameParser parser;
  mavlink::FrameWriter ground_station({255, 190});  // a GCS's ids, as QGroundControl uses
  std::map<std::string, std::uint64_t> counts;
  std::uint64_t printed = 0;
  const auto start = std::chrono::steady_clock::now();
  auto next_heartbeat = start;
  std::vector<std::uint8_t> buffer(4096);
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  try {
    while (!g_listen_stop && (!args.duration_s || elapsed() < *args.duration_s) &&
           (!args.count || printed < *args.count)) {
      if (args.heartbeat && std::chrono::steady_clock::now() >= next_heartbeat) {
        link->send(ground_station.encode(mavlink::ground_station_heartbeat()));
        next_heartbeat += std::chrono::seconds(1);
      }
      const std::size_t n = link->receive(buffer, std::chrono::milliseconds(100));
      for (const mavlink::Frame& f : parser.feed(std::span(buffer.data(), n))) {
        const auto* d = mavlink::find_definition(f.message_id);
        const std::string name(d->name());
        ++counts[name];
        if (!only.empty() && !only.contains(name)) continue;
        if (args.count && printed >= *args.count) continue;
        std::printf("%s\n", mavlink::message_text(*d, f.payload).c_str());
        std::fflush(stdout);
        ++printed;
      }
    }
  } catch (const Error& e) {
    std::fprintf(stderr, "kestrel mavlink listen: %s\n", e.what());
    print_summary(counts, elapsed(), parser.counts());
    return kRunFailed;
  }
  print_summary(counts, elapsed(), parser.counts());
  if (parser.counts().frames == 0) {
    std::fprintf(stderr, "kestrel mavlink listen: no MAVLink frame received on %s\n", args.connection.c_str());
    return kRunFailed;
  }
  return kOk;
}

}  // namespace kestrel::cli

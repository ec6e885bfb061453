// `kestrel mavlink keygen FILE` and `kestrel mavlink setup-signing URL --key FILE`: the two steps
// of putting MAVLink 2 signing on a vehicle (docs/field.md, "Security"). The key is written
// readable by its owner only and never printed; SETUP_SIGNING carries it in clear, so it goes
// over a channel the user trusts (USB), and the command then checks that the autopilot's own
// frames come signed with that key.
#include <chrono>
#include <cstdio>
#include <kestrel/error.hpp>
#include <optional>

#include "commands.hpp"
#include "kestrel/mavlink/frame_parser.hpp"
#include "kestrel/mavlink/messages.hpp"
#include "kestrel/mavlink/signing.hpp"
#include "kestrel/mavlink/transport.hpp"

namespace kestrel::cli {

int mavlink_keygen_command(const std::string& file) {
  try {
    mavlink::write_signing_key(file, mavlink::random_signing_key());
  } catch (const Error& e) {
    std::fprintf(stderr, "kestrel mavlink keygen: %s\n", e.what());
    return kRunFailed;
  }
  std::fprintf(stderr,
               "wrote a new signing key to %s (readable by you only). Give both ends the same file: "
               "signing_key_file in the graph, and kestrel mavlink setup-signing for the autopilot.\n",
               file.c_str());
  return kOk;
}

int mavlink_setup_signing_command(const MavlinkSetupSigningArgs& args) {
  const char* const name = "kestrel mavlink setup-signing";
  std::unique_ptr<mavlink::Transport> link;
  mavlink::SigningKey key{};
  try {
    const auto url = mavlink::parse_connection_url(args.connection);
    try {
      key = mavlink::load_signing_key(args.key_file);
      link = mavlink::open_transport(url);
    } catch (const Error& e) {
      std::fprintf(stderr, "%s: %s\n", name, e.what());
      return kRunFailed;
    }
  } catch (const Error& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return kUsage;
  }

  using Clock = std::chrono::steady_clock;
  const auto deadline = [](Clock::time_point from, double s) {
    return from + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
  };
  const Clock::time_point start = Clock::now();
  mavlink::FrameParser parser;
  mavlink::FrameWriter ground_station({255, 190});  // a GCS's ids, as QGroundControl uses
  std::vector<std::uint8_t> buffer(4096);
  std::optional<mavlink::Sender> autopilot;
  std::optional<Clock::time_point> sent_at, last_sent_at;
  Clock::time_point next_heartbeat = start;
  std::uint64_t verified = 0, unsigned_frames = 0, other_key = 0;
  try {
    while (Clock::now() < deadline(sent_at.value_or(start), args.timeout_s) && verified == 0) {
      const Clock::time_point now = Clock::now();
      if (now >= next_heartbeat) {
        link->send(ground_station.encode(mavlink::ground_station_heartbeat()));
        next_heartbeat = now + std::chrono::seconds(1);
      }
      // SETUP_SIGNING once the autopilot is known, and again every 2 s until its frames are signed
      // (nothing acknowledges it, and a datagram can be lost).
      if (autopilot && (!last_sent_at || now >= *last_sent_at + std::chrono::seconds(2))) {
        mavlink::SetupSigning setup;
        setup.target_system = autopilot->system_id;
        setup.target_component = autopilot->component_id;
        setup.secret_key = key;
        setup.initial_timestamp = mavlink::signing_timestamp_now();
        if (!sent_at)
          std::fprintf(stderr, "sending SETUP_SIGNING to system %u component %u on %s\n", autopilot->system_id,
                       autopilot->component_id, link->describe().c_str());
        link->send(ground_station.encode(setup));
        if (!sent_at) sent_at = now;
        last_sent_at = now;
      }
      const std::size_t n = link->receive(buffer, std::chrono::milliseconds(100));
      for (const mavlink::Frame& f : parser.feed(std::span(buffer.data(), n))) {
        if (!autopilot) {
          if (f.is<mavlink::Heartbeat>() && f.as<mavlink::Heartbeat>().autopilot != mavlink::mav::autopilot_invalid)
            autopilot = mavlink::Sender{f.system_id, f.component_id};
          continue;
        }
        if (f.system_id != autopilot->system_id || !sent_at) continue;
        if (!f.is_signed())
          ++unsigned_frames;
        else if (mavlink::signature_matches(f, key))
          ++verified;
        else
          ++other_key;
      }
    }
  } catch (const Error& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return kRunFailed;
  }
  if (!autopilot) {
    std::fprintf(stderr, "%s: no autopilot heartbeat on %s within %g s\n", name, args.connection.c_str(),
                 args.timeout_s);
    return kRunFailed;
  }
  if (verified == 0) {
    std::fprintf(stderr,
                 "%s: SETUP_SIGNING sent, but no frame of system %u came signed with this key within %g s (%llu "
                 "unsigned, %llu signed with another key). PX4 takes it only over USB, ArduPilot only with "
                 "MAVLink 2 on that port (docs/field.md).\n",
                 name, autopilot->system_id, args.timeout_s, static_cast<unsigned long long>(unsigned_frames),
                 static_cast<unsigned long long>(other_key));
    return kRunFailed;
  }
  std::fprintf(stderr, "the autopilot (system %u) signs with this key: give the link's nodes signing_key_file: %s\n",
               autopilot->system_id, args.key_file.c_str());
  return kOk;
}

}  // namespace kestrel::cli

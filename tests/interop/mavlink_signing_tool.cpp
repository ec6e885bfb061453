// kestrel's side of the MAVLink signing interop test (check_mavlink_signing.sh):
//   mavlink_signing_tool check NODE.json      node-mavlink's signed frames: does kestrel find each
//                                             signature right, and does kestrel, decoding the
//                                             message and signing it again with the same ids,
//                                             link id and timestamp, give the same bytes?
//   mavlink_signing_tool write OUT.json KEY   kestrel's own signed frames, for node-mavlink to check
#include <cstdio>
#include <fstream>
#include <kestrel/error.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "kestrel/mavlink/frame_parser.hpp"
#include "kestrel/mavlink/messages.hpp"
#include "kestrel/mavlink/signing.hpp"

using namespace kestrel::mavlink;
using nlohmann::json;

namespace {

std::vector<std::uint8_t> from_hex(const std::string& hex) {
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2)
    out.push_back(static_cast<std::uint8_t>(std::stoi(hex.substr(i, 2), nullptr, 16)));
  return out;
}

SigningKey key_of(const std::string& hex) {
  const std::vector<std::uint8_t> text(hex.begin(), hex.end());
  return parse_signing_key(text, "key");
}

template <class M>
std::vector<std::uint8_t> signed_frame(const M& m, Sender from, std::uint8_t sequence, const SigningKey& key,
                                       std::uint8_t link_id, SigningTimestamp timestamp) {
  std::vector<std::uint8_t> frame = encode_v2(M::definition(), &m, from, sequence, incompat_signed);
  append_signature(frame, key, link_id, timestamp);
  return frame;
}

// The frame kestrel builds from the message `f` carries, with `f`'s ids, link id and timestamp.
template <class M>
std::vector<std::uint8_t> again(const Frame& f, const SigningKey& key) {
  return signed_frame(f.as<M>(), {f.system_id, f.component_id}, f.sequence, key, f.link_id(), f.signature_timestamp());
}

std::vector<std::uint8_t> sign_again(const Frame& f, const SigningKey& key) {
  if (f.is<Heartbeat>()) return again<Heartbeat>(f, key);
  if (f.is<CommandLong>()) return again<CommandLong>(f, key);
  if (f.is<SetPositionTargetLocalNed>()) return again<SetPositionTargetLocalNed>(f, key);
  if (f.is<AttitudeQuaternion>()) return again<AttitudeQuaternion>(f, key);
  if (f.is<SetupSigning>()) return again<SetupSigning>(f, key);
  throw kestrel::Error("no re-encoding for message id " + std::to_string(f.message_id));
}

int check(const std::string& path) {
  const json in = json::parse(std::ifstream(path));
  const SigningKey key = key_of(in.at("key"));
  json verdicts = json::array();
  for (const json& entry : in.at("frames")) {
    const std::string hex = entry.at("hex");
    FrameParser parser;
    const auto frames = parser.feed(from_hex(hex));
    if (frames.size() != 1) throw kestrel::Error(entry.at("name").get<std::string>() + ": not one frame");
    const Frame& f = frames.front();
    verdicts.push_back({{"name", find_definition(f.message_id)->name()},
                        {"signed", f.is_signed()},
                        {"matches", signature_matches(f, key)},
                        {"same_bytes", to_hex(sign_again(f, key)) == hex},
                        {"link_id", f.link_id()},
                        {"timestamp", f.signature_timestamp()}});
  }
  std::printf("%s\n", verdicts.dump(1).c_str());
  return 0;
}

int write(const std::string& path, const std::string& key_hex) {
  const SigningKey key = key_of(key_hex);
  // Timestamps in whole milliseconds: node-mavlink signs with a millisecond time.
  const SigningTimestamp t0 = 37'630'800'000'000 + 5'000'000;
  json frames = json::array();
  const auto add = [&](const auto& m, Sender from, std::uint8_t sequence, std::uint8_t link_id, int i) {
    const SigningTimestamp t = t0 + 100 * static_cast<SigningTimestamp>(i);
    frames.push_back({{"name", std::decay_t<decltype(m)>::definition().name()},
                      {"hex", to_hex(signed_frame(m, from, sequence, key, link_id, t))}});
  };
  Heartbeat hb;
  hb.type = mav::type_onboard_controller;
  hb.autopilot = mav::autopilot_invalid;
  hb.system_status = mav::state_active;
  add(hb, {1, mav::comp_onboard_computer}, 4, 0, 0);
  CommandLong fire;
  fire.target_system = 1;
  fire.target_component = 1;
  fire.command = mav::cmd_do_set_servo;
  fire.param1 = 9;
  fire.param2 = 1900;
  add(fire, {1, mav::comp_onboard_computer}, 5, 0, 1);
  SetPositionTargetLocalNed sp;
  sp.time_boot_ms = 98765;
  sp.target_system = 1;
  sp.target_component = 1;
  sp.type_mask = 0x0DC0;
  sp.x = -4.5f;
  sp.y = 3.25f;
  sp.z = -2.0f;
  sp.vx = 1.0f;
  sp.yaw = -0.75f;
  add(sp, {1, mav::comp_onboard_computer}, 6, 3, 2);
  AttitudeQuaternion att;
  att.time_boot_ms = 7;
  att.q1 = 0.0f;
  att.q2 = 1.0f;
  att.yawspeed = -0.5f;
  add(att, {1, mav::comp_autopilot1}, 200, 0, 3);
  SetupSigning setup;
  setup.target_system = 1;
  setup.target_component = 1;
  setup.secret_key = key;
  setup.initial_timestamp = t0;
  add(setup, {255, 190}, 1, 1, 4);
  std::ofstream(path) << json{{"key", key_hex}, {"frames", frames}}.dump(1) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "check" && argc == 3) return check(argv[2]);
    if (mode == "write" && argc == 4) return write(argv[2], argv[3]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mavlink_signing_tool: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr, "usage: mavlink_signing_tool check NODE.json | write OUT.json KEY_HEX\n");
  return 2;
}

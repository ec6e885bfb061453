#pragma once
// The signing parameters as every end of a MAVLink link declares them (INTERFACES.md: `signing`,
// `signing_key_file`): mavlink_source, mavlink_sink and sim_autopilot. The key is read when the
// node starts, so a missing or exposed key file stops the graph with the node's name.
#include <kestrel/config_spec.hpp>
#include <kestrel/report_section.hpp>
#include <memory>
#include <string>

#include "kestrel/mavlink/signing.hpp"

namespace kestrel::mavlink {

struct SigningConfig {
  SigningMode mode = SigningMode::off;
  std::string key_file;
  std::int64_t link_id = 0;
};

template <class Config>
void declare_signing(ConfigSpec<Config>& c, SigningConfig Config::*group) {
  c.choice("signing", group, &SigningConfig::mode,
           {{"off", SigningMode::off}, {"sign", SigningMode::sign}, {"require", SigningMode::require}})
      .describe(
          "MAVLink 2 signing: off; sign (frames out signed, signed frames in checked, unsigned ones accepted); "
          "require (only correctly signed, fresh frames accepted: the others are dropped and counted)");
  c.param("signing_key_file", group, &SigningConfig::key_file)
      .describe(
          "the shared secret: a file of 32 bytes or 64 hexadecimal characters, readable by its owner only "
          "(kestrel mavlink keygen FILE)");
  c.param("signing_link_id", group, &SigningConfig::link_id)
      .range(0, 255)
      .describe("the link id this end signs with (one per channel of a vehicle)");
  c.rule("signing other than off needs a signing_key_file", {"signing", "signing_key_file"},
         [group](const Config& config) {
           const SigningConfig& s = config.*group;
           return s.mode == SigningMode::off || !s.key_file.empty();
         });
}

/// The signing state `config` asks for: nullptr when off. Throws kestrel::Error (the key file).
inline std::shared_ptr<Signing> make_signing(const SigningConfig& config) {
  if (config.mode == SigningMode::off) return nullptr;
  return std::make_shared<Signing>(config.mode, load_signing_key(config.key_file),
                                   static_cast<std::uint8_t>(config.link_id));
}

inline const char* signing_mode_name(SigningMode mode) {
  switch (mode) {
    case SigningMode::off:
      return "off";
    case SigningMode::sign:
      return "sign";
    case SigningMode::require:
      return "require";
  }
  return "off";
}

/// The report keys every end of a link gives: its mode and what its signatures let in or kept out.
inline ReportSection& report_signing(ReportSection& section, SigningMode mode, const SigningCounts& counts) {
  return section.info("signing", signing_mode_name(mode))
      .quantity("signed_frames", counts.signed_frames, "frames")
      .metric("unsigned_frames", counts.unsigned_frames, "frames", Better::lower)
      .metric("bad_signature", counts.bad_signature, "frames", Better::lower)
      .metric("replayed_frames", counts.replayed, "frames", Better::lower);
}

}  // namespace kestrel::mavlink

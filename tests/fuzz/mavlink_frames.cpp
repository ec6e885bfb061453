// Fuzz target: the MAVLink frame parser on bytes from a link. The first byte chooses where the
// rest is cut into two feeds. Whatever the bytes: no crash and no read out of bounds; the frames
// are the same however the stream is cut; each frame holds a payload of at most 255 bytes that
// decodes and prints; a frame re-encoded from what it decoded to parses back to the same message;
// judging signatures never fails on any frame, and a frame signed again with a key verifies.
#include <cstdint>
#include <span>
#include <vector>

#include "kestrel/mavlink/frame_parser.hpp"
#include "kestrel/mavlink/message_text.hpp"
#include "kestrel/mavlink/messages.hpp"
#include "kestrel/mavlink/signing.hpp"

using namespace kestrel::mavlink;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::span<const std::uint8_t> stream(data + 1, size - 1);
  const std::size_t cut = stream.empty() ? 0 : data[0] % (stream.size() + 1);

  FrameParser whole;
  const std::vector<Frame> frames = whole.feed(stream);
  FrameParser split;
  std::vector<Frame> pieces = split.feed(stream.first(cut));
  for (Frame& f : split.feed(stream.subspan(cut))) pieces.push_back(std::move(f));
  if (pieces.size() != frames.size()) __builtin_trap();

  static const SigningKey key = [] {
    SigningKey k{};
    k.fill(0x42);
    return k;
  }();
  Signing require(SigningMode::require, key, 0, [] { return SigningTimestamp{1'000'000'000}; });
  for (const Frame& f : frames) (void)require.admit(f);  // whatever the bytes, a verdict
  const SigningCounts judged = require.counts();
  if (judged.signed_frames + judged.unsigned_frames + judged.bad_signature + judged.replayed != frames.size())
    __builtin_trap();

  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Frame& f = frames[i];
    if (f.payload != pieces[i].payload || f.message_id != pieces[i].message_id) __builtin_trap();
    if (f.payload.size() > 255) __builtin_trap();
    const MessageDefinition* d = find_definition(f.message_id);
    if (d == nullptr) __builtin_trap();  // the parser delivers only what it could check
    if (message_text(*d, f.payload).empty()) __builtin_trap();
    if (f.is<Heartbeat>()) {
      const Heartbeat h = f.as<Heartbeat>();
      FrameParser again;
      const auto back = again.feed(encode_v2(Heartbeat::definition(), &h, {f.system_id, f.component_id}, f.sequence));
      if (back.size() != 1 || back[0].as<Heartbeat>().custom_mode != h.custom_mode) __builtin_trap();
      std::vector<std::uint8_t> resigned =
          encode_v2(Heartbeat::definition(), &h, {f.system_id, f.component_id}, f.sequence, incompat_signed);
      append_signature(resigned, key, f.link_id(), f.signature_timestamp());
      const auto verified = again.feed(resigned);
      if (verified.size() != 1 || !signature_matches(verified[0], key)) __builtin_trap();
    }
  }
  return 0;
}

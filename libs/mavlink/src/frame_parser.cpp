#include "kestrel/mavlink/frame_parser.hpp"

#include <algorithm>

#include "kestrel/mavlink/messages.hpp"

namespace kestrel::mavlink {

namespace {

bool is_magic(std::uint8_t b) { return b == magic_v2 || b == magic_v1; }

enum class Candidate { need_more, bad_flags, unknown_id, bad_checksum, good };

struct Probe {
  Candidate what = Candidate::need_more;
  std::size_t header = 0;
  std::size_t total = 0;
  std::uint32_t id = 0;
};

// What the bytes from `at` (a magic byte) hold, reading nothing past `size`.
Probe probe(const std::uint8_t* data, std::size_t size, std::size_t at, FrameParser::Lookup lookup) {
  Probe p;
  const bool v2 = data[at] == magic_v2;
  p.header = v2 ? header_v2 : header_v1;
  if (size - at < p.header) return p;
  const std::uint8_t length = data[at + 1];
  const std::uint8_t incompat = v2 ? data[at + 2] : 0;
  if ((incompat & ~incompat_signed) != 0) {
    p.what = Candidate::bad_flags;
    return p;
  }
  p.total = p.header + length + checksum_size + ((incompat & incompat_signed) ? signature_size : 0);
  p.id = v2 ? static_cast<std::uint32_t>(data[at + 7]) | (static_cast<std::uint32_t>(data[at + 8]) << 8) |
                  (static_cast<std::uint32_t>(data[at + 9]) << 16)
            : data[at + 5];
  if (size - at < p.total) return p;
  const MessageDefinition* definition = lookup(p.id);
  if (definition == nullptr) {
    p.what = Candidate::unknown_id;
    return p;
  }
  const std::size_t crc_at = at + p.header + length;
  const std::uint16_t expected =
      frame_checksum(std::span(data + at + 1, p.header - 1 + length), definition->crc_extra());
  const std::uint16_t received = static_cast<std::uint16_t>(data[crc_at] | (data[crc_at + 1] << 8));
  p.what = expected == received ? Candidate::good : Candidate::bad_checksum;
  return p;
}

// Whether a frame that checks out starts inside (at, at + total); need_more if that cannot be
// told yet.
Candidate covers_a_good_frame(const std::uint8_t* data, std::size_t size, std::size_t at, std::size_t total,
                              FrameParser::Lookup lookup) {
  bool undecided = false;
  for (std::size_t p = at + 1; p < at + total; ++p) {
    if (!is_magic(data[p])) continue;
    const Candidate c = probe(data, size, p, lookup).what;
    if (c == Candidate::good) return Candidate::good;
    if (c == Candidate::need_more) undecided = true;
  }
  return undecided ? Candidate::need_more : Candidate::unknown_id;
}

}  // namespace

FrameParser::FrameParser(Lookup lookup) : lookup_(lookup ? lookup : &find_definition) {}

std::vector<Frame> FrameParser::feed(std::span<const std::uint8_t> bytes) {
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
  std::vector<Frame> frames;
  const std::uint8_t* const data = buffer_.data();
  const std::size_t size = buffer_.size();
  std::size_t at = 0;
  const auto skip_byte = [&] {
    ++counts_.bytes_skipped;
    ++at;
  };
  while (at < size) {
    if (!is_magic(data[at])) {
      skip_byte();
      continue;
    }
    const Probe p = probe(data, size, at, lookup_);
    if (p.what == Candidate::need_more) break;
    if (p.what == Candidate::bad_flags) {
      ++counts_.bad_flags;
      skip_byte();
      continue;
    }
    if (p.what == Candidate::bad_checksum) {
      ++counts_.bad_checksum;
      skip_byte();
      continue;
    }
    if (p.what == Candidate::unknown_id) {
      // Unverifiable: stepped over by its length, unless a frame that checks out starts inside
      // it; then it was noise posing as a header.
      const Candidate inside = covers_a_good_frame(data, size, at, p.total, lookup_);
      if (inside == Candidate::need_more) break;
      if (inside == Candidate::good) {
        skip_byte();
      } else {
        ++counts_.unknown_id;
        at += p.total;
      }
      continue;
    }
    const bool v2 = data[at] == magic_v2;
    Frame f;
    f.version = v2 ? 2 : 1;
    f.incompat_flags = v2 ? data[at + 2] : 0;
    f.compat_flags = v2 ? data[at + 3] : 0;
    f.sequence = data[at + (v2 ? 4 : 2)];
    f.system_id = data[at + (v2 ? 5 : 3)];
    f.component_id = data[at + (v2 ? 6 : 4)];
    f.message_id = p.id;
    const std::size_t payload_end = at + p.header + data[at + 1];
    f.payload.assign(data + at + p.header, data + payload_end);
    f.checksum = static_cast<std::uint16_t>(data[payload_end] | (data[payload_end + 1] << 8));
    if (f.is_signed()) std::copy(data + payload_end + checksum_size, data + at + p.total, f.signature.begin());
    ++counts_.frames;
    if (!v2) ++counts_.v1_frames;
    if (f.is_signed()) ++counts_.signed_frames;
    frames.push_back(std::move(f));
    at += p.total;
  }
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(at));
  return frames;
}

}  // namespace kestrel::mavlink

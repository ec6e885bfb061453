#include "kestrel/dds/cdr_padding.hpp"

namespace kestrel::dds {

std::vector<std::uint8_t> pad_cdr(std::span<const std::uint8_t> cdr) {
  std::vector<std::uint8_t> out(cdr.begin(), cdr.end());
  const std::size_t pad = (4 - cdr.size() % 4) % 4;
  if (pad == 0 || cdr.size() < 4) return out;
  out.resize(cdr.size() + pad, 0);
  out[3] = static_cast<std::uint8_t>((out[3] & ~3u) | pad);
  return out;
}

void strip_cdr_padding(std::vector<std::uint8_t>& cdr) {
  if (cdr.size() < 4) return;
  const std::size_t pad = cdr[3] & 3u;
  if (pad == 0 || cdr.size() < 4 + pad) return;
  cdr.resize(cdr.size() - pad);
  cdr[3] = static_cast<std::uint8_t>(cdr[3] & ~3u);
}

}  // namespace kestrel::dds

#include "kestrel/mavlink/message_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace kestrel::mavlink {

namespace {

std::string element_text(BaseType type, const std::uint8_t* at) {
  switch (type) {
    case BaseType::uint8:
      return std::to_string(detail::get<std::uint8_t>(at));
    case BaseType::int8:
      return std::to_string(detail::get<std::int8_t>(at));
    case BaseType::character:
      return std::to_string(detail::get<std::uint8_t>(at));
    case BaseType::uint16:
      return std::to_string(detail::get<std::uint16_t>(at));
    case BaseType::int16:
      return std::to_string(detail::get<std::int16_t>(at));
    case BaseType::uint32:
      return std::to_string(detail::get<std::uint32_t>(at));
    case BaseType::int32:
      return std::to_string(detail::get<std::int32_t>(at));
    case BaseType::uint64:
      return std::to_string(detail::get<std::uint64_t>(at));
    case BaseType::int64:
      return std::to_string(detail::get<std::int64_t>(at));
    case BaseType::float32:
      return fmt::format("{:g}", detail::get<float>(at));
    case BaseType::float64:
      return fmt::format("{:g}", detail::get<double>(at));
  }
  return "?";
}

// A char array is text up to its first NUL, quoted, with anything unprintable escaped.
std::string text_field(const std::uint8_t* at, std::size_t n) {
  std::string out = "\"";
  for (std::size_t i = 0; i < n && at[i] != 0; ++i) {
    const char c = static_cast<char>(at[i]);
    if (c == '"' || c == '\\')
      out += fmt::format("\\{}", c);
    else if (at[i] >= 0x20 && at[i] < 0x7F)
      out += c;
    else
      out += fmt::format("\\x{:02x}", at[i]);
  }
  return out + "\"";
}

}  // namespace

std::string message_text(const MessageDefinition& definition, std::span<const std::uint8_t> payload) {
  std::vector<std::uint8_t> full(definition.length(), 0);
  std::copy_n(payload.begin(), std::min(payload.size(), full.size()), full.begin());
  std::string line(definition.name());
  for (const FieldDefinition& f : definition.fields()) {
    const auto w = std::find_if(definition.wire().begin(), definition.wire().end(),
                                [&](const WireField& x) { return x.field == &f; });
    const std::uint8_t* at = full.data() + w->offset;
    line += ' ';
    line += f.name;
    line += '=';
    if (f.array_length == 0) {
      line += element_text(f.type, at);
    } else if (f.type == BaseType::character) {
      line += text_field(at, f.array_length);
    } else {
      line += '[';
      for (std::size_t i = 0; i < f.array_length; ++i) {
        if (i) line += ',';
        line += element_text(f.type, at + i * f.element_size());
      }
      line += ']';
    }
  }
  return line;
}

}  // namespace kestrel::mavlink

#include "kestrel/mavlink/message_definition.hpp"

#include <algorithm>

#include "kestrel/mavlink/crc16.hpp"

namespace kestrel::mavlink {

std::string_view c_name(BaseType t) {
  switch (t) {
    case BaseType::uint8:
      return "uint8_t";
    case BaseType::int8:
      return "int8_t";
    case BaseType::character:
      return "char";
    case BaseType::uint16:
      return "uint16_t";
    case BaseType::int16:
      return "int16_t";
    case BaseType::uint32:
      return "uint32_t";
    case BaseType::int32:
      return "int32_t";
    case BaseType::float32:
      return "float";
    case BaseType::uint64:
      return "uint64_t";
    case BaseType::int64:
      return "int64_t";
    case BaseType::float64:
      return "double";
  }
  return "?";
}

std::uint8_t compute_crc_extra(std::string_view name, const std::vector<WireField>& wire) {
  std::uint16_t crc = crc16_accumulate(name, crc16_initial);
  crc = crc16_accumulate(' ', crc);
  for (const WireField& w : wire) {
    const FieldDefinition& f = *w.field;
    if (f.part == FieldPart::extension) continue;
    crc = crc16_accumulate(c_name(f.type), crc);
    crc = crc16_accumulate(' ', crc);
    crc = crc16_accumulate(f.name, crc);
    crc = crc16_accumulate(' ', crc);
    if (f.array_length != 0) crc = crc16_accumulate(static_cast<std::uint8_t>(f.array_length), crc);
  }
  return static_cast<std::uint8_t>((crc & 0xFF) ^ (crc >> 8));
}

MessageDefinition::MessageDefinition(std::uint32_t id, std::string_view name, std::vector<FieldDefinition> xml_fields)
    : id_(id), name_(name), fields_(std::move(xml_fields)) {
  std::vector<const FieldDefinition*> base, extensions;
  for (const FieldDefinition& f : fields_) (f.part == FieldPart::base ? base : extensions).push_back(&f);
  std::stable_sort(base.begin(), base.end(), [](const FieldDefinition* a, const FieldDefinition* b) {
    return a->element_size() > b->element_size();
  });
  std::size_t offset = 0;
  for (const FieldDefinition* f : base) {
    wire_.push_back({f, offset});
    offset += f->size();
  }
  min_length_ = offset;
  for (const FieldDefinition* f : extensions) {
    wire_.push_back({f, offset});
    offset += f->size();
  }
  length_ = offset;
  crc_extra_ = compute_crc_extra(name_, wire_);
}

std::vector<std::uint8_t> MessageDefinition::write(const void* message) const {
  std::vector<std::uint8_t> payload(length_, 0);
  for (const WireField& w : wire_) w.field->write(message, payload.data() + w.offset);
  return payload;
}

void MessageDefinition::read(void* message, std::span<const std::uint8_t> payload) const {
  std::vector<std::uint8_t> full(length_, 0);
  std::copy_n(payload.begin(), std::min(payload.size(), length_), full.begin());
  for (const WireField& w : wire_) w.field->read(message, full.data() + w.offset);
}

}  // namespace kestrel::mavlink

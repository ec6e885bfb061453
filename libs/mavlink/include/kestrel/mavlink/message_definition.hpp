#pragma once
// A MAVLink message's definition: its id, name and fields in XML order, and what the protocol
// derives from them: the wire order (base fields sorted by element size, largest first, stable;
// extensions after them in XML order), each field's offset, the minimum and full payload lengths
// and CRC_EXTRA, the checksum seed that catches two ends built from different definitions.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kestrel/mavlink/field_definition.hpp"

namespace kestrel::mavlink {

struct WireField {
  const FieldDefinition* field;
  std::size_t offset;
};

class MessageDefinition {
 public:
  MessageDefinition(std::uint32_t id, std::string_view name, std::vector<FieldDefinition> xml_fields);
  MessageDefinition(const MessageDefinition&) = delete;
  MessageDefinition& operator=(const MessageDefinition&) = delete;

  std::uint32_t id() const { return id_; }
  std::string_view name() const { return name_; }
  const std::vector<FieldDefinition>& fields() const { return fields_; }  ///< XML order
  const std::vector<WireField>& wire() const { return wire_; }            ///< payload order
  std::size_t min_length() const { return min_length_; }                  ///< base fields only
  std::size_t length() const { return length_; }                          ///< with the extensions
  std::uint8_t crc_extra() const { return crc_extra_; }

  /// The full payload (length() bytes, untruncated) of a message struct of this definition.
  std::vector<std::uint8_t> write(const void* message) const;
  /// Fills a message struct from a received payload: bytes past its end read as zero (MAVLink 2
  /// truncation, missing extensions); bytes past length() (a newer definition) are ignored.
  void read(void* message, std::span<const std::uint8_t> payload) const;

 private:
  std::uint32_t id_;
  std::string name_;
  std::vector<FieldDefinition> fields_;
  std::vector<WireField> wire_;
  std::size_t min_length_ = 0;
  std::size_t length_ = 0;
  std::uint8_t crc_extra_ = 0;
};

/// CRC_EXTRA as the protocol defines it: CRC-16/MCRF4XX over "NAME ", then for each base field in
/// wire order "TYPE NAME " and, for an array, one byte of its length; the two bytes XORed.
std::uint8_t compute_crc_extra(std::string_view name, const std::vector<WireField>& wire);

}  // namespace kestrel::mavlink

#pragma once
// One field of a MAVLink message as common.xml declares it: its C type, name, array length and
// whether it is an extension, bound to the member of the C++ struct that holds it. The message's
// wire layout and CRC_EXTRA are computed from these (message_definition.hpp).
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

namespace kestrel::mavlink {

enum class BaseType : std::uint8_t {
  uint8,
  int8,
  character,
  uint16,
  int16,
  uint32,
  int32,
  float32,
  uint64,
  int64,
  float64
};

/// Bytes of one element on the wire.
constexpr std::size_t size_of(BaseType t) {
  switch (t) {
    case BaseType::uint8:
    case BaseType::int8:
    case BaseType::character:
      return 1;
    case BaseType::uint16:
    case BaseType::int16:
      return 2;
    case BaseType::uint32:
    case BaseType::int32:
    case BaseType::float32:
      return 4;
    default:
      return 8;
  }
}

/// The type's name as CRC_EXTRA hashes it ("uint8_t", "float", "char", ...).
std::string_view c_name(BaseType t);

/// Extension fields (after <extensions/> in the XML) keep XML order, follow the others on the
/// wire, stay out of CRC_EXTRA and may be truncated away.
enum class FieldPart : std::uint8_t { base, extension };

struct FieldDefinition {
  std::string_view name;
  BaseType type{};
  std::size_t array_length = 0;  ///< 0 for a scalar
  FieldPart part = FieldPart::base;
  void (*write)(const void* message, std::uint8_t* at) = nullptr;  ///< little-endian, into the payload
  void (*read)(void* message, const std::uint8_t* at) = nullptr;

  std::size_t element_size() const { return size_of(type); }
  std::size_t size() const { return size_of(type) * (array_length == 0 ? 1 : array_length); }
};

namespace detail {

template <class T>
struct base_type_of;
template <>
struct base_type_of<std::uint8_t> : std::integral_constant<BaseType, BaseType::uint8> {};
template <>
struct base_type_of<std::int8_t> : std::integral_constant<BaseType, BaseType::int8> {};
template <>
struct base_type_of<char> : std::integral_constant<BaseType, BaseType::character> {};
template <>
struct base_type_of<std::uint16_t> : std::integral_constant<BaseType, BaseType::uint16> {};
template <>
struct base_type_of<std::int16_t> : std::integral_constant<BaseType, BaseType::int16> {};
template <>
struct base_type_of<std::uint32_t> : std::integral_constant<BaseType, BaseType::uint32> {};
template <>
struct base_type_of<std::int32_t> : std::integral_constant<BaseType, BaseType::int32> {};
template <>
struct base_type_of<float> : std::integral_constant<BaseType, BaseType::float32> {};
template <>
struct base_type_of<std::uint64_t> : std::integral_constant<BaseType, BaseType::uint64> {};
template <>
struct base_type_of<std::int64_t> : std::integral_constant<BaseType, BaseType::int64> {};
template <>
struct base_type_of<double> : std::integral_constant<BaseType, BaseType::float64> {};

template <class T>
struct elements {
  using type = T;
  static constexpr std::size_t count = 0;
};
template <class E, std::size_t N>
struct elements<std::array<E, N>> {
  using type = E;
  static constexpr std::size_t count = N;
};

template <class>
struct member_of;
template <class M, class T>
struct member_of<T M::*> {
  using message = M;
  using type = T;
};

template <class T>
using bits_of =
    std::conditional_t<sizeof(T) == 1, std::uint8_t,
                       std::conditional_t<sizeof(T) == 2, std::uint16_t,
                                          std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;

template <class T>
void put(std::uint8_t* at, T value) {
  auto bits = std::bit_cast<bits_of<T>>(value);
  for (std::size_t i = 0; i < sizeof(T); ++i) at[i] = static_cast<std::uint8_t>(bits >> (8 * i));
}

template <class T>
T get(const std::uint8_t* at) {
  bits_of<T> bits = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i) bits = static_cast<bits_of<T>>(bits | (bits_of<T>(at[i]) << (8 * i)));
  return std::bit_cast<T>(bits);
}

template <class T>
void put_value(std::uint8_t* at, const T& v) {
  if constexpr (elements<T>::count == 0) {
    put(at, v);
  } else {
    using E = typename elements<T>::type;
    for (std::size_t i = 0; i < v.size(); ++i) put(at + i * sizeof(E), v[i]);
  }
}

template <class T>
void get_value(const std::uint8_t* at, T& v) {
  if constexpr (elements<T>::count == 0) {
    v = get<T>(at);
  } else {
    using E = typename elements<T>::type;
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = get<E>(at + i * sizeof(E));
  }
}

}  // namespace detail

/// The field bound to `Member` (a scalar, or a std::array for an XML array), named as in the XML.
template <auto Member>
FieldDefinition field(std::string_view name, FieldPart part = FieldPart::base) {
  using M = typename detail::member_of<decltype(Member)>::message;
  using T = typename detail::member_of<decltype(Member)>::type;
  using E = typename detail::elements<T>::type;
  return FieldDefinition{
      name,
      detail::base_type_of<E>::value,
      detail::elements<T>::count,
      part,
      [](const void* m, std::uint8_t* at) { detail::put_value(at, static_cast<const M*>(m)->*Member); },
      [](void* m, const std::uint8_t* at) { detail::get_value(at, static_cast<M*>(m)->*Member); }};
}

}  // namespace kestrel::mavlink

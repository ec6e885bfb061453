#pragma once
// Message types and the envelope that carries them between nodes.
//
// A message is any C++ type that has been given a stable name with KESTREL_MESSAGE. Names, not
// RTTI, identify types across shared-library boundaries. Messages travel as
// std::shared_ptr<const T>: an edge never copies the payload, and nobody can change it once it
// is published.
#include <concepts>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "kestrel/time.hpp"

namespace kestrel {

/// Specialise through KESTREL_MESSAGE(T, "name", "description"), never by hand.
template <class T>
struct MessageTraits;

template <class T>
concept MessageType = requires {
  { MessageTraits<T>::name } -> std::convertible_to<std::string_view>;
  { MessageTraits<T>::description } -> std::convertible_to<std::string_view>;
};

/// The wildcard port type: an input of type AnyMessage accepts every message type.
struct AnyMessage {};

/// A message type as the registry and `kestrel inspect` see it.
struct MessageInfo {
  std::string name;
  std::string description;
};

template <MessageType T>
MessageInfo message_info() {
  return {std::string(MessageTraits<T>::name), std::string(MessageTraits<T>::description)};
}

/// One published message: the immutable payload, its type name, when it was published and a
/// per-run sequence number that gives every message a total order.
struct Envelope {
  std::shared_ptr<const void> payload;
  std::string_view type;
  Time published_at{0};
  std::uint64_t sequence = 0;

  explicit operator bool() const { return payload != nullptr; }
};

}  // namespace kestrel

/// Gives message type T its stable, globally unique name. Use at global namespace scope, in the
/// header that defines T, e.g. KESTREL_MESSAGE(kestrel::msg::PointCloud, "kestrel.PointCloud",
/// "...").
#define KESTREL_MESSAGE(T, NAME, DESCRIPTION)                    \
  template <>                                                    \
  struct kestrel::MessageTraits<T> {                             \
    static constexpr std::string_view name = NAME;               \
    static constexpr std::string_view description = DESCRIPTION; \
  }

KESTREL_MESSAGE(kestrel::AnyMessage, "*", "any message type");

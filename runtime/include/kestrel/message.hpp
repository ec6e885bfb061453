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
#include <vector>

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

/// One field of a message as its header declares it (KESTREL_MESSAGE_FIELDS). Fields of nested
/// elements are named by their path: `items[].position`.
struct MessageFieldDecl {
  std::string_view name;
  std::string_view type;
  std::string_view unit;   ///< SI unit, "" for none (a count, a flag, a name)
  std::string_view frame;  ///< "world", "body", "camera", "in frame" (the message's `frame`), or ""
  std::string_view description;
};

/// Specialise through KESTREL_MESSAGE_FIELDS(T, {...}, ...), never by hand. Optional: a message
/// without it is still a message, but `kestrel inspect` cannot list its fields.
template <class T>
struct MessageFields;

/// A field as the registry keeps it: owned strings, valid after the declaring plugin is unloaded.
struct MessageField {
  std::string name, type, unit, frame, description;
};

/// A message type as the registry and `kestrel inspect` see it.
struct MessageInfo {
  std::string name;
  std::string description;
  std::vector<MessageField> fields;  ///< empty when the type declares none
};

template <MessageType T>
MessageInfo message_info() {
  MessageInfo info{std::string(MessageTraits<T>::name), std::string(MessageTraits<T>::description), {}};
  if constexpr (requires { MessageFields<T>::fields; })
    for (const MessageFieldDecl& f : MessageFields<T>::fields)
      info.fields.push_back({std::string(f.name), std::string(f.type), std::string(f.unit), std::string(f.frame),
                             std::string(f.description)});
  return info;
}

/// One published message: the immutable payload, its type name, when it was published, a
/// per-run sequence number that gives every message a total order, and the output it came from.
struct Envelope {
  std::shared_ptr<const void> payload;
  std::string_view type;
  Time published_at{0};
  std::uint64_t sequence = 0;
  std::string_view source_node;  ///< id of the node that published it; valid for the whole run
  std::string_view source_port;  ///< the output it was published on

  explicit operator bool() const { return payload != nullptr; }
};

/// The topic of an output, "/NODE/PORT": how taps select outputs, and the channel name MCAP
/// recordings and the live view give it (ROS 2 topic names allow no dots).
inline std::string output_topic(std::string_view node, std::string_view port) {
  std::string topic;
  topic.reserve(node.size() + port.size() + 2);
  topic.append("/").append(node).append("/").append(port);
  return topic;
}

/// The topic of the output a message was published on.
inline std::string topic_of(const Envelope& e) { return output_topic(e.source_node, e.source_port); }

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

/// Declares the fields of message type T, in the header that defines T, after KESTREL_MESSAGE:
/// KESTREL_MESSAGE_FIELDS(my::Scan, {"stamp", "Time", "ns", "", "capture time"}, ...).
#define KESTREL_MESSAGE_FIELDS(T, ...)                                   \
  template <>                                                            \
  struct kestrel::MessageFields<T> {                                     \
    static constexpr kestrel::MessageFieldDecl fields[] = {__VA_ARGS__}; \
  }

KESTREL_MESSAGE(kestrel::AnyMessage, "*", "any message type");

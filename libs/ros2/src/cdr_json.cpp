#include "kestrel/ros2/cdr_json.hpp"

#include <cmath>

namespace kestrel::ros2 {

namespace {

constexpr int kMaxDepth = 64;  // ROS 2 types do not nest themselves; a deeper schema is malformed

nlohmann::ordered_json number(double v) { return std::isfinite(v) ? nlohmann::ordered_json(v) : nullptr; }

nlohmann::ordered_json primitive(CdrReader& in, const std::string& type) {
  if (type == "bool") return in.boolean();
  if (type == "byte" || type == "char" || type == "uint8") return in.u8();
  if (type == "int8") return in.i8();
  if (type == "int16") return in.i16();
  if (type == "uint16") return in.u16();
  if (type == "int32") return in.i32();
  if (type == "uint32") return in.u32();
  if (type == "int64") return in.i64();
  if (type == "uint64") return in.u64();
  if (type == "float32") return number(in.f32());
  if (type == "float64") return number(in.f64());
  if (type == "string") return in.string();
  if (type == "time" || type == "duration") {  // ROS 1 names: builtin_interfaces Time and Duration
    nlohmann::ordered_json t;
    t["sec"] = in.i32();
    t["nanosec"] = in.u32();
    return t;
  }
  throw CdrError("unsupported primitive type " + type);
}

nlohmann::ordered_json message(CdrReader& in, const MessageSchema& schema, const MessageDefinition& def, int depth);

nlohmann::ordered_json element(CdrReader& in, const MessageSchema& schema, const FieldType& type, int depth) {
  return type.is_message ? message(in, schema, schema.definition(type.name), depth + 1) : primitive(in, type.name);
}

nlohmann::ordered_json message(CdrReader& in, const MessageSchema& schema, const MessageDefinition& def, int depth) {
  if (depth > kMaxDepth) throw CdrError("message " + def.name + " nests deeper than " + std::to_string(kMaxDepth));
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  if (def.fields.empty()) {
    in.u8();  // ROS 2 serializes an empty message as one byte
    return out;
  }
  for (const Field& f : def.fields) {
    const FieldType& t = f.type;
    if (t.array == FieldType::Array::none) {
      out[f.name] = element(in, schema, t, depth);
      continue;
    }
    std::size_t n = t.length;
    if (t.array == FieldType::Array::sequence) {
      const std::size_t size = t.is_message ? 1 : std::max<std::size_t>(1, primitive_size(t.name));
      n = in.sequence_length(size);
      if (t.length > 0 && n > t.length)
        throw CdrError(def.name + "." + f.name + " holds " + std::to_string(n) + " elements, over its bound of " +
                       std::to_string(t.length));
    } else if (n > in.remaining()) {
      throw CdrError(def.name + "." + f.name + ": " + std::to_string(n) + " elements cannot fit the bytes left");
    }
    nlohmann::ordered_json array = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < n; ++i) array.push_back(element(in, schema, t, depth));
    out[f.name] = std::move(array);
  }
  return out;
}

}  // namespace

nlohmann::ordered_json cdr_to_json(const MessageSchema& schema, std::span<const std::uint8_t> cdr) {
  CdrReader in(cdr);
  nlohmann::ordered_json out = message(in, schema, schema.root(), 0);
  // CDR pads a message to a multiple of 4 bytes at most; more left over means another type.
  if (in.remaining() > 3)
    throw CdrError(std::to_string(in.remaining()) + " bytes left after a whole " + schema.root().name);
  return out;
}

}  // namespace kestrel::ros2

#include "kestrel/ros2/ros2msg.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace kestrel::ros2 {

namespace {

const std::map<std::string, std::size_t>& primitives() {
  static const std::map<std::string, std::size_t> sizes = {{"bool", 1},
                                                           {"byte", 1},
                                                           {"char", 1},
                                                           {"int8", 1},
                                                           {"uint8", 1},
                                                           {"int16", 2},
                                                           {"uint16", 2},
                                                           {"int32", 4},
                                                           {"uint32", 4},
                                                           {"int64", 8},
                                                           {"uint64", 8},
                                                           {"float32", 4},
                                                           {"float64", 8},
                                                           {"string", 0},
                                                           {"wstring", 0},
                                                           // ROS 1 names some tools still write
                                                           {"time", 0},
                                                           {"duration", 0}};
  return sizes;
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

bool is_separator(const std::string& line) {
  return line.size() >= 3 && std::all_of(line.begin(), line.end(), [](char c) { return c == '='; });
}

std::size_t parse_size(const std::string& text, const std::string& where) {
  if (text.empty() || !std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); }))
    throw SchemaError(where + ": '" + text + "' is not an array size");
  try {
    return std::stoul(text);
  } catch (const std::exception&) {
    throw SchemaError(where + ": array size '" + text + "' is out of range");
  }
}

FieldType parse_type(std::string text, const std::string& package, const std::string& where) {
  FieldType t;
  const auto bracket = text.find('[');
  if (bracket != std::string::npos) {
    if (text.back() != ']') throw SchemaError(where + ": '" + text + "' has an unclosed '['");
    const std::string inside = text.substr(bracket + 1, text.size() - bracket - 2);
    text = text.substr(0, bracket);
    if (inside.empty()) {
      t.array = FieldType::Array::sequence;
    } else if (inside.rfind("<=", 0) == 0) {
      t.array = FieldType::Array::sequence;
      t.length = parse_size(inside.substr(2), where);
    } else {
      t.array = FieldType::Array::fixed;
      t.length = parse_size(inside, where);
    }
  }
  const auto bound = text.find("<=");  // string<=N
  if (bound != std::string::npos) {
    parse_size(text.substr(bound + 2), where);
    text = text.substr(0, bound);
  }
  if (text.empty()) throw SchemaError(where + ": a field without a type");
  if (text == "wstring") throw SchemaError(where + ": wstring fields are not supported");
  if (primitives().count(text)) {
    t.name = text;
    return t;
  }
  t.is_message = true;
  if (text == "Header") {
    t.name = "std_msgs/Header";
  } else if (text.find('/') == std::string::npos) {
    t.name = package + "/" + text;  // a type of the same package
  } else {
    t.name = MessageSchema::normalise(text);
  }
  return t;
}

MessageDefinition parse_definition(const std::string& name, const std::vector<std::string>& lines,
                                   std::size_t first_line) {
  MessageDefinition def;
  def.name = name;
  const std::string package = name.substr(0, name.find('/'));
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string where = "schema " + name + ", line " + std::to_string(first_line + i);
    std::string line = lines[i];
    const auto hash = line.find('#');
    // A '#' inside a string constant's value is part of it; elsewhere it starts a comment.
    const auto equals = line.find('=');
    if (hash != std::string::npos && (equals == std::string::npos || hash < equals)) line = line.substr(0, hash);
    line = trim(line);
    if (line.empty()) continue;
    std::istringstream words(line);
    std::string type, field;
    words >> type;
    std::getline(words, field);
    field = trim(field);
    if (field.empty()) throw SchemaError(where + ": '" + line + "' has a type but no name");
    const auto eq = field.find('=');
    const bool bounded_string = field.rfind("<=", 0) == 0;  // a space in "string <=5 x" is not valid anyway
    if (eq != std::string::npos && !bounded_string) {
      def.constants.push_back({type, trim(field.substr(0, eq)), trim(field.substr(eq + 1))});
      continue;
    }
    std::string field_name = field.substr(0, field.find_first_of(" \t"));  // the rest is a default value
    if (field_name.empty() ||
        !std::all_of(field_name.begin(), field_name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; }))
      throw SchemaError(where + ": '" + field_name + "' is not a field name");
    def.fields.push_back({field_name, parse_type(type, package, where)});
  }
  return def;
}

}  // namespace

bool is_primitive(const std::string& type) { return primitives().count(type) > 0; }

std::size_t primitive_size(const std::string& type) {
  const auto it = primitives().find(type);
  return it == primitives().end() ? 0 : it->second;
}

std::string MessageSchema::normalise(const std::string& name) {
  const auto first = name.find('/');
  const auto last = name.rfind('/');
  if (first != std::string::npos && first != last) return name.substr(0, first) + name.substr(last);
  return name;
}

MessageSchema::MessageSchema(const std::string& name, const std::string& text) {
  root_ = normalise(name);
  if (root_.find('/') == std::string::npos) throw SchemaError("schema name '" + name + "' is not pkg/msg/Type");
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);

  std::string current = root_;
  std::vector<std::string> body;
  std::size_t body_start = 1;
  const auto flush = [&] {
    definitions_[current] = parse_definition(current, body, body_start);
    body.clear();
  };
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string line = trim(lines[i]);
    if (!is_separator(line)) {
      body.push_back(lines[i]);
      continue;
    }
    flush();
    // The next line names the dependency: "MSG: pkg/Type".
    std::size_t j = i + 1;
    while (j < lines.size() && trim(lines[j]).empty()) ++j;
    if (j == lines.size() || trim(lines[j]).rfind("MSG:", 0) != 0)
      throw SchemaError("schema " + name + ", line " + std::to_string(j + 1) +
                        ": expected 'MSG: pkg/Type' after '==='");
    current = normalise(trim(trim(lines[j]).substr(4)));
    if (current.find('/') == std::string::npos)
      throw SchemaError("schema " + name + ", line " + std::to_string(j + 1) + ": '" + current + "' is not pkg/Type");
    i = j;
    body_start = j + 2;
  }
  flush();

  // Every nested type must be defined.
  for (const auto& [type_name, def] : definitions_)
    for (const Field& f : def.fields)
      if (f.type.is_message && !definitions_.count(f.type.name))
        throw SchemaError("schema " + name + ": " + type_name + "." + f.name + " is a " + f.type.name +
                          ", which the schema does not define");
}

const MessageDefinition& MessageSchema::definition(const std::string& name) const {
  const auto it = definitions_.find(normalise(name));
  if (it == definitions_.end()) throw SchemaError("no definition of " + name + " in schema " + root_);
  return it->second;
}

}  // namespace kestrel::ros2

#pragma once
// Which outputs a tap input takes (TapOptions in ports.hpp): topic patterns, as `kestrel run
// --record FILE --topics PATTERNS` and the recorder's `topics` parameter give them.
#include <kestrel/message.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace kestrel {

class TopicSelection {
 public:
  /// `patterns`: fnmatch globs separated by commas or spaces (`*` crosses '/'); '!' before a
  /// pattern takes what it matches out. `skip_types`: what the default selection leaves out.
  TopicSelection(const std::string& patterns, std::vector<std::string> skip_types);

  /// Whether an output is taken. `connected`: it feeds at least one input other than a tap.
  bool selects(const std::string& topic, std::string_view type, bool connected) const;

 private:
  std::vector<std::string> take_, leave_;
  std::vector<std::string> skip_types_;
};

}  // namespace kestrel

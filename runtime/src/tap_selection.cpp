#include "tap_selection.hpp"

#include <fnmatch.h>

#include <algorithm>

namespace kestrel {

TopicSelection::TopicSelection(const std::string& patterns, std::vector<std::string> skip_types)
    : skip_types_(std::move(skip_types)) {
  std::string word;
  auto flush = [&] {
    if (word.empty()) return;
    if (word[0] == '!') {
      if (word.size() > 1) leave_.push_back(word.substr(1));
    } else {
      take_.push_back(word);
    }
    word.clear();
  };
  for (char c : patterns) {
    if (c == ',' || c == ' ' || c == '\t' || c == '\n')
      flush();
    else
      word += c;
  }
  flush();
}

bool TopicSelection::selects(const std::string& topic, std::string_view type, bool connected) const {
  auto matches = [&](const std::string& pattern) { return fnmatch(pattern.c_str(), topic.c_str(), 0) == 0; };
  if (std::any_of(leave_.begin(), leave_.end(), matches)) return false;
  if (!take_.empty()) return std::any_of(take_.begin(), take_.end(), matches);
  return connected && std::find(skip_types_.begin(), skip_types_.end(), type) == skip_types_.end();
}

}  // namespace kestrel

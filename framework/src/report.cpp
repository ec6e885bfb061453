#include "kestrel/report.hpp"

#include "kestrel/error.hpp"

namespace kestrel {

void Report::set_section(const std::string& owner, const std::string& key, nlohmann::json value, std::string markdown) {
  std::lock_guard lock(mutex_);
  auto it = sections_.find(key);
  if (it != sections_.end() && it->second.owner != owner)
    throw Error("report section '" + key + "' already belongs to node '" + it->second.owner + "'");
  sections_[key] = Section{owner, std::move(value), std::move(markdown)};
}

std::map<std::string, Report::Section> Report::sections() const {
  std::lock_guard lock(mutex_);
  return sections_;
}

}  // namespace kestrel

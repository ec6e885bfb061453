#include "kestrel/report.hpp"

#include <fstream>

#include "kestrel/error.hpp"

namespace kestrel {

void Report::set_section(const std::string& owner, const std::string& key, const ReportSection& section) {
  if (key.empty() || key.find('.') != std::string::npos)
    throw Error("'" + key + "' is not a report section key (one word, no dots)");
  std::lock_guard lock(mutex_);
  auto it = sections_.find(key);
  if (it != sections_.end() && it->second.owner != owner)
    throw Error("report section '" + key + "' already belongs to node '" + it->second.owner + "'");
  // A section set again replaces its readings with its values.
  const std::string prefix = key + ".";
  for (auto m = metrics_.lower_bound(prefix); m != metrics_.end() && m->first.starts_with(prefix);)
    m = metrics_.erase(m);
  for (const auto& [path, meta] : section.metrics()) metrics_[prefix + path] = meta;
  sections_[key] = Section{owner, section.values(), section.markdown()};
}

void Report::add_artifact(const std::string& owner, const std::string& file, std::string_view bytes,
                          std::string caption) {
  if (artifact_dir_.empty()) return;
  if (file.empty() || file.find('/') != std::string::npos || file.front() == '.')
    throw Error("'" + file + "' is not a plain file name for a report artifact");
  {
    std::lock_guard lock(mutex_);
    for (const auto& a : artifacts_)
      if (a.file == file && a.owner != owner)
        throw Error("report file '" + file + "' was already added by node '" + a.owner + "'");
  }
  const std::filesystem::path path = artifact_dir_ / file;
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw Error("cannot write report file " + path.string());
  std::lock_guard lock(mutex_);
  for (auto& a : artifacts_)
    if (a.file == file) {
      a.caption = std::move(caption);
      return;
    }
  artifacts_.push_back(Artifact{file, owner, std::move(caption)});
}

std::map<std::string, MetricMeta> Report::metrics() const {
  std::lock_guard lock(mutex_);
  return metrics_;
}

std::vector<Artifact> Report::artifacts() const {
  std::lock_guard lock(mutex_);
  return artifacts_;
}

std::map<std::string, Report::Section> Report::sections() const {
  std::lock_guard lock(mutex_);
  return sections_;
}

}  // namespace kestrel

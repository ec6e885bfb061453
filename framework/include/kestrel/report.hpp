#pragma once
// The run report: one report.json that the runtime's statistics and every evaluator node add to,
// plus a human-readable report.md beside it. Later stages add their metrics here rather than
// inventing files of their own.
#include <filesystem>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>

namespace kestrel {

class Report {
 public:
  /// Sets the top-level section `key` of report.json (e.g. "detection"). `markdown`, if given,
  /// is the section's text in report.md; otherwise the JSON is rendered as a table. A key can be
  /// owned by one node only; a second owner is an error.
  void set_section(const std::string& owner, const std::string& key, nlohmann::json value, std::string markdown = {});

  /// Where nodes may write files that belong with the report (PNG images, CSV). Empty when the
  /// run was started without --report.
  const std::filesystem::path& artifact_dir() const { return artifact_dir_; }
  void set_artifact_dir(std::filesystem::path dir) { artifact_dir_ = std::move(dir); }

  struct Section {
    std::string owner;
    nlohmann::json value;
    std::string markdown;
  };
  /// A copy of the sections, for writing.
  std::map<std::string, Section> sections() const;

 private:
  mutable std::mutex mutex_;
  std::map<std::string, Section> sections_;
  std::filesystem::path artifact_dir_;
};

}  // namespace kestrel

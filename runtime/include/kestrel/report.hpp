#pragma once
// The run report: one report.json that the runtime's statistics and every evaluator node add to,
// plus a human-readable report.md beside it. Later stages add their metrics here rather than
// inventing files of their own.
#include <filesystem>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kestrel/report_section.hpp"

namespace kestrel {

/// A file that belongs to the report: a plot, a snapshot, a table.
struct Artifact {
  std::string file;  ///< name inside the report folder
  std::string owner;
  std::string caption;
};

class Report {
 public:
  /// Sets the top-level section `key` of report.json (e.g. "detection") and records how to read
  /// each of its metrics as "key.path" (report.json's "metrics_meta"). The section's markdown, if
  /// any, is its text in report.md; otherwise the values are rendered as a table. A key can be
  /// owned by one node only; a second owner is an error.
  void set_section(const std::string& owner, const std::string& key, const ReportSection& section);

  /// Writes `bytes` as `file` in the report folder and lists it in the report (images are shown
  /// in report.md). Does nothing when the run has no report folder. Throws kestrel::Error if the
  /// file cannot be written, or if another node already added a file of that name.
  void add_artifact(const std::string& owner, const std::string& file, std::string_view bytes, std::string caption);
  /// True when the run writes a report folder (artifacts are kept).
  bool keeps_artifacts() const { return !artifact_dir_.empty(); }
  void set_artifact_dir(std::filesystem::path dir) { artifact_dir_ = std::move(dir); }

  struct Section {
    std::string owner;
    nlohmann::json value;
    std::string markdown;
  };
  /// A copy of the sections, for writing.
  std::map<std::string, Section> sections() const;
  std::map<std::string, MetricMeta> metrics() const;
  std::vector<Artifact> artifacts() const;

 private:
  mutable std::mutex mutex_;
  std::map<std::string, Section> sections_;
  std::map<std::string, MetricMeta> metrics_;
  std::vector<Artifact> artifacts_;
  std::filesystem::path artifact_dir_;
};

}  // namespace kestrel

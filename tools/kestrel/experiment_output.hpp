#pragma once
// The files that `kestrel sweep` and `kestrel ab` leave: CSV for scripts, Markdown for people,
// JSON for tools and PNG plots.
#include <filesystem>
#include <string>

#include "commands.hpp"
#include "experiment_analysis.hpp"
#include "run_plan.hpp"

namespace kestrel::cli {

/// Writes DIR/sweep.csv (every run), sweep.md (means over seeds) and sweep.png; returns the
/// Markdown.
std::string write_sweep_outputs(const std::filesystem::path& dir, const std::string& graph, const SweepPlan& plan,
                                const SweepSummary& summary);

/// Writes DIR/ab.md, ab.json and ab.png; returns the Markdown.
std::string write_ab_outputs(const std::filesystem::path& dir, const AbArgs& args, const AbSummary& summary);

}  // namespace kestrel::cli

#include "graph_loading.hpp"

#include <spdlog/spdlog.h>

#include <cstdio>

namespace kestrel::cli {

LoadedGraph load_graph(const GraphArgs& args, const char* not_done) {
  LoadedGraph loaded;
  const GraphSource source = GraphSource::from_file(args.graph);
  loaded.plugins = std::make_unique<PluginHost>();
  loaded.plugins->load_search_path(source.plugin_paths());
  for (const auto& e : loaded.plugins->errors()) spdlog::warn("{}", e.message);
  std::vector<GraphSource> fragments;
  std::vector<const GraphSource*> fragment_ptrs;
  for (const auto& f : args.fragments) fragments.push_back(GraphSource::from_string(f.yaml, f.label));
  for (const auto& f : fragments) fragment_ptrs.push_back(&f);
  std::optional<ExecutorKind> executor;
  if (args.executor == "realtime") executor = ExecutorKind::realtime;
  if (args.executor == "lockstep") executor = ExecutorKind::lockstep;
  BuildResult result = build_graph(source, loaded.plugins->registry(), args.overrides, fragment_ptrs, executor);
  std::fputs(result.diagnostics.str().c_str(), stderr);
  if (result.diagnostics.has_errors())
    std::fprintf(stderr, "%s: %zu error(s); %s\n", args.graph.c_str(), result.diagnostics.error_count(), not_done);
  loaded.graph = std::move(result.graph);
  return loaded;
}

}  // namespace kestrel::cli

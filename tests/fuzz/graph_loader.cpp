// Fuzz target: the YAML graph loader (GraphSource::from_file, includes, build_graph with --set
// overrides) against a registry that holds the test plugin's node types, so that parameter,
// port and connection checks run too. Whatever the input, loading must end with a graph or with
// diagnostics: never a crash, an exception, a hang or a leak.
//
// The input is split at lines "%%" into up to three parts:
//   main graph  %%  included graph  %%  overrides, one "node.param=value" per line
// The main graph is written to main.yaml and the included one to part.yaml in the same scratch
// folder, so `include: [part.yaml]` (or part.yaml including main.yaml) reaches it.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "kestrel/runtime/graph.hpp"
#include "kestrel/runtime/plugin_host.hpp"

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kSeparator = "\n%%\n";
constexpr std::size_t kMaxOverrides = 16;

struct Fixture {
  kestrel::PluginHost host;
  fs::path dir;

  Fixture() {
    if (!host.load(KESTREL_TEST_PLUGIN_DIR "/kestrel_test_nodes.so")) {
      std::fprintf(stderr, "cannot load the test plugin: %s\n", host.errors().back().message.c_str());
      std::abort();
    }
    // In memory when the machine has a tmpfs: rewriting two files per input on a disk costs more
    // than loading them.
    std::error_code ec;
    const fs::path base = fs::is_directory("/dev/shm", ec) && access("/dev/shm", W_OK) == 0 ? fs::path("/dev/shm")
                                                                                            : fs::temp_directory_path();
    dir = base / ("kestrel-fuzz-graph-" + std::to_string(getpid()));
    fs::create_directories(dir);
  }
  ~Fixture() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

void write(const fs::path& file, std::string_view text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

std::vector<std::string_view> split(std::string_view input) {
  std::vector<std::string_view> parts;
  while (parts.size() < 2) {
    const auto at = input.find(kSeparator);
    if (at == std::string_view::npos) break;
    parts.push_back(input.substr(0, at));
    input.remove_prefix(at + kSeparator.size());
  }
  parts.push_back(input);
  return parts;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fixture();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Fixture& f = fixture();
  const auto parts = split(std::string_view(reinterpret_cast<const char*>(data), size));
  write(f.dir / "main.yaml", parts[0]);
  write(f.dir / "part.yaml", parts.size() > 1 ? parts[1] : std::string_view());

  std::vector<std::string> overrides;
  if (parts.size() > 2) {
    std::string_view rest = parts[2];
    while (!rest.empty() && overrides.size() < kMaxOverrides) {
      const auto end = rest.find('\n');
      overrides.emplace_back(rest.substr(0, end));
      rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    }
  }

  const auto source = kestrel::GraphSource::from_file(f.dir / "main.yaml");
  (void)source.plugin_paths();
  const auto result = kestrel::build_graph(source, f.host.registry(), overrides);
  // A graph is returned exactly when there is no error, and every error can be printed.
  if (result.graph.has_value() == result.diagnostics.has_errors()) std::abort();
  (void)result.diagnostics.str();
  if (result.graph) (void)kestrel::to_dot(*result.graph);
  return 0;
}

// The plugin host loads good plugins and refuses every bad one with a message naming the file.
#include <gmock/gmock.h>

#include <filesystem>
#include <fstream>

#include "kestrel/abi.hpp"
#include "kestrel/testing/graphs.hpp"
#include "kestrel/testing/scratch_path.hpp"

using namespace kestrel;
using ::testing::HasSubstr;

namespace fs = std::filesystem;

namespace {

const fs::path kBad = KESTREL_BAD_PLUGIN_DIR;
const fs::path kGood = fs::path(KESTREL_TEST_PLUGIN_DIR) / "kestrel_test_nodes.so";

std::string refusal(const fs::path& file) {
  PluginHost host;
  EXPECT_FALSE(host.load(file));
  EXPECT_EQ(host.errors().size(), 1u);
  return host.errors().empty() ? "" : host.errors().front().message;
}

}  // namespace

TEST(PluginLoading, GoodPluginRegistersItsTypes) {
  PluginHost host;
  ASSERT_TRUE(host.load(kGood)) << host.errors().front().message;
  ASSERT_EQ(host.plugins().size(), 1u);
  const auto& info = host.plugins().front();
  EXPECT_EQ(info.name, "test_nodes");
  EXPECT_THAT(info.node_types, ::testing::Contains("counter_source"));
  // Its own message types, and the framework's that its ports use: a plugin brings the message
  // types it needs, the runtime registers none.
  EXPECT_THAT(info.messages,
              ::testing::UnorderedElementsAre("test.Number", "test.Blob", "test.Counted", "kestrel.Detections",
                                              "kestrel.GroundTruth", "kestrel.Tracks", "kestrel.NetFire"));
  const NodeType* relay = host.registry().find_node("relay");
  ASSERT_NE(relay, nullptr);
  EXPECT_EQ(relay->plugin, kGood.string());
  EXPECT_EQ(relay->spec.inputs().at(0).type(), "test.Number");
  // Loading the same file again is a no-op, not a duplicate registration.
  EXPECT_TRUE(host.load(kGood));
  EXPECT_EQ(host.plugins().size(), 1u);
}

TEST(PluginLoading, RefusesALibraryWithoutEntryPoint) {
  const auto file = kBad / "not_a_plugin.so";
  EXPECT_THAT(refusal(file),
              HasSubstr(file.string() + " is not a kestrel plugin: it has no kestrel_plugin_descriptor_v1"));
}

TEST(PluginLoading, RefusesAnotherAbiMajorNamingBothVersions) {
  const auto file = kBad / "wrong_abi_major.so";
  const std::string e = refusal(file);
  EXPECT_THAT(e, HasSubstr("refusing plugin " + file.string()));
  EXPECT_THAT(e, HasSubstr("built for kestrel 99.0.0 (ABI major 99"));
  EXPECT_THAT(e, HasSubstr(std::string("but this is kestrel ") + KESTREL_VERSION_STRING));
}

TEST(PluginLoading, RefusesAnotherAbiTagNamingBothTags) {
  const std::string e = refusal(kBad / "wrong_abi_tag.so");
  EXPECT_THAT(e, HasSubstr("tag c++201703/libstdc++-cxx11abi0/api-000000000000"));
  EXPECT_THAT(e, HasSubstr(std::string("tag ") + KESTREL_ABI_TAG));
}

TEST(PluginLoading, RefusesAMissingSymbolWithDlerrorText) {
  const auto file = kBad / "missing_symbol.so";
  const std::string e = refusal(file);
  EXPECT_THAT(e, HasSubstr("cannot load plugin " + file.string()));
  EXPECT_THAT(e, HasSubstr("undefined symbol: kestrel_test_symbol_nobody_defines"));
}

TEST(PluginLoading, RefusesACorruptFile) {
  const fs::path dir = kestrel::testing::scratch_path("kestrel-corrupt-plugin");
  fs::create_directories(dir);
  const fs::path file = dir / "kestrel_corrupt.so";
  std::ofstream(file) << "this is not a shared library";
  EXPECT_THAT(refusal(file), HasSubstr(file.string() + " is not a shared library (no ELF header)"));

  // A truncated ELF file gets past the magic number; dlopen's own reason is passed on.
  fs::copy_file(kGood, dir / "kestrel_truncated.so", fs::copy_options::overwrite_existing);
  fs::resize_file(dir / "kestrel_truncated.so", 100);
  EXPECT_THAT(refusal(dir / "kestrel_truncated.so"), HasSubstr("cannot load plugin"));
}

TEST(PluginLoading, RefusesADuplicateTypeNamingBothPlugins) {
  PluginHost host;
  ASSERT_TRUE(host.load(kGood));
  EXPECT_FALSE(host.load(kBad / "duplicate_type.so"));
  EXPECT_THAT(host.errors().front().message,
              HasSubstr("registers node type 'relay', which " + kGood.string() + " already provides"));
}

TEST(PluginLoading, FailedRegistrationAddsNothing) {
  PluginHost host;
  EXPECT_FALSE(host.load(kBad / "failing_registration.so"));
  EXPECT_THAT(host.errors().front().message, HasSubstr("failed to register: spec() cannot be built"));
  EXPECT_EQ(host.registry().find_node("fine_but_doomed"), nullptr);
}

TEST(PluginLoading, AMalformedSpecIsRefusedWithThePluginsName) {
  PluginHost host;
  EXPECT_FALSE(host.load(kBad / "malformed_spec.so"));
  ASSERT_EQ(host.errors().size(), 1u);
  const std::string& e = host.errors().front().message;
  EXPECT_THAT(e, HasSubstr("malformed_spec.so failed to register: node type 'sloppy' has a malformed spec"));
  EXPECT_THAT(e, HasSubstr("parameter 'gain': the default 5 is outside its range [0, 1]"));
  EXPECT_THAT(e, HasSubstr("rule 'gain <= limit' names an undeclared parameter 'limit'"));
  EXPECT_EQ(host.registry().find_node("sloppy"), nullptr);
}

TEST(PluginLoading, ADirectoryOfMixedFilesLoadsEveryGoodPlugin) {
  const fs::path dir = kestrel::testing::scratch_path("kestrel-mixed-plugins");
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const auto& f : fs::directory_iterator(kBad)) fs::copy_file(f.path(), dir / f.path().filename());
  std::ofstream(dir / "garbage.so") << "junk";

  PluginHost host;
  ASSERT_TRUE(host.load(kGood));
  host.load_search_path({dir});
  std::vector<std::string> loaded;
  for (const auto& p : host.plugins()) loaded.push_back(p.name);
  EXPECT_THAT(loaded, ::testing::Contains("test_nodes"));
  // Every broken file is named in exactly one error.
  for (const char* name : {"not_a_plugin.so", "wrong_abi_major.so", "wrong_abi_tag.so", "missing_symbol.so",
                           "duplicate_type.so", "failing_registration.so", "malformed_spec.so", "garbage.so"}) {
    int mentions = 0;
    for (const auto& e : host.errors())
      if (e.file == dir / name) ++mentions;
    EXPECT_EQ(mentions, 1) << name;
  }
}

TEST(PluginLoading, SearchPathOrderIsBuiltinThenEnvironmentThenGraph) {
  ::setenv("KESTREL_PLUGIN_PATH", "/opt/a:/opt/b", 1);
  const auto path = PluginHost::search_path({"/graph/plugins"});
  ::unsetenv("KESTREL_PLUGIN_PATH");
  ASSERT_EQ(path.size(), 4u);
  EXPECT_EQ(path[0], PluginHost::builtin_plugin_dir());
  EXPECT_EQ(path[1], "/opt/a");
  EXPECT_EQ(path[2], "/opt/b");
  EXPECT_EQ(path[3], "/graph/plugins");
}

TEST(PluginLoading, MissingPluginFolderIsReported) {
  PluginHost host;
  host.load_search_path({"/nonexistent/kestrel/plugins"});
  ASSERT_FALSE(host.errors().empty());
  EXPECT_THAT(host.errors().back().message, HasSubstr("/nonexistent/kestrel/plugins is not a folder or a file"));
}

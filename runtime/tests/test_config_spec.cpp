// Parameters declared once, bound to config structs: types and defaults from the fields, choices
// onto enums, nested groups, fixed-size vectors, rules, and the checks a declaration must pass
// when a plugin registers it.
#include <gmock/gmock.h>

#include <Eigen/Core>
#include <array>

#include "kestrel/component.hpp"
#include "kestrel/config_spec.hpp"
#include "kestrel/node_spec.hpp"
#include "kestrel/registry.hpp"

using namespace kestrel;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

namespace {

struct Gains {
  double kp = 6.0;
  double kd = 4.7;
};

struct Config {
  enum class Rule { longest, nearest };
  int min_points = 20;
  int max_points = 200;
  double tolerance_m = 0.5;
  std::string label = "cluster";
  bool enabled = true;
  Rule rule = Rule::longest;
  Eigen::Vector3d aim{0.0, 1.0, 2.0};
  std::array<double, 2> window{-1.0, 1.0};
  Gains gains;
};

ConfigSpec<Config> declare() {
  ConfigSpec<Config> c;
  c.param("min_points", &Config::min_points).at_least(1).describe("smallest cluster");
  c.param("max_points", &Config::max_points).at_least(1).describe("largest cluster");
  c.param("tolerance_m", &Config::tolerance_m).with_unit("m").range(0.0, 10.0).describe("neighbour distance");
  c.param("label", &Config::label).describe("a name");
  c.param("enabled", &Config::enabled).describe("on or off");
  c.choice("rule", &Config::rule, {{"longest", Config::Rule::longest}, {"nearest", Config::Rule::nearest}})
      .describe("selection");
  c.param("aim", &Config::aim).with_unit("m").describe("aim point");
  c.param("window", &Config::window).describe("bounds");
  c.param("kp", &Config::gains, &Gains::kp).at_least(0.0).describe("position gain");
  c.param("kd", &Config::gains, &Gains::kd).at_least(0.0).describe("velocity gain");
  c.rule("min_points <= max_points", {"min_points", "max_points"},
         [](const Config& k) { return k.min_points <= k.max_points; });
  return c;
}

Params defaults(const ParamSet& set) {
  Params p;
  for (const auto& s : set.params) p.set(s.name, *s.default_value);
  return p;
}

}  // namespace

TEST(ConfigSpec, FieldTypesAndInitialValuesBecomeTypesAndDefaults) {
  const ParamSet set = declare().release();
  ASSERT_EQ(set.params.size(), 10u);
  auto spec = [&](const char* name) { return *set.find(name); };
  EXPECT_EQ(spec("min_points").type, ParamType::integer);
  EXPECT_EQ(to_string(*spec("min_points").default_value), "20");
  EXPECT_EQ(spec("tolerance_m").type, ParamType::number);
  EXPECT_EQ(spec("tolerance_m").unit, "m");
  EXPECT_EQ(spec("label").type, ParamType::string);
  EXPECT_EQ(spec("enabled").type, ParamType::boolean);
  EXPECT_EQ(spec("rule").type, ParamType::string);
  EXPECT_THAT(spec("rule").allowed, ElementsAre("longest", "nearest"));
  EXPECT_EQ(to_string(*spec("rule").default_value), "longest");
  EXPECT_EQ(spec("aim").type, ParamType::number_list);
  EXPECT_EQ(spec("aim").length, 3u);
  EXPECT_EQ(to_string(*spec("aim").default_value), "[0, 1, 2]");
  EXPECT_EQ(spec("window").length, 2u);
  EXPECT_EQ(to_string(*spec("kd").default_value), "4.7");
  EXPECT_THAT(check_param_set(set), IsEmpty());
}

TEST(ConfigSpec, BuildsTheStructFromValidatedValues) {
  const ParamSet set = declare().release();
  Params p = defaults(set);
  p.set("max_points", std::int64_t{300});
  p.set("rule", std::string("nearest"));
  p.set("aim", std::vector<double>{1, 2, 3});
  p.set("kp", std::int64_t{8});  // an integer where a float is declared widens
  p.set("label", std::string("x"));
  const Config c = detail::config_from<Config>(set, p, "test");
  EXPECT_EQ(c.max_points, 300);
  EXPECT_EQ(c.min_points, 20);
  EXPECT_EQ(c.rule, Config::Rule::nearest);
  EXPECT_TRUE(c.aim.isApprox(Eigen::Vector3d(1, 2, 3)));
  EXPECT_DOUBLE_EQ(c.gains.kp, 8.0);
  EXPECT_DOUBLE_EQ(c.gains.kd, 4.7);
  EXPECT_EQ(c.label, "x");
  EXPECT_THROW(detail::config_from<Gains>(set, p, "test"), Error);  // not the struct spec() binds
}

TEST(ConfigSpec, RulesAreEvaluatedOnTheBuiltStruct) {
  const ParamSet set = declare().release();
  Params p = defaults(set);
  EXPECT_THAT(set.broken_rules(p), IsEmpty());
  p.set("min_points", std::int64_t{500});
  const auto broken = set.broken_rules(p);
  ASSERT_EQ(broken.size(), 1u);
  EXPECT_EQ(broken.front()->text, "min_points <= max_points");
}

TEST(ConfigSpec, MalformedDeclarationsAreNamed) {
  struct C {
    double a = 5.0;
    double b = 1.0;
    int n = 3;
    std::vector<double> v{1, 2};
  };
  ConfigSpec<C> c;
  c.param("a", &C::a).range(0.0, 1.0).describe("default outside its range");
  c.param("a", &C::b).describe("declared twice");
  c.param("n", &C::n).describe("");
  c.param("v", &C::v).with_length(3).describe("default of the wrong length");
  c.rule("a <= limit", {"a", "limit"}, [](const C&) { return true; });
  const auto problems = check_param_set(std::move(c).release());
  EXPECT_THAT(problems, ::testing::Contains(HasSubstr("parameter 'a': the default 5 is outside its range [0, 1]")));
  EXPECT_THAT(problems, ::testing::Contains(HasSubstr("parameter 'a' is declared twice")));
  EXPECT_THAT(problems, ::testing::Contains(HasSubstr("parameter 'n' has no description")));
  EXPECT_THAT(problems, ::testing::Contains(HasSubstr("the default has 2 numbers, but the parameter takes 3")));
  EXPECT_THAT(problems, ::testing::Contains(HasSubstr("rule 'a <= limit' names an undeclared parameter 'limit'")));
}

TEST(ConfigSpec, DefaultsThatBreakARuleAreMalformed) {
  struct C {
    int lo = 10;
    int hi = 5;
  };
  ConfigSpec<C> c;
  c.param("lo", &C::lo).describe("low");
  c.param("hi", &C::hi).describe("high");
  c.rule("lo <= hi", {"lo", "hi"}, [](const C& k) { return k.lo <= k.hi; });
  EXPECT_THAT(check_param_set(std::move(c).release()), ElementsAre("the defaults break the rule 'lo <= hi'"));
}

TEST(ConfigSpec, TheRegistryRefusesAMalformedSpecByName) {
  struct C {
    double gain = 5.0;
  };
  ConfigSpec<C> c;
  c.param("gain", &C::gain).range(0.0, 1.0).describe("gain");
  Registry registry;
  try {
    registry.add_node(NodeSpec("sloppy", "careless").config(std::move(c)), nullptr);
    FAIL() << "a malformed spec was registered";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("node type 'sloppy' has a malformed spec: parameter 'gain': the default 5 is "
                                    "outside its range [0, 1]"));
  }
  EXPECT_EQ(registry.find_node("sloppy"), nullptr);
}

TEST(ConfigSpec, ComponentSeedsAreStableAndDistinct) {
  EXPECT_EQ(detail::derive_seed(7, "associator"), detail::derive_seed(7, "associator"));
  EXPECT_NE(detail::derive_seed(7, "associator"), detail::derive_seed(7, "filter"));
  EXPECT_NE(detail::derive_seed(7, "filter"), detail::derive_seed(8, "filter"));
}

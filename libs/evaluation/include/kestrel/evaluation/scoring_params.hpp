#pragma once
// The parameters every evaluator against ground truth shares, declared once: a group that each
// evaluator's config struct holds, and the function that declares it on the evaluator's spec.
//
//   struct Config {
//     ScoringParams scoring{.section = "detection"};   // the section's default is the evaluator's
//   };
//   ConfigSpec<Config> c;
//   declare_scoring_params(c, &Config::scoring, "largest error still matched");
#include <string>

#include "kestrel/config_spec.hpp"

namespace kestrel::evaluation {

struct ScoringParams {
  double match_radius_m = 1.0;
  double skip_first_s = 0.0;
  double max_lag_s = 1.0;
  double lag_step_s = 0.001;
  std::string section;
};

/// Declares match_radius_m, skip_first_s, max_lag_s, lag_step_s and section, bound to the group
/// `group` of Config, with their rules: the lag step fits in the lag range, and the section has a
/// name. The defaults are the values of Config{}.
template <class Config>
void declare_scoring_params(ConfigSpec<Config>& c, ScoringParams Config::*group,
                            const std::string& radius_description) {
  c.param("match_radius_m", group, &ScoringParams::match_radius_m)
      .range(0.0, 100.0)
      .with_unit("m")
      .describe(radius_description);
  c.param("skip_first_s", group, &ScoringParams::skip_first_s)
      .range(0.0, 1e6)
      .with_unit("s")
      .describe("frames captured earlier are not scored");
  c.param("max_lag_s", group, &ScoringParams::max_lag_s).range(0.0, 100.0).with_unit("s").describe("lag search range");
  c.param("lag_step_s", group, &ScoringParams::lag_step_s)
      .range(1e-6, 1.0)
      .with_unit("s")
      .describe("lag search resolution");
  c.param("section", group, &ScoringParams::section).describe("report.json key");
  c.rule("lag_step_s <= max_lag_s (unless max_lag_s = 0)", {"lag_step_s", "max_lag_s"}, [group](const Config& k) {
    const ScoringParams& s = k.*group;
    return s.max_lag_s == 0.0 || s.lag_step_s <= s.max_lag_s;
  });
  c.rule("section is not empty", {"section"}, [group](const Config& k) { return !(k.*group).section.empty(); });
}

}  // namespace kestrel::evaluation

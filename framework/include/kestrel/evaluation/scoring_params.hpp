#pragma once
// The parameters every evaluator against ground truth shares, declared once.
#include <string>

#include "kestrel/node.hpp"
#include "kestrel/node_spec.hpp"

namespace kestrel::evaluation {

struct ScoringParams {
  double match_radius_m = 1.0;
  double skip_first_s = 0.0;
  double max_lag_s = 1.0;
  double lag_step_s = 0.001;
  std::string section;
};

/// match_radius_m, skip_first_s, max_lag_s, lag_step_s and section (default `section`).
inline NodeSpec& add_scoring_params(NodeSpec& spec, const std::string& section, const std::string& radius_description) {
  return spec.param(param("match_radius_m", 1.0).range(0.0, 100.0).with_unit("m").describe(radius_description))
      .param(
          param("skip_first_s", 0.0).range(0.0, 1e6).with_unit("s").describe("frames captured earlier are not scored"))
      .param(param("max_lag_s", 1.0).range(0.0, 100.0).with_unit("s").describe("lag search range"))
      .param(param("lag_step_s", 0.001).range(1e-6, 1.0).with_unit("s").describe("lag search resolution"))
      .param(param("section", section).describe("report.json key"));
}

inline ScoringParams scoring_params(const NodeInit& init) {
  return {init.param<double>("match_radius_m"), init.param<double>("skip_first_s"), init.param<double>("max_lag_s"),
          init.param<double>("lag_step_s"), init.param<std::string>("section")};
}

}  // namespace kestrel::evaluation

#pragma once
// A component declares its parameters once, in a template over the config they are bound to:
// its own config struct, or a config that derives from it (a node that takes the component's
// parameters flat, as the deprecated tracker node types do). field_of() turns a field of the
// component's struct into a field of that config.
//
//   template <class Config>
//   static void declare(ConfigSpec<Config>& c) {
//     c.param("q", field_of<Config>(&KalmanConfig::q)).describe("...");
//   }
#include <type_traits>

namespace kestrel::tracking {

template <class Config, class Part, class T>
constexpr T Config::*field_of(T Part::*field) {
  static_assert(std::is_base_of_v<Part, Config>, "the config must be the component's config or derive from it");
  return field;
}

}  // namespace kestrel::tracking

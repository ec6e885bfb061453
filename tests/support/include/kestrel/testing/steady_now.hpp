#pragma once
// A run clock for drivers under test that stamp with the machine's steady clock.
#include <chrono>

#include "kestrel/time.hpp"

namespace kestrel::testing {

inline Time steady_now() { return std::chrono::steady_clock::now().time_since_epoch(); }

}  // namespace kestrel::testing

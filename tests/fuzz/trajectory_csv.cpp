// Fuzz target: the intruder's recorded-flight CSV reader (RecordedFlight). Any bytes must give a
// flight or a kestrel::Error naming the line; a flight that loads must give finite positions and
// velocities at any finite time, looping or not.
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "kestrel/error.hpp"
#include "trajectory.hpp"

namespace {

void check(const kestrel::intruder::State& s) {
  if (!s.position.allFinite() || !s.velocity.allFinite()) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const bool loop : {false, true}) {
    std::istringstream in(text);
    try {
      const kestrel::intruder::RecordedFlight flight(in, "fuzz.csv", loop);
      const double d = flight.duration();
      for (const double t : {-1.0, 0.0, 0.25 * d, 0.5 * d, d, 1.5 * d, 3.7 * d + 0.1, 1e9}) check(flight.at(t));
    } catch (const kestrel::Error&) {
      // a malformed file: the message names its line
    }
  }
  return 0;
}

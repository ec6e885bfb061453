#pragma once
// A track as the track-management components (initiator, deleter, selector) see it: its counts
// and, read-only, its filter.
#include <cstdint>

namespace kestrel::tracking {

class TrackFilter;

struct TrackStatus {
  std::uint64_t id = 0;                 ///< 1, 2, ... in order of birth
  int age = 0;                          ///< frames since birth, the birth frame included
  int hits = 0;                         ///< frames with an associated detection, the birth frame included
  int misses = 0;                       ///< consecutive frames without one, up to this frame
  bool confirmed = false;               ///< published, and a candidate target
  const TrackFilter* filter = nullptr;  ///< the track's estimator
};

}  // namespace kestrel::tracking

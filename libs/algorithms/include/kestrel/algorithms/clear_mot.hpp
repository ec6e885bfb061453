#pragma once
// CLEAR-MOT and identity metrics for multi-object tracking, as defined by MOT16 and computed by
// py-motmetrics. Feed one frame at a time: the ground-truth object ids, the hypothesis (track)
// ids, and their distances (not finite = the pair may not match).
#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <vector>

namespace kestrel::algorithms {

struct MotSummary {
  std::uint64_t frames = 0;
  std::uint64_t objects = 0;     ///< ground-truth entries over all frames
  std::uint64_t hypotheses = 0;  ///< hypothesis entries over all frames
  std::uint64_t matches = 0;     ///< including switches
  std::uint64_t fp = 0, fn = 0, idsw = 0, fragmentations = 0;
  std::uint64_t mostly_tracked = 0, partially_tracked = 0, mostly_lost = 0;
  std::uint64_t idtp = 0, idfp = 0, idfn = 0;
  double mota = 0.0;
  double motp = 0.0;  ///< mean distance of matches
  double idf1 = 0.0, idp = 0.0, idr = 0.0;
  double precision = 0.0, recall = 0.0;
};

class ClearMotAccumulator {
 public:
  /// One frame. distances(i, j) between objects[i] and hypotheses[j].
  void update(const std::vector<std::uint64_t>& objects, const std::vector<std::uint64_t>& hypotheses,
              const Eigen::MatrixXd& distances);
  MotSummary summary() const;

  /// Per match of this frame (object index, hypothesis index), for callers that need them.
  const std::vector<std::pair<int, int>>& last_matches() const { return last_matches_; }

 private:
  std::map<std::uint64_t, std::uint64_t> last_match_;   // object -> hypothesis it last matched
  std::map<std::uint64_t, std::vector<char>> tracked_;  // object -> tracked flag per frame present
  std::map<std::pair<std::uint64_t, std::uint64_t>, std::uint64_t> co_valid_;  // identity pairs
  std::map<std::uint64_t, std::uint64_t> object_frames_, hypothesis_frames_;
  std::vector<std::pair<int, int>> last_matches_;
  MotSummary counts_;
  double distance_sum_ = 0.0;
};

}  // namespace kestrel::algorithms

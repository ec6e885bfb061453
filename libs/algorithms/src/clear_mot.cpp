#include "kestrel/algorithms/clear_mot.hpp"

#include <algorithm>
#include <cmath>

#include "kestrel/algorithms/assignment.hpp"

namespace kestrel::algorithms {

void ClearMotAccumulator::update(const std::vector<std::uint64_t>& objects,
                                 const std::vector<std::uint64_t>& hypotheses, const Eigen::MatrixXd& distances) {
  const auto n_obj = objects.size(), n_hyp = hypotheses.size();
  auto valid = [&](std::size_t i, std::size_t j) {
    return std::isfinite(distances(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
  };
  std::vector<char> object_done(n_obj, 0), hypothesis_done(n_hyp, 0);
  last_matches_.clear();
  auto record_match = [&](std::size_t i, std::size_t j) {
    object_done[i] = hypothesis_done[j] = 1;
    last_match_[objects[i]] = hypotheses[j];
    distance_sum_ += distances(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
    ++counts_.matches;
    last_matches_.emplace_back(static_cast<int>(i), static_cast<int>(j));
  };

  // 1. Correspondences from earlier frames survive while their distance stays valid.
  for (std::size_t i = 0; i < n_obj; ++i) {
    const auto previous = last_match_.find(objects[i]);
    if (previous == last_match_.end()) continue;
    for (std::size_t j = 0; j < n_hyp; ++j)
      if (!hypothesis_done[j] && hypotheses[j] == previous->second && valid(i, j)) {
        record_match(i, j);
        break;
      }
  }
  // 2. The rest by minimum-cost assignment; a new partner for a matched object is a switch.
  std::vector<std::size_t> free_obj, free_hyp;
  for (std::size_t i = 0; i < n_obj; ++i)
    if (!object_done[i]) free_obj.push_back(i);
  for (std::size_t j = 0; j < n_hyp; ++j)
    if (!hypothesis_done[j]) free_hyp.push_back(j);
  Eigen::MatrixXd cost(static_cast<Eigen::Index>(free_obj.size()), static_cast<Eigen::Index>(free_hyp.size()));
  for (std::size_t a = 0; a < free_obj.size(); ++a)
    for (std::size_t b = 0; b < free_hyp.size(); ++b)
      cost(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) =
          valid(free_obj[a], free_hyp[b])
              ? distances(static_cast<Eigen::Index>(free_obj[a]), static_cast<Eigen::Index>(free_hyp[b]))
              : kForbidden;
  const Assignment assignment = solve_assignment(cost);
  for (std::size_t a = 0; a < free_obj.size(); ++a) {
    const int b = assignment.row_to_col[a];
    if (b < 0) continue;
    const std::size_t i = free_obj[a], j = free_hyp[static_cast<std::size_t>(b)];
    const auto previous = last_match_.find(objects[i]);
    if (previous != last_match_.end() && previous->second != hypotheses[j]) ++counts_.idsw;
    record_match(i, j);
  }
  // 3. What is left: misses and false positives.
  for (std::size_t i = 0; i < n_obj; ++i) {
    if (!object_done[i]) ++counts_.fn;
    tracked_[objects[i]].push_back(object_done[i]);
    ++object_frames_[objects[i]];
  }
  for (std::size_t j = 0; j < n_hyp; ++j) {
    if (!hypothesis_done[j]) ++counts_.fp;
    ++hypothesis_frames_[hypotheses[j]];
  }
  for (std::size_t i = 0; i < n_obj; ++i)
    for (std::size_t j = 0; j < n_hyp; ++j)
      if (valid(i, j)) ++co_valid_[{objects[i], hypotheses[j]}];
  counts_.objects += n_obj;
  counts_.hypotheses += n_hyp;
  ++counts_.frames;
}

MotSummary ClearMotAccumulator::summary() const {
  MotSummary s = counts_;
  s.mota = s.objects ? 1.0 - static_cast<double>(s.fn + s.fp + s.idsw) / static_cast<double>(s.objects) : 1.0;
  s.motp = s.matches ? distance_sum_ / static_cast<double>(s.matches) : 0.0;
  s.precision = s.hypotheses ? static_cast<double>(s.matches) / static_cast<double>(s.hypotheses) : 1.0;
  s.recall = s.objects ? static_cast<double>(s.matches) / static_cast<double>(s.objects) : 1.0;

  for (const auto& [object, flags] : tracked_) {
    std::uint64_t hit = 0;
    for (char f : flags) hit += f ? 1 : 0;
    const double ratio = static_cast<double>(hit) / static_cast<double>(flags.size());
    if (ratio >= 0.8)
      ++s.mostly_tracked;
    else if (ratio < 0.2)
      ++s.mostly_lost;
    else
      ++s.partially_tracked;
    // A fragmentation: a tracked span interrupted by a miss, between the first and last tracked frames.
    const auto first = std::find(flags.begin(), flags.end(), 1);
    const auto last = std::find(flags.rbegin(), flags.rend(), 1).base();
    for (auto it = first; it != flags.end() && it + 1 < last; ++it)
      if (*it && !*(it + 1)) ++s.fragmentations;
  }

  // Identity metrics: the one-to-one object-hypothesis mapping that maximises the frames in
  // which mapped pairs could match (IDTP), by assignment on negated counts.
  std::vector<std::uint64_t> object_ids, hypothesis_ids;
  for (const auto& [o, _] : object_frames_) object_ids.push_back(o);
  for (const auto& [h, _] : hypothesis_frames_) hypothesis_ids.push_back(h);
  Eigen::MatrixXd cost = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(object_ids.size()),
                                               static_cast<Eigen::Index>(hypothesis_ids.size()));
  for (std::size_t i = 0; i < object_ids.size(); ++i)
    for (std::size_t j = 0; j < hypothesis_ids.size(); ++j)
      if (auto it = co_valid_.find({object_ids[i], hypothesis_ids[j]}); it != co_valid_.end())
        cost(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = -static_cast<double>(it->second);
  const Assignment identity = solve_assignment(cost);
  s.idtp = static_cast<std::uint64_t>(std::llround(-identity.total_cost));
  s.idfn = s.objects - s.idtp;
  s.idfp = s.hypotheses - s.idtp;
  s.idf1 = s.objects + s.hypotheses ? 2.0 * static_cast<double>(s.idtp) / static_cast<double>(s.objects + s.hypotheses)
                                    : 1.0;
  s.idp = s.hypotheses ? static_cast<double>(s.idtp) / static_cast<double>(s.hypotheses) : 1.0;
  s.idr = s.objects ? static_cast<double>(s.idtp) / static_cast<double>(s.objects) : 1.0;
  return s;
}

}  // namespace kestrel::algorithms

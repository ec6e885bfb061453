#pragma once
// Pairs what an evaluator scores (detections, tracks) with the ground truth of the same capture
// time. Either may arrive first (under the realtime executor they travel different paths);
// unpaired truth is kept for a bounded number of frames, for frames the chain dropped.
#include <functional>
#include <map>
#include <memory>

#include "kestrel/messages/ground_truth.hpp"
#include "kestrel/time.hpp"

namespace kestrel::evaluation {

template <class T>
class TruthPairing {
 public:
  explicit TruthPairing(std::size_t max_waiting_truths = 300) : max_truths_(max_waiting_truths) {}

  void add_truth(std::shared_ptr<const msg::GroundTruth> truth) {
    truths_[truth->stamp] = std::move(truth);
    while (truths_.size() > max_truths_) truths_.erase(truths_.begin());
  }

  /// `arrival_s`: when the item reached the evaluator (the lag's time base).
  void add(Time stamp, std::shared_ptr<const T> item, double arrival_s) {
    waiting_[stamp] = {std::move(item), arrival_s};
  }

  /// Calls score(item, truth, arrival_s) for every item whose truth is here, in capture order,
  /// and forgets them (and older truth).
  void pair(const std::function<void(const T&, const msg::GroundTruth&, double)>& score) {
    for (auto it = waiting_.begin(); it != waiting_.end();) {
      const auto truth = truths_.find(it->first);
      if (truth == truths_.end()) {
        ++it;
        continue;
      }
      score(*it->second.item, *truth->second, it->second.arrival_s);
      truths_.erase(truths_.begin(), std::next(truth));
      it = waiting_.erase(it);
    }
  }

  /// Items still without their truth.
  std::size_t unpaired() const { return waiting_.size(); }

 private:
  struct Waiting {
    std::shared_ptr<const T> item;
    double arrival_s = 0.0;
  };
  std::size_t max_truths_;
  std::map<Time, std::shared_ptr<const msg::GroundTruth>> truths_;
  std::map<Time, Waiting> waiting_;
};

}  // namespace kestrel::evaluation

#pragma once
// Pairs what an evaluator scores (detections, tracks) with the ground truth of the same capture
// time. Either may arrive first (under the realtime executor they travel different paths).
//
// Both waiting lists are bounded, and nothing leaves them unseen: every item and every truth is
// either paired or counted as unpaired, so an evaluator can report what it could not score.
//   - Time moves forward: once an item is paired at capture time t, the truth and the items
//     captured before t can no longer pair (their partner was skipped) and are counted.
//   - An item that arrives for a capture time already paired, or older, is counted at once.
//   - A second item or truth for the same capture time replaces the first, which is counted.
//   - Over its bound, a list drops its oldest entry (a frame the other side never delivered)
//     and counts it.
#include <cstdint>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <optional>

#include "kestrel/messages/ground_truth.hpp"
#include "kestrel/time.hpp"

namespace kestrel::evaluation {

template <class T>
class TruthPairing {
 public:
  explicit TruthPairing(std::size_t max_waiting_truths = 300, std::size_t max_waiting_items = 300)
      : max_truths_(max_waiting_truths), max_items_(max_waiting_items) {}

  void add_truth(std::shared_ptr<const msg::GroundTruth> truth) {
    const Time stamp = truth->stamp;
    if (last_paired_ && stamp <= *last_paired_) {
      ++truths_dropped_;
      return;
    }
    if (!truths_.insert_or_assign(stamp, std::move(truth)).second) ++truths_dropped_;
    while (truths_.size() > max_truths_) {
      truths_.erase(truths_.begin());
      ++truths_dropped_;
    }
  }

  /// `arrival_s`: when the item reached the evaluator (the lag's time base).
  void add(Time stamp, std::shared_ptr<const T> item, double arrival_s) {
    if (last_paired_ && stamp <= *last_paired_) {
      ++items_dropped_;
      return;
    }
    if (!waiting_.insert_or_assign(stamp, Waiting{std::move(item), arrival_s}).second) ++items_dropped_;
    while (waiting_.size() > max_items_) {
      waiting_.erase(waiting_.begin());
      ++items_dropped_;
    }
  }

  /// Calls score(item, truth, arrival_s) for every item whose truth is here, in capture order,
  /// and forgets them, and the items and truth captured earlier (counted as unpaired).
  void pair(const std::function<void(const T&, const msg::GroundTruth&, double)>& score) {
    for (auto it = waiting_.begin(); it != waiting_.end();) {
      const auto truth = truths_.find(it->first);
      if (truth == truths_.end()) {
        ++it;
        continue;
      }
      score(*it->second.item, *truth->second, it->second.arrival_s);
      ++paired_;
      last_paired_ = it->first;
      truths_dropped_ += static_cast<std::uint64_t>(std::distance(truths_.begin(), truth));
      truths_.erase(truths_.begin(), std::next(truth));
      items_dropped_ += static_cast<std::uint64_t>(std::distance(waiting_.begin(), it));
      it = waiting_.erase(waiting_.begin(), std::next(it));
    }
  }

  /// Items waiting for their truth now.
  std::size_t unpaired() const { return waiting_.size(); }
  /// Truths waiting for their item now.
  std::size_t waiting_truths() const { return truths_.size(); }
  /// Items scored.
  std::uint64_t paired() const { return paired_; }
  /// Items that will never be scored: dropped so far plus those still waiting.
  std::uint64_t unpaired_items() const { return items_dropped_ + waiting_.size(); }
  /// Truths never paired with an item: dropped so far plus those still waiting.
  std::uint64_t unpaired_truths() const { return truths_dropped_ + truths_.size(); }

 private:
  struct Waiting {
    std::shared_ptr<const T> item;
    double arrival_s = 0.0;
  };
  std::size_t max_truths_;
  std::size_t max_items_;
  std::map<Time, std::shared_ptr<const msg::GroundTruth>> truths_;
  std::map<Time, Waiting> waiting_;
  std::optional<Time> last_paired_;
  std::uint64_t paired_ = 0;
  std::uint64_t items_dropped_ = 0;
  std::uint64_t truths_dropped_ = 0;
};

}  // namespace kestrel::evaluation

// TruthPairing on hand-made arrival orders: what pairs with what, in which order, and how every
// item or truth that cannot pair is counted rather than kept for ever.
#include <gmock/gmock.h>

#include "kestrel/evaluation/truth_pairing.hpp"

using namespace kestrel;
using kestrel::evaluation::TruthPairing;
using ::testing::ElementsAre;
using ::testing::IsEmpty;
using ::testing::Pair;

namespace {

struct Item {
  int id = 0;
};

Time frame(int k) { return from_seconds(0.1 * k); }

std::shared_ptr<const msg::GroundTruth> truth(int k) {
  auto t = std::make_shared<msg::GroundTruth>();
  t->stamp = frame(k);
  return t;
}

// Records each pairing as (item id, truth frame) and the arrival time handed over.
struct Recorder {
  std::vector<std::pair<int, int>> pairs;
  std::vector<double> arrivals;
  void operator()(const Item& item, const msg::GroundTruth& t, double arrival_s) {
    pairs.emplace_back(item.id, static_cast<int>(std::lround(to_seconds(t.stamp) / 0.1)));
    arrivals.push_back(arrival_s);
  }
};

struct Pairing : TruthPairing<Item> {
  using TruthPairing<Item>::TruthPairing;
  Recorder recorder;
  void item(int k, int id, double arrival_s = 0.0) {
    add(frame(k), std::make_shared<const Item>(Item{id}), arrival_s);
    pair(std::ref(recorder));
  }
  void truth_of(int k) {
    add_truth(truth(k));
    pair(std::ref(recorder));
  }
};

}  // namespace

TEST(TruthPairing, PairsByCaptureTimeWhicheverArrivesFirst) {
  Pairing p;
  p.truth_of(0);         // truth first
  p.item(0, 100, 0.05);  // then its item
  p.item(1, 101, 0.15);  // item first
  p.truth_of(1);         // then its truth
  p.truth_of(2);
  p.truth_of(3);
  p.item(2, 102, 0.30);  // the chain running behind the truth
  p.item(3, 103, 0.40);
  EXPECT_THAT(p.recorder.pairs, ElementsAre(Pair(100, 0), Pair(101, 1), Pair(102, 2), Pair(103, 3)));
  EXPECT_THAT(p.recorder.arrivals, ElementsAre(0.05, 0.15, 0.30, 0.40));
  EXPECT_EQ(p.paired(), 4u);
  EXPECT_EQ(p.unpaired_items(), 0u);
  EXPECT_EQ(p.unpaired_truths(), 0u);
}

TEST(TruthPairing, ItemsArrivingOutOfOrderAreScoredInCaptureOrder) {
  Pairing p;
  p.item(2, 102);
  p.item(0, 100);
  p.item(1, 101);
  EXPECT_THAT(p.recorder.pairs, IsEmpty());
  EXPECT_EQ(p.unpaired(), 3u);
  p.truth_of(1);  // truth 1 pairs item 1; item 0 can no longer pair once time has moved on
  p.truth_of(2);
  EXPECT_THAT(p.recorder.pairs, ElementsAre(Pair(101, 1), Pair(102, 2)));
  EXPECT_EQ(p.unpaired_items(), 1u);  // item 0, counted
  p.truth_of(0);                      // its truth, too late: counted, not paired
  EXPECT_THAT(p.recorder.pairs, ElementsAre(Pair(101, 1), Pair(102, 2)));
  EXPECT_EQ(p.unpaired_truths(), 1u);
  EXPECT_EQ(p.unpaired(), 0u);
  EXPECT_EQ(p.waiting_truths(), 0u);
}

TEST(TruthPairing, UnpairedItemsAndTruthsAreCounted) {
  Pairing p;
  for (int k = 0; k < 6; ++k) p.truth_of(k);
  p.item(0, 100);
  // The chain dropped frames 1 and 2: their truth is given up once frame 3 pairs.
  p.item(3, 103);
  EXPECT_EQ(p.unpaired_truths(), 2u + 2u);  // frames 1, 2 given up; 4, 5 still waiting
  EXPECT_EQ(p.waiting_truths(), 2u);
  // A late item for a frame already passed is counted at once, never scored.
  p.item(2, 102);
  EXPECT_EQ(p.unpaired_items(), 1u);
  EXPECT_EQ(p.unpaired(), 0u);
  // An item whose truth never comes keeps waiting and is counted as unpaired.
  p.item(9, 109);
  EXPECT_EQ(p.unpaired(), 1u);
  EXPECT_EQ(p.unpaired_items(), 2u);
  // A second item for the same frame replaces the first, which is counted.
  p.item(7, 107);
  p.item(7, 207);
  p.truth_of(7);
  EXPECT_THAT(p.recorder.pairs, ElementsAre(Pair(100, 0), Pair(103, 3), Pair(207, 7)));
  EXPECT_EQ(p.paired(), 3u);
  // Counted: items 102 and 107 dropped, 109 waiting. Truths 1, 2, 4, 5 given up; none waiting.
  EXPECT_EQ(p.unpaired_items(), 3u);
  EXPECT_EQ(p.unpaired_truths(), 4u);
  EXPECT_EQ(p.paired() + p.unpaired_items(), 6u);   // every item added, accounted for
  EXPECT_EQ(p.paired() + p.unpaired_truths(), 7u);  // every truth added, accounted for
}

TEST(TruthPairing, WaitingListsStayWithinTheirBoundsAndCountWhatTheyDrop) {
  Pairing p(/*max_waiting_truths=*/4, /*max_waiting_items=*/3);
  // A truth stream whose items never come (a chain that died): memory stays bounded.
  for (int k = 0; k < 1000; ++k) p.truth_of(k);
  EXPECT_EQ(p.waiting_truths(), 4u);
  EXPECT_EQ(p.unpaired_truths(), 1000u);
  // Items for frames whose truth never comes: the oldest are dropped and counted.
  for (int k = 2000; k < 2010; ++k) p.item(k, k);
  EXPECT_EQ(p.unpaired(), 3u);
  EXPECT_EQ(p.unpaired_items(), 10u);
  // The three kept are the newest: their truths pair them; the dropped ones do not come back.
  for (int k = 2000; k < 2010; ++k) p.truth_of(k);
  EXPECT_THAT(p.recorder.pairs, ElementsAre(Pair(2007, 2007), Pair(2008, 2008), Pair(2009, 2009)));
  EXPECT_EQ(p.unpaired_items(), 7u);
  EXPECT_EQ(p.paired() + p.unpaired_items(), 10u);
}

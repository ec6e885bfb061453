// The recorder's queue to its writer thread: never blocks the producer, drops and counts what
// finds it full, and hands over everything queued before it closed. Run under TSan (label threads).
#include <gmock/gmock.h>

#include <thread>

#include "kestrel/mcap/write_queue.hpp"

using kestrel::mcap::WriteQueue;

TEST(WriteQueue, DropsAndCountsWhatFindsItFullWithoutWaiting) {
  WriteQueue<int> q(2);
  EXPECT_TRUE(q.push(1));
  EXPECT_TRUE(q.push(2));
  EXPECT_FALSE(q.push(3));  // full: returns at once
  EXPECT_EQ(q.dropped(), 1u);
  q.close();
  EXPECT_FALSE(q.push(4));  // closed
  EXPECT_EQ(q.pop(), 1);
  EXPECT_EQ(q.pop(), 2);
  EXPECT_EQ(q.pop(), std::nullopt);
  EXPECT_EQ(q.dropped(), 2u);
}

TEST(WriteQueue, AWriterThreadGetsEveryItemNotDroppedInOrder) {
  WriteQueue<int> q(8);
  std::vector<int> got;
  std::thread writer([&] {
    while (auto item = q.pop()) got.push_back(*item);
  });
  std::uint64_t accepted = 0;
  for (int i = 0; i < 20000; ++i) accepted += q.push(i) ? 1 : 0;
  q.close();
  writer.join();
  EXPECT_EQ(got.size(), accepted);
  EXPECT_EQ(accepted + q.dropped(), 20000u);
  EXPECT_TRUE(std::is_sorted(got.begin(), got.end()));
}

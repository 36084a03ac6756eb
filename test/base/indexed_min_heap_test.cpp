#include "polygon_coverage_ros_bridge/base/indexed_min_heap.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

namespace kinematic_coverage::core {
namespace {

TEST(IndexedMinHeap, PopsInCostOrderUnderRandomPushesAndDecreases) {
  // Against a plain array of queued costs: every pop is an item of least cost, each item
  // is queued at most once, and a higher cost never raises a queued item.
  std::mt19937 rng(3);
  constexpr int kItems = 200;
  const double absent = std::numeric_limits<double>::infinity();
  for (int trial = 0; trial < 20; ++trial) {
    IndexedMinHeap heap(kItems);
    std::vector<double> queued(kItems, absent);
    std::uniform_int_distribution<int> item(0, kItems - 1);
    std::uniform_int_distribution<int> cost(0, 50);  // ties occur
    for (int step = 0; step < 3000; ++step) {
      if (rng() % 3 != 0 || heap.empty()) {
        const int i = item(rng);
        const double c = cost(rng);
        heap.pushOrDecrease(i, c);
        if (c < queued[i]) queued[i] = c;
      } else {
        const int popped = heap.popMin();
        ASSERT_NE(queued[popped], absent);
        for (int i = 0; i < kItems; ++i) ASSERT_LE(queued[popped], queued[i]) << i;
        queued[popped] = absent;
      }
    }
    while (!heap.empty()) {
      const int popped = heap.popMin();
      ASSERT_NE(queued[popped], absent);
      queued[popped] = absent;
    }
    for (int i = 0; i < kItems; ++i) EXPECT_EQ(queued[i], absent) << "item " << i << " lost";
  }
}

TEST(IndexedMinHeap, PoppedItemsCanBeQueuedAgain) {
  IndexedMinHeap heap(3);
  heap.pushOrDecrease(2, 5.0);
  heap.pushOrDecrease(0, 7.0);
  heap.pushOrDecrease(2, 9.0);  // higher: ignored
  EXPECT_EQ(heap.popMin(), 2);
  heap.pushOrDecrease(2, 1.0);
  EXPECT_EQ(heap.popMin(), 2);
  EXPECT_EQ(heap.popMin(), 0);
  EXPECT_TRUE(heap.empty());
}

}  // namespace
}  // namespace kinematic_coverage::core

#include "polygon_coverage_ros_bridge/base/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace kinematic_coverage::core {
namespace {

TEST(ParallelFor, CallsTheBodyOnceForEveryIndex) {
  for (std::size_t count : {0u, 1u, 2u, 7u, 1000u}) {
    std::vector<std::atomic<int>> calls(count);
    parallelFor(count, [&](std::size_t i) { ++calls[i]; });
    for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(calls[i], 1) << "index " << i;
  }
}

TEST(ParallelFor, UnevenRowsGiveWhatOneThreadGives) {
  // A triangle of work, as the visibility graph's rows: each row writes its own results.
  const std::size_t n = 300;
  std::vector<std::vector<double>> rows(n);
  parallelFor(n, [&](std::size_t u) {
    for (std::size_t w = u; w < n; ++w) rows[u].push_back(static_cast<double>(u * n + w) / 7.0);
  });
  for (std::size_t u = 0; u < n; ++u) {
    ASSERT_EQ(rows[u].size(), n - u);
    for (std::size_t w = u; w < n; ++w) {
      EXPECT_EQ(rows[u][w - u], static_cast<double>(u * n + w) / 7.0);
    }
  }
}

TEST(ParallelFor, OnThreadsGivesEachBodyAThreadOfItsOwn) {
  // Per-thread scratch state is safe: a thread index is below the thread count asked for
  // (more than the hardware has, too) and never in use by two bodies at once.
  for (std::size_t threads : {1u, 2u, 5u}) {
    std::vector<std::atomic<int>> busy(threads);
    std::vector<std::atomic<int>> calls(500);
    std::atomic<bool> shared{false};
    std::atomic<std::size_t> highest{0};
    parallelForOnThreads(calls.size(), threads, [&](std::size_t i, std::size_t thread) {
      std::size_t seen = highest;
      while (thread > seen && !highest.compare_exchange_weak(seen, thread)) {
      }
      if (thread >= threads) return;
      if (++busy[thread] != 1) shared = true;
      ++calls[i];
      --busy[thread];
    });
    EXPECT_LT(highest, threads);
    EXPECT_FALSE(shared);
    for (std::size_t i = 0; i < calls.size(); ++i) EXPECT_EQ(calls[i], 1) << "index " << i;
  }
  EXPECT_EQ(parallelThreadCount(3, 8), 3u);
  EXPECT_EQ(parallelThreadCount(0, 8), 1u);
  EXPECT_GE(parallelThreadCount(100), 1u);
}

TEST(ParallelFor, RethrowsWhatABodyThrewAfterEveryThreadStopped) {
  std::atomic<int> running{0};
  EXPECT_THROW(parallelFor(100,
                           [&](std::size_t i) {
                             ++running;
                             if (i == 17) {
                               --running;
                               throw std::runtime_error("index 17");
                             }
                             --running;
                           }),
               std::runtime_error);
  EXPECT_EQ(running, 0);
}

TEST(ParallelFor, InOrderRethrowsTheLowestFailingIndexAfterRunningTheRest) {
  // Every index runs; of the failures, the one a loop in order meets first is rethrown,
  // whichever thread failed first.
  for (int repeat = 0; repeat < 20; ++repeat) {
    std::vector<std::atomic<int>> calls(200);
    try {
      parallelForInOrder(200, [&](std::size_t i) {
        ++calls[i];
        if (i == 150 || i == 40 || i == 41) throw std::runtime_error(std::to_string(i));
      });
      ADD_FAILURE() << "nothing thrown";
    } catch (const std::runtime_error& error) {
      EXPECT_EQ(std::string(error.what()), "40");
    }
    for (std::size_t i = 0; i < calls.size(); ++i) EXPECT_EQ(calls[i], 1) << "index " << i;
  }
  parallelForInOrder(0, [](std::size_t) { ADD_FAILURE() << "no index to call"; });
}

}  // namespace
}  // namespace kinematic_coverage::core

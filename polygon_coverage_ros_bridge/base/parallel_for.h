#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace kinematic_coverage::core {

/// The number of threads that run `count` indices: `threads`, or every hardware thread when
/// it is 0; at most one per index, at least 1.
inline std::size_t parallelThreadCount(std::size_t count, std::size_t threads = 0) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  return std::max<std::size_t>(1, std::min(count, threads));
}

/// Calls body(i, thread) once for every i in [0, count), spread over
/// parallelThreadCount(count, threads) threads (the calling thread among them, as
/// thread 0), indices handed out one at a time so that uneven work balances. `thread` tells
/// a body which per-thread scratch state it may use (a local search's buffers): no two
/// bodies run on the same thread at once. The bodies must write disjoint results. Rethrows
/// the first exception a body threw, after every thread has stopped.
template <typename Body>
void parallelForOnThreads(std::size_t count, std::size_t threads, Body&& body) {
  threads = parallelThreadCount(count, threads);
  if (threads <= 1) {
    for (std::size_t i = 0; i < count; ++i) body(i, std::size_t{0});
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&](std::size_t thread) {
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        body(i, thread);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = count;
      }
    }
  };
  std::vector<std::thread> helpers;
  for (std::size_t t = 1; t < threads; ++t) helpers.emplace_back(work, t);
  work(0);
  for (std::thread& helper : helpers) helper.join();
  if (failure) std::rethrow_exception(failure);
}

/// Calls body(i) once for every i in [0, count), spread over the machine's hardware threads
/// (parallelForOnThreads on 0 threads). For the planner's independent visibility tests:
/// the bodies must write disjoint results. Rethrows the first exception a body threw,
/// after every thread has stopped.
template <typename Body>
void parallelFor(std::size_t count, Body&& body) {
  parallelForOnThreads(count, 0, [&body](std::size_t i, std::size_t) { body(i); });
}

/// parallelFor whose failure is the one a loop in order would have: rethrows what the body
/// of the lowest failing index threw (the others still run), so that a stage reports the
/// same error on any number of threads.
template <typename Body>
void parallelForInOrder(std::size_t count, Body&& body) {
  std::vector<std::exception_ptr> failures(count);
  parallelFor(count, [&](std::size_t i) {
    try {
      body(i);
    } catch (...) {
      failures[i] = std::current_exception();
    }
  });
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
}

}  // namespace kinematic_coverage::core

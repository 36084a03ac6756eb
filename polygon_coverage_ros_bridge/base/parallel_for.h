#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace kinematic_coverage::core {

/// Calls body(i) once for every i in [0, count), spread over the machine's hardware threads
/// (the calling thread among them), indices handed out one at a time so that uneven rows
/// (a triangle of pairs) balance. For the planner's independent visibility tests: the
/// bodies must write disjoint results. Rethrows the first exception a body threw, after
/// every thread has stopped.
template <typename Body>
void parallelFor(std::size_t count, Body&& body) {
  const std::size_t threads =
      std::min<std::size_t>(count, std::max(1u, std::thread::hardware_concurrency()));
  if (threads <= 1) {
    for (std::size_t i = 0; i < count; ++i) body(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&]() {
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        body(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = count;
      }
    }
  };
  std::vector<std::thread> helpers;
  for (std::size_t t = 1; t < threads; ++t) helpers.emplace_back(work);
  work();
  for (std::thread& helper : helpers) helper.join();
  if (failure) std::rethrow_exception(failure);
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

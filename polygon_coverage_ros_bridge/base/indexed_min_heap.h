#pragma once

#include <cstddef>
#include <limits>
#include <vector>

namespace kinematic_coverage::core {

/// A min-heap of the items 0 to size - 1 keyed by a cost, each item at most once, with
/// decrease-key: Dijkstra's queue without the stale entries of a lazy-deletion queue, so
/// that its size stays below the node count (the all-pairs routes of a visibility graph
/// run one Dijkstra per node). Four children per entry: fewer levels for the same compares.
class IndexedMinHeap {
 public:
  /// An empty heap for the items [0, size).
  explicit IndexedMinHeap(std::size_t size) : slot_(size, kAbsent) {}

  bool empty() const { return entries_.empty(); }

  /// Removes every item, in the time of the items queued.
  void clear() {
    for (const Entry& entry : entries_) slot_[static_cast<std::size_t>(entry.item)] = kAbsent;
    entries_.clear();
  }

  /// Inserts `item` with `cost`, or lowers its cost to `cost` when it is queued with a
  /// higher one (a higher cost for a queued item is ignored).
  void pushOrDecrease(int item, double cost) {
    std::size_t i = slot_[static_cast<std::size_t>(item)];
    if (i == kAbsent) {
      i = entries_.size();
      entries_.push_back({cost, item});
    } else if (cost < entries_[i].cost) {
      entries_[i].cost = cost;
    } else {
      return;
    }
    siftUp(i);
  }

  /// Removes and returns an item of least cost (the heap must not be empty).
  int popMin() {
    const int item = entries_.front().item;
    slot_[static_cast<std::size_t>(item)] = kAbsent;
    const Entry last = entries_.back();
    entries_.pop_back();
    if (!entries_.empty()) {
      entries_.front() = last;
      siftDown(0);
    }
    return item;
  }

 private:
  struct Entry {
    double cost;
    int item;
  };
  static constexpr std::size_t kArity = 4;
  static constexpr std::size_t kAbsent = std::numeric_limits<std::size_t>::max();

  void place(std::size_t i, const Entry& entry) {
    entries_[i] = entry;
    slot_[static_cast<std::size_t>(entry.item)] = i;
  }

  void siftUp(std::size_t i) {
    const Entry entry = entries_[i];
    while (i > 0) {
      const std::size_t parent = (i - 1) / kArity;
      if (entries_[parent].cost <= entry.cost) break;
      place(i, entries_[parent]);
      i = parent;
    }
    place(i, entry);
  }

  void siftDown(std::size_t i) {
    const Entry entry = entries_[i];
    const std::size_t size = entries_.size();
    for (;;) {
      const std::size_t first = i * kArity + 1;
      if (first >= size) break;
      std::size_t best = first;
      const std::size_t end = first + kArity < size ? first + kArity : size;
      for (std::size_t child = first + 1; child < end; ++child) {
        if (entries_[child].cost < entries_[best].cost) best = child;
      }
      if (entries_[best].cost >= entry.cost) break;
      place(i, entries_[best]);
      i = best;
    }
    place(i, entry);
  }

  std::vector<Entry> entries_;
  std::vector<std::size_t> slot_;  ///< per item, its entry, or kAbsent
};

}  // namespace kinematic_coverage::core

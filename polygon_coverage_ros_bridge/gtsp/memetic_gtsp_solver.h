#pragma once

#include <chrono>
#include <random>
#include <vector>

#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsp_local_search.h"

namespace kinematic_coverage::core {

/// Memetic GTSP heuristic after Gutin and Karapetyan (Natural Computing 9(1), 2010): a
/// population of locally optimal tours (cluster order + one node per cluster), children by
/// ordered crossover of the cluster orders or by a double-bridge mutation, each improved by
/// GtspLocalSearch (reinsertion with node choice, or-opt, 2-opt, cluster optimization by a
/// layered shortest path; with GtspOptions::focused_search starting from the child's new
/// edges), (mu + lambda) replacement among tours of distinct cost.
///
/// Why this design (measured, docs/BENCHMARKS_GTSP.md): with cluster neighbour lists and
/// don't-look bits one local search costs a few moves per cluster, so a population of up to
/// 100 tours can be evolved for dozens of generations within seconds; recombining cluster
/// orders is what separates near-optimal tours, and cluster optimization makes the node
/// choice exact for every order. On GTSPLIB this reaches 0 % mean gap on every symmetric
/// instance up to 89pcb442 in under 1 s and 0.05-0.25 % on 115rat575..217vm1084 in under
/// 10 s, i.e. the targets and GLNS's published gaps, so a GLNS-style adaptive large
/// neighbourhood search was not added. Path mode is native: the sequence has fixed start and
/// goal ends and no closing edge, so no sentinel costs are needed. The run stops after a
/// number of generations without improvement (deterministic for a seed, on any number of
/// threads: GtspOptions::threads); the time limit is only a safety cap.
class MemeticGtspSolver {
 public:
  /// instance must be valid (validateGtspInstance) and outlive the solver; a warm start in
  /// options must be a valid tour (validateGtspTour).
  MemeticGtspSolver(const GtspInstance& instance, const GtspOptions& options);

  /// Runs the algorithm and returns the best tour found.
  GtspSolution solve();

 private:
  using Clock = std::chrono::steady_clock;
  struct Individual {
    std::vector<int> sequence;
    double cost = 0.0;
  };

  /// A random interior order (nodes chosen later by cluster optimization).
  std::vector<int> randomSequence();
  /// The warm start as a sequence with fixed ends.
  std::vector<int> sequenceFromTour(const std::vector<int>& tour) const;
  /// Ordered crossover (OX) of the parents' interior cluster orders.
  std::vector<int> crossover(const std::vector<int>& first, const std::vector<int>& second);
  /// Double bridge: swaps two consecutive random segments of the interior.
  void mutate(std::vector<int>& sequence);
  /// Sets focus_ to the clusters at either end of an edge of `child` that neither parent
  /// has (`second` null: a mutation of `first`): the only places where a child of locally
  /// optimal parents can be improved by a local move, so local search starts there.
  void markNewEdges(const std::vector<int>& child, const std::vector<int>& first,
                    const std::vector<int>* second);
  /// Index of the better of two random population members.
  std::size_t tournament(const std::vector<Individual>& population);
  std::size_t randomIndex(std::size_t bound) { return bound <= 1 ? 0 : random_() % bound; }
  int clusterOf(int node) const { return searches_.front().clusterOf(node); }
  GtspSolution toSolution(const Individual& individual) const;
  static bool byCost(const Individual& a, const Individual& b) { return a.cost < b.cost; }
  /// True when no member's cost equals `cost` (relatively): the population keeps one
  /// individual per cost.
  static bool distinctCost(const std::vector<Individual>& members, double cost);
  /// Improves every individual by local search (with focuses[i] when given), on
  /// GtspOptions::threads threads, each with its own GtspLocalSearch.
  void improveAll(std::vector<Individual>& individuals,
                  const std::vector<std::vector<char>>* focuses = nullptr);
  /// The warm start, if any, and locally optimised random individuals of distinct costs,
  /// cheapest first (one only for a `trivial` instance, which has one order).
  std::vector<Individual> initialPopulation(int population_size, bool trivial);
  /// One generation: children by crossover or mutation, locally optimised, and the best
  /// of parents and children with distinct costs kept, cheapest first.
  void nextGeneration(std::vector<Individual>& population, int population_size);

  const GtspInstance& instance_;
  GtspOptions options_;
  int anchor_cluster_ = -1;
  std::mt19937 random_;
  std::vector<GtspLocalSearch> searches_;  ///< one per thread, identical but for scratch state
  Clock::time_point deadline_;
  std::vector<int> first_successor_;   ///< per cluster, the next cluster in the first parent
  std::vector<int> second_successor_;  ///< the same in the second parent
  std::vector<char> focus_;
};

}  // namespace kinematic_coverage::core

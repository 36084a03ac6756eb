#include "polygon_coverage_ros_bridge/gtsp/memetic_gtsp_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "polygon_coverage_ros_bridge/base/parallel_for.h"

namespace kinematic_coverage::core {
namespace {

/// Default number of cluster neighbours that local search moves consider.
constexpr int kDefaultNeighbourCount = 20;
/// Share of children made by crossover (the others by mutation of one parent).
constexpr double kCrossoverShare = 0.8;
/// Population when not given: kPopulationBase + clusters / 2, at most
/// GtspOptions::max_population.
constexpr int kPopulationBase = 10;
/// Generations without improvement before stopping, when not given: kStallBase +
/// clusters / 3, clamped to [kMinStallGenerations, kMaxStallGenerations].
constexpr int kStallBase = 20;
constexpr int kMinStallGenerations = 30;
constexpr int kMaxStallGenerations = 80;

/// Clusters above which GtspOptions::focused_search applies: smaller instances keep the
/// full search, which is cheap there and finds the optimum of every small test instance.
constexpr int kFocusedSearchMinClusters = 50;
/// Tours whose costs differ by less than this (relative) count as equal: duplicates in the
/// population, and no improvement for the stopping rule.
constexpr double kRelativeCostTolerance = 1e-9;
/// Longest time limit honoured (seconds, about 11 days): keeps the deadline representable.
constexpr double kMaxTimeLimit = 1e6;

/// The cycle's anchor: its smallest cluster (cheapest cluster optimization).
int chooseAnchor(const GtspInstance& instance) {
  if (instance.isPath()) return -1;
  int anchor = 0;
  for (std::size_t c = 1; c < instance.clusters.size(); ++c) {
    if (instance.clusters[c].size() < instance.clusters[anchor].size())
      anchor = static_cast<int>(c);
  }
  return anchor;
}

}  // namespace

MemeticGtspSolver::MemeticGtspSolver(const GtspInstance& instance, const GtspOptions& options)
    : instance_(instance),
      options_(options),
      anchor_cluster_(chooseAnchor(instance)),
      random_(options.seed) {
  const std::size_t threads =
      parallelThreadCount(std::numeric_limits<std::size_t>::max(),
                          static_cast<std::size_t>(std::max(options.threads, 0)));
  searches_.reserve(threads);
  searches_.emplace_back(
      instance, anchor_cluster_,
      options.neighbour_count > 0 ? options.neighbour_count : kDefaultNeighbourCount);
  while (searches_.size() < threads) searches_.push_back(searches_.front());
}

void MemeticGtspSolver::improveAll(std::vector<Individual>& individuals,
                                   const std::vector<std::vector<char>>* focuses) {
  parallelForOnThreads(
      individuals.size(), searches_.size(), [&](std::size_t i, std::size_t thread) {
        individuals[i].cost = searches_[thread].improve(
            individuals[i].sequence, deadline_, focuses != nullptr ? &(*focuses)[i] : nullptr);
      });
}

std::vector<int> MemeticGtspSolver::randomSequence() {
  std::vector<int> interior;
  for (int c = 0; c < static_cast<int>(instance_.clusters.size()); ++c) {
    if (c != anchor_cluster_ && c != instance_.start_cluster && c != instance_.goal_cluster) {
      interior.push_back(instance_.clusters[c][randomIndex(instance_.clusters[c].size())]);
    }
  }
  for (std::size_t i = interior.size(); i > 1; --i)
    std::swap(interior[i - 1], interior[randomIndex(i)]);
  std::vector<int> sequence;
  if (instance_.isPath()) {
    sequence.push_back(instance_.clusters[instance_.start_cluster].front());
    sequence.insert(sequence.end(), interior.begin(), interior.end());
    sequence.push_back(instance_.clusters[instance_.goal_cluster].front());
  } else {
    const int anchor = instance_.clusters[anchor_cluster_].front();
    sequence.push_back(anchor);
    sequence.insert(sequence.end(), interior.begin(), interior.end());
    sequence.push_back(anchor);
  }
  return sequence;
}

std::vector<int> MemeticGtspSolver::sequenceFromTour(const std::vector<int>& tour) const {
  if (instance_.isPath()) return tour;
  std::size_t first = 0;
  while (clusterOf(tour[first]) != anchor_cluster_) ++first;
  std::vector<int> sequence;
  for (std::size_t i = 0; i <= tour.size(); ++i)
    sequence.push_back(tour[(first + i) % tour.size()]);
  return sequence;
}

std::vector<int> MemeticGtspSolver::crossover(const std::vector<int>& first,
                                              const std::vector<int>& second) {
  const std::size_t interior = first.size() - 2;
  std::size_t a = randomIndex(interior);
  std::size_t b = randomIndex(interior);
  if (a > b) std::swap(a, b);
  std::vector<int> child(first.size(), -1);
  child.front() = first.front();
  child.back() = first.back();
  std::vector<bool> used(instance_.clusters.size(), false);
  for (std::size_t i = a; i <= b; ++i) {
    child[i + 1] = first[i + 1];
    used[clusterOf(first[i + 1])] = true;
  }
  std::size_t source = (b + 1) % interior;
  for (std::size_t k = 0; k < interior - (b - a + 1); ++k) {
    const std::size_t target = (b + 1 + k) % interior;
    while (used[clusterOf(second[source + 1])]) source = (source + 1) % interior;
    child[target + 1] = second[source + 1];
    used[clusterOf(second[source + 1])] = true;
  }
  return child;
}

void MemeticGtspSolver::mutate(std::vector<int>& sequence) {
  const std::size_t interior = sequence.size() - 2;
  if (interior < 2) return;
  if (interior < 4) {
    std::swap(sequence[1 + randomIndex(interior)], sequence[1 + randomIndex(interior)]);
    return;
  }
  std::size_t cuts[3] = {1 + randomIndex(interior - 1), 1 + randomIndex(interior - 1),
                         1 + randomIndex(interior - 1)};
  std::sort(cuts, cuts + 3);
  // Interior [0, c0) [c0, c1) [c1, c2) [c2, end) becomes [0, c0) [c1, c2) [c0, c1) [c2, end).
  std::rotate(sequence.begin() + 1 + static_cast<std::ptrdiff_t>(cuts[0]),
              sequence.begin() + 1 + static_cast<std::ptrdiff_t>(cuts[1]),
              sequence.begin() + 1 + static_cast<std::ptrdiff_t>(cuts[2]));
}

void MemeticGtspSolver::markNewEdges(const std::vector<int>& child, const std::vector<int>& first,
                                     const std::vector<int>* second) {
  const std::size_t m = instance_.clusters.size();
  auto successors = [&](const std::vector<int>& sequence, std::vector<int>& successor) {
    successor.assign(m, -1);
    for (std::size_t i = 0; i + 1 < sequence.size(); ++i) {
      successor[clusterOf(sequence[i])] = clusterOf(sequence[i + 1]);
    }
  };
  successors(first, first_successor_);
  if (second != nullptr) {
    successors(*second, second_successor_);
  } else {
    second_successor_ = first_successor_;
  }
  focus_.assign(m, 0);
  for (std::size_t i = 0; i + 1 < child.size(); ++i) {
    const int from = clusterOf(child[i]);
    const int to = clusterOf(child[i + 1]);
    if (first_successor_[from] != to && second_successor_[from] != to) {
      focus_[from] = 1;
      focus_[to] = 1;
    }
  }
}

std::size_t MemeticGtspSolver::tournament(const std::vector<Individual>& population) {
  const std::size_t a = randomIndex(population.size());
  const std::size_t b = randomIndex(population.size());
  return population[a].cost <= population[b].cost ? a : b;
}

GtspSolution MemeticGtspSolver::toSolution(const Individual& individual) const {
  GtspSolution solution;
  solution.nodes = individual.sequence;
  if (!instance_.isPath()) solution.nodes.pop_back();
  solution.cost = gtspTourCost(instance_, solution.nodes);
  return solution;
}

bool MemeticGtspSolver::distinctCost(const std::vector<Individual>& members, double cost) {
  for (const Individual& other : members) {
    if (std::abs(other.cost - cost) <= kRelativeCostTolerance * std::max(1.0, std::abs(cost))) {
      return false;
    }
  }
  return true;
}

std::vector<MemeticGtspSolver::Individual> MemeticGtspSolver::initialPopulation(int population_size,
                                                                                bool trivial) {
  std::vector<Individual> population;
  if (!options_.warm_start.empty()) {
    std::vector<Individual> warm = {{sequenceFromTour(options_.warm_start), 0.0}};
    improveAll(warm);
    population.push_back(std::move(warm.front()));
  }
  // Random orders in batches of as many as places are left, improved on every thread and
  // taken in order as one at a time would be: the random generator is left as if only the
  // orders taken had been drawn, so the run does not depend on the thread count.
  const int max_attempts = trivial ? 1 : 3 * population_size;
  int attempts = 0;
  while (attempts < max_attempts && static_cast<int>(population.size()) < population_size &&
         (population.empty() || Clock::now() < deadline_)) {
    const int batch =
        std::min(population_size - static_cast<int>(population.size()), max_attempts - attempts);
    std::vector<Individual> drawn(static_cast<std::size_t>(batch));
    std::vector<std::mt19937> random_after(drawn.size());
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      drawn[i].sequence = randomSequence();
      random_after[i] = random_;
    }
    improveAll(drawn);
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      ++attempts;
      if (distinctCost(population, drawn[i].cost)) population.push_back(std::move(drawn[i]));
      if (static_cast<int>(population.size()) == population_size) {
        random_ = random_after[i];
        break;
      }
    }
  }
  std::sort(population.begin(), population.end(), byCost);
  return population;
}

void MemeticGtspSolver::nextGeneration(std::vector<Individual>& population, int population_size) {
  const int m = static_cast<int>(instance_.clusters.size());
  const bool focused = options_.focused_search && m > kFocusedSearchMinClusters;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Every child is drawn from the parents first (the random draws in one order), then all
  // are improved at once.
  std::vector<Individual> children(static_cast<std::size_t>(population_size));
  std::vector<std::vector<char>> focuses(focused ? children.size() : 0);
  for (std::size_t k = 0; k < children.size(); ++k) {
    Individual& child = children[k];
    const std::size_t parent = tournament(population);
    const std::vector<int>* second = nullptr;
    if (population.size() >= 2 && unit(random_) < kCrossoverShare) {
      second = &population[tournament(population)].sequence;
      child.sequence = crossover(population[parent].sequence, *second);
    } else {
      child.sequence = population[parent].sequence;
      mutate(child.sequence);
    }
    if (focused) {
      markNewEdges(child.sequence, population[parent].sequence, second);
      focuses[k] = focus_;
    }
  }
  improveAll(children, focused ? &focuses : nullptr);
  std::vector<Individual> pool = population;
  for (Individual& child : children) pool.push_back(std::move(child));
  std::stable_sort(pool.begin(), pool.end(), byCost);
  population.clear();
  for (Individual& individual : pool) {
    if (static_cast<int>(population.size()) < population_size &&
        distinctCost(population, individual.cost)) {
      population.push_back(std::move(individual));
    }
  }
}

GtspSolution MemeticGtspSolver::solve() {
  // A NaN, negative or huge limit must not overflow the clock: clamp it to [0, kMaxTimeLimit].
  const double limit =
      options_.time_limit_s > 0.0 ? std::min(options_.time_limit_s, kMaxTimeLimit) : 0.0;
  deadline_ = Clock::now() +
              std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limit));
  const int m = static_cast<int>(instance_.clusters.size());
  const int population_size =
      options_.population_size > 0
          ? options_.population_size
          : std::max(1, std::min(kPopulationBase + m / 2, options_.max_population));
  const int stall_limit =
      options_.stall_generations > 0
          ? options_.stall_generations
          : std::clamp(kStallBase + m / 3, kMinStallGenerations, kMaxStallGenerations);
  const bool trivial = static_cast<int>(randomSequence().size()) <= 3;
  std::vector<Individual> population = initialPopulation(population_size, trivial);
  if (trivial) return toSolution(population.front());
  int stall = 0;
  // The best cost after each generation, for the gain over the last stall_limit ones.
  std::vector<double> best_costs = {population.front().cost};
  while (stall < stall_limit && Clock::now() < deadline_) {
    const double previous_best = population.front().cost;
    nextGeneration(population, population_size);
    const double best = population.front().cost;
    if (best < previous_best - kRelativeCostTolerance * std::max(1.0, previous_best)) {
      stall = 0;
    } else {
      ++stall;
    }
    best_costs.push_back(best);
    const std::size_t window = static_cast<std::size_t>(stall_limit);
    if (options_.min_stall_gain > 0.0 && best_costs.size() > window &&
        best_costs[best_costs.size() - 1 - window] - best < options_.min_stall_gain * best) {
      break;
    }
  }
  GtspSolution solution = toSolution(population.front());
  solution.time_capped = Clock::now() >= deadline_;
  return solution;
}

}  // namespace kinematic_coverage::core

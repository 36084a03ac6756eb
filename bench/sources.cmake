# Benchmark programs: each prints a table; figures and commands in docs/BENCHMARKS.md.
include(bench/coverage/sources.cmake OPTIONAL)
include(bench/gtsp/sources.cmake OPTIONAL)
include(bench/planner/sources.cmake OPTIONAL)
include(bench/replanning/sources.cmake OPTIONAL)
include(bench/smoothing/sources.cmake OPTIONAL)
include(bench/soak/sources.cmake OPTIONAL)
include(bench/trajectory/sources.cmake OPTIONAL)

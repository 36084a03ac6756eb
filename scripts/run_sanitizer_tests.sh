#!/usr/bin/env bash
# The unit-test suite under AddressSanitizer + UndefinedBehaviorSanitizer:
# installs clang, builds every gtest suite and coverage_tool with KC_SANITIZE=ON into
# ./build-asan (or $BUILD_DIR) and runs them; any finding (memory error, leak, undefined
# behaviour) fails the test that hit it. About 16 minutes on 2 cores: 10 to build, 5 to 7
# to run.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
source "$root/scripts/sanitizer_env.sh"
build_dir=${BUILD_DIR:-$root/build-asan}
"$root/scripts/install_dependencies.sh" --clang
echo "== build (clang, ASan + UBSan) in $build_dir"
kc_configure_sanitized "$build_dir"
cmake --build "$build_dir" -j"${JOBS:-$(nproc)}" --target tests kinematic_coverage_coverage_tool >/dev/null
echo "== unit tests under the sanitizers"
cd "$build_dir"
ctest -R gtest --output-on-failure -j"${JOBS:-$(nproc)}"

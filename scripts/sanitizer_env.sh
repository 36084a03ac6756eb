# Sourced by scripts/run_fuzzers.sh and scripts/run_sanitizer_tests.sh: the clang build
# with AddressSanitizer and UndefinedBehaviorSanitizer (KC_SANITIZE=ON) and the runtime
# options under which any finding fails the run.
kc_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export LSAN_OPTIONS=suppressions=$kc_root/cmake/lsan_suppressions.txt:print_suppressions=0

# kc_configure_sanitized BUILD_DIR [CMAKE_ARGS...]: configures a RelWithDebInfo clang build
# with the sanitizers; its log goes to BUILD_DIR.configure.log.
kc_configure_sanitized() {
  local build_dir=$1
  shift
  CC=clang CXX=clang++ cmake -S "$kc_root" -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DKC_SANITIZE=ON "$@" >"$build_dir.configure.log" 2>&1 || {
    cat "$build_dir.configure.log"
    return 1
  }
}

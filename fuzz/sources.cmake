# libFuzzer targets (KC_FUZZ=ON, Clang only). Each one is a LLVMFuzzerTestOneInput over
# a public entry point of the core; libFuzzer's main comes from -fsanitize=fuzzer.
# Seed corpora are in fuzz/corpus/<target>/. Build with the `fuzzers` target.
add_custom_target(fuzzers)

function(kc_add_fuzzer name)
  kc_add_executable(${name} fuzz/${name}.cpp)
  target_link_libraries(${PROJECT_NAME}_${name} PRIVATE ${PROJECT_NAME}_core)
  target_compile_options(${PROJECT_NAME}_${name} PRIVATE -Wall -Wextra)
  target_link_options(${PROJECT_NAME}_${name} PRIVATE -fsanitize=fuzzer)
  add_dependencies(fuzzers ${PROJECT_NAME}_${name})
endfunction()

kc_add_fuzzer(mission_file_fuzzer)
kc_add_fuzzer(gtsplib_fuzzer)
kc_add_fuzzer(corner_smoothing_fuzzer)
kc_add_fuzzer(coverage_preserving_fuzzer)
kc_add_fuzzer(planner_fuzzer)

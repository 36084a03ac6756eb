# kc_add_gtest(NAME src... [LIBRARIES kc_stage...]): a gtest executable linked to the
# named stage libraries (default: the whole core), registered with ctest
# through catkin when it is present (env wrapping, `tests` target) and plainly otherwise.
if(NOT catkin_FOUND)
  find_package(GTest REQUIRED)
  enable_testing()
  if(NOT TARGET tests)
    add_custom_target(tests)
  endif()
endif()

function(kc_add_gtest name)
  cmake_parse_arguments(ARG "" "" "LIBRARIES" ${ARGN})
  if(NOT ARG_LIBRARIES)
    set(ARG_LIBRARIES kinematic_coverage_core)
  endif()
  if(catkin_FOUND)
    catkin_add_gtest(${name} ${ARG_UNPARSED_ARGUMENTS})
    target_link_libraries(${name} ${GTEST_MAIN_LIBRARIES})
  else()
    add_executable(${name} EXCLUDE_FROM_ALL ${ARG_UNPARSED_ARGUMENTS})
    target_link_libraries(${name} GTest::gtest GTest::gtest_main)
    add_test(NAME ${name} COMMAND ${name})
    set_tests_properties(${name} PROPERTIES TIMEOUT 900)
    add_dependencies(tests ${name})
  endif()
  target_link_libraries(${name} ${ARG_LIBRARIES})
  target_compile_definitions(${name} PRIVATE
    KC_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    KC_BENCH_DATA_DIR="${PROJECT_SOURCE_DIR}/bench/data"
    KC_TOOL_PATH="${CMAKE_RUNTIME_OUTPUT_DIRECTORY}/coverage_tool")
endfunction()

# kc_add_gtest(NAME src... [LIBRARIES kc_stage...]): a gtest executable ${PROJECT_NAME}_NAME
# linked to the named stage libraries (default: the whole core), registered with ctest
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
    set(ARG_LIBRARIES ${PROJECT_NAME}_core)
  endif()
  # The target and its executable carry the package's name (no clash with another
  # package's test_planner in a workspace; catkin runs a gtest by its target's name); a
  # plain-CMake ctest test keeps the short name.
  set(target ${PROJECT_NAME}_${name})
  if(catkin_FOUND)
    catkin_add_gtest(${target} ${ARG_UNPARSED_ARGUMENTS})
    target_link_libraries(${target} ${GTEST_MAIN_LIBRARIES})
  else()
    add_executable(${target} EXCLUDE_FROM_ALL ${ARG_UNPARSED_ARGUMENTS})
    target_link_libraries(${target} GTest::gtest GTest::gtest_main)
    add_test(NAME ${name} COMMAND ${target})
    set_tests_properties(${name} PROPERTIES TIMEOUT 900)
    add_dependencies(tests ${target})
  endif()
  target_link_libraries(${target} ${ARG_LIBRARIES})
  target_compile_definitions(${target} PRIVATE
    KC_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    KC_BENCH_DATA_DIR="${PROJECT_SOURCE_DIR}/bench/data"
    KC_TOOL_PATH="${CMAKE_RUNTIME_OUTPUT_DIRECTORY}/coverage_tool")
endfunction()

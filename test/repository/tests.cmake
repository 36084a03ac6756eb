# Repository-wide checks: nothing outside the repository is used, the figures in docs/
# are what their commands print (scripts/doc_figures.py; CI reruns the ci= rows), every
# key of package.xml is a rosdep key for Noetic on focal and for bookworm, catkin_lint -W2
# finds nothing, and every stage includes only the stages of its floor
# (scripts/stage_graph.py, docs/ARCHITECTURE.md).
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME self_contained COMMAND ${PROJECT_SOURCE_DIR}/test/repository/self_contained_test.sh
  ${PROJECT_SOURCE_DIR})
if(KINEMATIC_COVERAGE_BENCHMARKS)
  add_test(NAME doc_figures COMMAND ${Python3_EXECUTABLE}
    ${PROJECT_SOURCE_DIR}/scripts/doc_figures.py check --ci --build-dir ${CMAKE_BINARY_DIR})
  set_tests_properties(doc_figures PROPERTIES TIMEOUT 1500)
endif()
add_test(NAME doc_figures_checker COMMAND ${Python3_EXECUTABLE}
  ${PROJECT_SOURCE_DIR}/test/repository/doc_figures_test.py)
add_test(NAME rosdep_keys COMMAND ${Python3_EXECUTABLE}
  ${PROJECT_SOURCE_DIR}/test/repository/rosdep_keys_test.py)
add_test(NAME catkin_lint COMMAND ${PROJECT_SOURCE_DIR}/test/repository/catkin_lint_test.sh
  ${PROJECT_SOURCE_DIR})
set_tests_properties(catkin_lint PROPERTIES SKIP_RETURN_CODE 77)
add_test(NAME stage_graph COMMAND ${Python3_EXECUTABLE}
  ${PROJECT_SOURCE_DIR}/scripts/stage_graph.py --check)
add_test(NAME stage_graph_checker COMMAND ${Python3_EXECUTABLE}
  ${PROJECT_SOURCE_DIR}/test/repository/stage_graph_test.py)
# No function of the core over 80 lines (clang-tidy's readability-function-size), where
# this build's compile_commands.json is the package's own (not in a catkin workspace).
if(KINEMATIC_COVERAGE_TOP_LEVEL)
  add_test(NAME function_size COMMAND ${PROJECT_SOURCE_DIR}/scripts/check_function_size.sh
    ${CMAKE_BINARY_DIR})
  set_tests_properties(function_size PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 900)
endif()
# Each parameter's name is a literal of one product file, the parameter schema.
add_test(NAME parameter_literals COMMAND ${Python3_EXECUTABLE}
  ${PROJECT_SOURCE_DIR}/test/repository/parameter_literals_test.py)
# Figures stated in prose (README.md, docs/*.md) are checked through a marker that ties each
# to a table cell, a setting or a constant, or computed by a document's generator; the rest
# may only fall (scripts/prose_figures.py; the limit is today's unchecked count).
add_test(NAME prose_figures COMMAND ${Python3_EXECUTABLE}
  ${PROJECT_SOURCE_DIR}/scripts/prose_figures.py --limit 3)
add_test(NAME prose_figures_checker COMMAND ${Python3_EXECUTABLE}
  ${PROJECT_SOURCE_DIR}/test/repository/prose_figures_test.py)
# The GUI tests (test/ros) start rviz again only after its known start-up abort.
add_test(NAME rviz_start_abort COMMAND ${Python3_EXECUTABLE}
  ${PROJECT_SOURCE_DIR}/test/ros/rviz_start_abort_test.py)

# kc_add_stage_library(NAME SOURCES src... [DEPENDS kc_other...] [CGAL])
# A static library for one pipeline stage of the ROS-free core. CGAL is linked privately,
# so that headers seen by nodes stay free of it and only the stages that need it pay its
# compile cost.
set(KC_STAGE_LIBRARIES "")
function(kc_add_stage_library name)
  cmake_parse_arguments(ARG "CGAL" "" "SOURCES;DEPENDS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>)
  target_compile_options(${name} PRIVATE -Wall -Wextra)
  target_link_libraries(${name} PUBLIC Eigen3::Eigen ${ARG_DEPENDS})
  if(ARG_CGAL)
    target_link_libraries(${name} PRIVATE CGAL::CGAL)
  endif()
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  set(KC_STAGE_LIBRARIES ${KC_STAGE_LIBRARIES} ${name} PARENT_SCOPE)
endfunction()

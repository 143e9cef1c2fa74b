# Shared settings for every wifislam target: warnings on, and the same defines everywhere.
function(wifislam_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
  target_compile_features(${target} PUBLIC cxx_std_20)
endfunction()

# Unity build (WIFISLAM_UNITY_BUILD) for a library, the wifislam program, the Python module or a
# test suite. A source that must stay its own unit (CGAL's long compiles) sets
# SKIP_UNITY_BUILD_INCLUSION.
function(wifislam_unity_build target)
  if(WIFISLAM_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON)
  endif()
endfunction()

# wifislam_library(<name> SOURCES ... DEPS ...): one library per folder (docs/layout.md).
function(wifislam_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  wifislam_target_defaults(${name})
  wifislam_unity_build(${name})
  set_property(GLOBAL APPEND PROPERTY WIFISLAM_LIBRARIES ${name})
endfunction()

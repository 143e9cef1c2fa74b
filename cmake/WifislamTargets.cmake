# Shared settings for every wifislam target: warnings on, and the same defines everywhere.
function(wifislam_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
  target_compile_features(${target} PUBLIC cxx_std_20)
endfunction()

# wifislam_library(<name> SOURCES ... DEPS ...): one library per folder (DESIGN.md, "Layout").
function(wifislam_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  wifislam_target_defaults(${name})
  set_property(GLOBAL APPEND PROPERTY WIFISLAM_LIBRARIES ${name})
endfunction()

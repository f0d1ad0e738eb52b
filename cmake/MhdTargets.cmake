# Helpers that give every MHD target the same language level and warning policy.
# Third-party headers come in as SYSTEM includes, so -Werror applies to our code only.

function(mhd_set_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wnon-virtual-dtor
    -Wcast-align -Wnull-dereference -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
  if(MHD_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# mhd_add_library(mhd_<layer> SOURCES ... [DEPS ...] [PRIVATE_DEPS ...]) defines target
# mhd_<layer> and its alias mhd::<layer>.
# One library per engine layer. Its include root is engine/, so code includes
# "collision/mesh_bvh.h"; a layer that is not in DEPS cannot be linked, which makes a
# wrong-way dependency a build error.
function(mhd_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  if(ARG_SOURCES)
    add_library(${name} STATIC ${ARG_SOURCES})
    target_include_directories(${name} PUBLIC "${PROJECT_SOURCE_DIR}/engine")
    target_link_libraries(${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
    set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    mhd_set_warnings(${name})
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE "${PROJECT_SOURCE_DIR}/engine")
    target_link_libraries(${name} INTERFACE ${ARG_DEPS})
  endif()
  string(REGEX REPLACE "^mhd_" "" short "${name}")
  add_library(mhd::${short} ALIAS ${name})
endfunction()

# mhd_add_executable(<name> SOURCES ... [DEPS ...])
function(mhd_add_executable name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
  mhd_set_warnings(${name})
endfunction()

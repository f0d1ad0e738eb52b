# Helpers that give every MHD target the same language level and warning policy.
# Third-party headers come in as SYSTEM includes, so -Werror applies to our code only.

include(MhdWarnings)

# mhd_add_library(mhd_<layer> SOURCES ... [DEPS ...] [PRIVATE_DEPS ...]) defines target
# mhd_<layer> and its alias mhd::<layer>.
# One library per engine layer. Its include root is engine/, so code includes
# "collision/mesh_bvh.h"; a layer that is not in DEPS cannot be linked, which makes a
# wrong-way dependency a build error. Each layer is part of the installed C++ API
# (cmake/MhdInstall.cmake): its headers go to <includedir>/mhd/engine/<layer>/ and the
# target is exported as MHD::<layer>.
function(mhd_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  if(ARG_SOURCES)
    add_library(${name} STATIC ${ARG_SOURCES})
    target_include_directories(${name} PUBLIC "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/engine>")
    target_link_libraries(${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
    set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    mhd_set_warnings(${name})
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/engine>")
    target_link_libraries(${name} INTERFACE ${ARG_DEPS})
  endif()
  target_include_directories(${name} INTERFACE "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/mhd/engine>")
  string(REGEX REPLACE "^mhd_" "" short "${name}")
  add_library(mhd::${short} ALIAS ${name})
  set_target_properties(${name} PROPERTIES EXPORT_NAME ${short})
  set_property(GLOBAL APPEND PROPERTY MHD_ENGINE_LIBRARIES ${name})
endfunction()

# mhd_add_executable(<name> SOURCES ... [DEPS ...])
function(mhd_add_executable name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
  mhd_set_warnings(${name})
endfunction()

# Helpers that give every MHD target the same language level and warning policy.
# Third-party headers come in as SYSTEM includes, so -Werror applies to our code only.

include(MhdWarnings)

# mhd_add_library(mhd_<layer> SOURCES ... [DEPS ...] [PRIVATE_DEPS ...] [NOT_INSTALLED])
# defines target mhd_<layer> and its alias mhd::<layer>, for the layer in the calling
# folder engine/<layer>/. Code includes "collision/mesh_bvh.h" as before, but each layer has an
# include root of its own (mhd_layer_include_root): a target sees the headers of the
# layers it links, directly or through DEPS, and no others, so a wrong-way include fails
# to compile ("No such file"), header-only or not. A new layer needs nothing but this
# call. Each layer is part of the installed C++ API (cmake/MhdInstall.cmake): its headers
# go to <includedir>/mhd/engine/<layer>/ and the target is exported as MHD::<layer>;
# NOT_INSTALLED keeps a layer out of it (the viewer: its OSG and X11 would become every
# find_package(MHD) user's dependencies).
function(mhd_add_library name)
  cmake_parse_arguments(ARG "NOT_INSTALLED" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  mhd_layer_include_root(root)
  if(ARG_SOURCES)
    add_library(${name} STATIC ${ARG_SOURCES})
    target_include_directories(${name} PUBLIC "$<BUILD_INTERFACE:${root}>")
    target_link_libraries(${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
    set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    mhd_set_warnings(${name})
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE "$<BUILD_INTERFACE:${root}>")
    target_link_libraries(${name} INTERFACE ${ARG_DEPS})
  endif()
  string(REGEX REPLACE "^mhd_" "" short "${name}")
  add_library(mhd::${short} ALIAS ${name})
  # Every engine layer, installed or not (tests/layering checks what each may see).
  if(CMAKE_CURRENT_SOURCE_DIR MATCHES "/engine/[^/]+$")
    set_property(GLOBAL APPEND PROPERTY MHD_ENGINE_LAYERS ${name})
  endif()
  if(NOT ARG_NOT_INSTALLED)
    target_include_directories(${name} INTERFACE "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/mhd/engine>")
    set_target_properties(${name} PROPERTIES EXPORT_NAME ${short})
    set_property(GLOBAL APPEND PROPERTY MHD_ENGINE_LIBRARIES ${name})
  endif()
endfunction()

# mhd_layer_include_root(<out-var>): for the calling folder .../<layer>/ (an engine layer,
# or a library folder under tools/), the folder ${PROJECT_BINARY_DIR}/layer_include/<layer>/
# holding one entry, <layer>, a symbolic link to the calling folder. Made at configure
# time, so the source layout and the include spelling ("<layer>/<file>.h") stay as they
# are. Both libraries of one folder share the root.
function(mhd_layer_include_root out_var)
  cmake_path(GET CMAKE_CURRENT_SOURCE_DIR FILENAME layer)
  set(root "${PROJECT_BINARY_DIR}/layer_include/${layer}")
  set(link "${root}/${layer}")
  set(target "")
  if(IS_SYMLINK "${link}")
    file(READ_SYMLINK "${link}" target)
  endif()
  if(NOT target STREQUAL CMAKE_CURRENT_SOURCE_DIR)
    file(MAKE_DIRECTORY "${root}")
    file(REMOVE "${link}")
    file(CREATE_LINK "${CMAKE_CURRENT_SOURCE_DIR}" "${link}" SYMBOLIC)
  endif()
  set(${out_var} "${root}" PARENT_SCOPE)
endfunction()

# mhd_add_executable(<name> SOURCES ... [DEPS ...])
function(mhd_add_executable name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
  mhd_set_warnings(${name})
endfunction()

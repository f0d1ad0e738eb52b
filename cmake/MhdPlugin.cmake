# Building MHD plugins: shared libraries that speak the plugin ABI
# (plugins/include/mhd/plugin_abi.h, docs/plugins.md).
#
# mhd_add_plugin(NAME <name> KIND <device|tracker|base|display> SOURCES ...
#                [DEPS ...] [OUTPUT_DIRECTORY <dir>] [NO_INSTALL])
# builds the MODULE library libmhd_<name>.so (target mhd_<name>) into
# ${MHD_PLUGIN_BUILD_DIR} (or OUTPUT_DIRECTORY), where the host's search path finds it.
# Symbols are hidden except the entry point; warnings are errors as for all MHD code.
# The sources see MHD_PLUGIN_NAME ("<name>") and MHD_PLUGIN_KIND (MHD_KIND_<KIND>) so
# the table and the file name cannot disagree. Installed to ${MHD_PLUGIN_INSTALL_DIR}
# unless NO_INSTALL (test plugins).
include_guard(GLOBAL)

set(MHD_PLUGIN_INCLUDE_DIR "${CMAKE_CURRENT_LIST_DIR}/../plugins/include")
cmake_path(NORMAL_PATH MHD_PLUGIN_INCLUDE_DIR)
file(STRINGS "${MHD_PLUGIN_INCLUDE_DIR}/mhd/plugin_abi.h" _mhd_abi_line
     REGEX "^#define MHD_PLUGIN_ABI_VERSION [0-9]+u?$")
string(REGEX REPLACE "^#define MHD_PLUGIN_ABI_VERSION ([0-9]+)u?$" "\\1" MHD_PLUGIN_ABI_VERSION "${_mhd_abi_line}")
if(NOT MHD_PLUGIN_ABI_VERSION MATCHES "^[0-9]+$")
  message(FATAL_ERROR "cannot read MHD_PLUGIN_ABI_VERSION from plugin_abi.h")
endif()
# The ABI version is part of the folder, so a host only ever sees plugins of its ABI.
set(MHD_PLUGIN_SUBDIR "mhd/plugins-abi${MHD_PLUGIN_ABI_VERSION}")
set(MHD_PLUGIN_BUILD_DIR "${CMAKE_BINARY_DIR}/lib/${MHD_PLUGIN_SUBDIR}")
set(MHD_PLUGIN_INSTALL_DIR "lib/${MHD_PLUGIN_SUBDIR}")

install(FILES "${MHD_PLUGIN_INCLUDE_DIR}/mhd/plugin_abi.h" DESTINATION include/mhd)

function(mhd_add_plugin)
  cmake_parse_arguments(ARG "NO_INSTALL" "NAME;KIND;OUTPUT_DIRECTORY" "SOURCES;DEPS" ${ARGN})
  if(NOT ARG_NAME MATCHES "^[A-Za-z0-9_-]+$")
    message(FATAL_ERROR "mhd_add_plugin: NAME '${ARG_NAME}' must be letters, digits, '_' and '-'")
  endif()
  set(kinds device tracker base display)
  if(NOT ARG_KIND IN_LIST kinds)
    message(FATAL_ERROR "mhd_add_plugin(${ARG_NAME}): KIND must be one of ${kinds}, not '${ARG_KIND}'")
  endif()
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "mhd_add_plugin(${ARG_NAME}): no SOURCES")
  endif()
  if(NOT ARG_OUTPUT_DIRECTORY)
    set(ARG_OUTPUT_DIRECTORY "${MHD_PLUGIN_BUILD_DIR}")
  endif()

  set(target mhd_${ARG_NAME})
  add_library(${target} MODULE ${ARG_SOURCES})
  string(TOUPPER "${ARG_KIND}" kind_upper)
  target_compile_definitions(${target} PRIVATE
    MHD_PLUGIN_NAME="${ARG_NAME}" MHD_PLUGIN_KIND=MHD_KIND_${kind_upper})
  target_include_directories(${target} PRIVATE "${MHD_PLUGIN_INCLUDE_DIR}")
  target_link_libraries(${target} PRIVATE ${ARG_DEPS})
  set_target_properties(${target} PROPERTIES
    PREFIX "lib"
    OUTPUT_NAME "mhd_${ARG_NAME}"
    SUFFIX ".so"
    LIBRARY_OUTPUT_DIRECTORY "${ARG_OUTPUT_DIRECTORY}"
    C_VISIBILITY_PRESET hidden
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON
    MHD_PLUGIN_KIND "${ARG_KIND}")
  mhd_set_warnings(${target})
  # A symbol the plugin forgot to link is a build error, not a dlopen failure later.
  target_link_options(${target} PRIVATE "LINKER:--no-undefined")
  # Engine libraries a plugin links stay out of its dynamic table (only the entry is
  # exported), so they never interpose with the host's own copies.
  target_link_options(${target} PRIVATE "LINKER:--exclude-libs,ALL")
  if(NOT ARG_NO_INSTALL)
    install(TARGETS ${target} LIBRARY DESTINATION "${MHD_PLUGIN_INSTALL_DIR}")
  endif()
endfunction()

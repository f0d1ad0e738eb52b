# Building MHD plugins: shared libraries that speak the plugin ABI
# (plugins/include/mhd/plugin_abi.h, docs/plugins.md). The same file serves the MHD tree
# (through MhdPluginAbi.cmake) and out-of-tree projects (installed; find_package(MHD)
# includes it), which is why it needs only what both provide: MHD_PLUGIN_ABI_VERSION,
# MHD_PLUGIN_INSTALL_DIR and the target MHD::plugin_abi.
#
# mhd_add_plugin(NAME <name> KIND <device|tracker|base|display|link> SOURCES ...
#                [DEPS ...] [OUTPUT_DIRECTORY <dir>] [NO_INSTALL])
# builds the MODULE library libmhd_<name>.so (target mhd_<name>), from C or C++ sources,
# into ${MHD_PLUGIN_BUILD_DIR} (or OUTPUT_DIRECTORY), where the host's search path finds
# it. Symbols are hidden except the entry point; MHD's warnings are on (per language), and
# are errors when MHD_WERROR is ON (always in the MHD tree; off unless set out of tree).
# The sources see MHD_PLUGIN_NAME ("<name>") and MHD_PLUGIN_KIND (MHD_KIND_<KIND>) so
# the table and the file name cannot disagree. Installed to ${MHD_PLUGIN_INSTALL_DIR}
# (relative to the install prefix; the folder an mhd installed in the same prefix
# searches) unless NO_INSTALL (test plugins).
# No include guard: find_package(MHD) in several folders includes this file in each, and
# each folder needs the variables set here.
include("${CMAKE_CURRENT_LIST_DIR}/MhdWarnings.cmake")

foreach(_mhd_required MHD_PLUGIN_ABI_VERSION MHD_PLUGIN_INSTALL_DIR)
  if(NOT DEFINED ${_mhd_required})
    message(FATAL_ERROR "MhdPlugin.cmake: ${_mhd_required} is not set (use find_package(MHD), not include())")
  endif()
endforeach()
if(NOT TARGET MHD::plugin_abi)
  message(FATAL_ERROR "MhdPlugin.cmake: no target MHD::plugin_abi (use find_package(MHD), not include())")
endif()
set(MHD_PLUGIN_SUBDIR "mhd/plugins-abi${MHD_PLUGIN_ABI_VERSION}")
set(MHD_PLUGIN_BUILD_DIR "${CMAKE_BINARY_DIR}/lib/${MHD_PLUGIN_SUBDIR}")

function(mhd_add_plugin)
  cmake_parse_arguments(ARG "NO_INSTALL" "NAME;KIND;OUTPUT_DIRECTORY" "SOURCES;DEPS" ${ARGN})
  if(NOT ARG_NAME MATCHES "^[A-Za-z0-9_-]+$")
    message(FATAL_ERROR "mhd_add_plugin: NAME '${ARG_NAME}' must be letters, digits, '_' and '-'")
  endif()
  set(kinds device tracker base display link)
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
  target_link_libraries(${target} PRIVATE MHD::plugin_abi ${ARG_DEPS})
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
  # GCC makes the statics of inline and template functions (std::to_string's digit table,
  # used by the SDK's messages) GNU unique symbols, and a library holding one is never
  # unloaded by dlclose; the host unloads plugins it no longer uses.
  target_compile_options(${target} PRIVATE $<$<COMPILE_LANG_AND_ID:CXX,GNU>:-fno-gnu-unique>)
  # A symbol the plugin forgot to link is a build error, not a dlopen failure later.
  target_link_options(${target} PRIVATE "LINKER:--no-undefined")
  # Engine libraries a plugin links stay out of its dynamic table (only the entry is
  # exported), so they never interpose with the host's own copies.
  target_link_options(${target} PRIVATE "LINKER:--exclude-libs,ALL")
  if(NOT ARG_NO_INSTALL)
    install(TARGETS ${target} LIBRARY DESTINATION "${MHD_PLUGIN_INSTALL_DIR}")
    # The shipped plugins, for a target that builds a runnable mhd and nothing else.
    set_property(GLOBAL APPEND PROPERTY MHD_SHIPPED_PLUGINS ${target})
  endif()
endfunction()

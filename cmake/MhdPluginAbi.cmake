# The plugin ABI inside the MHD tree: reads MHD_PLUGIN_ABI_VERSION from
# plugins/include/mhd/plugin_abi.h, defines the header-only target mhd_plugin_abi
# (MHD::plugin_abi, exported with the package) and then mhd_add_plugin (MhdPlugin.cmake,
# the same file an installed MHD gives out-of-tree plugins).
include_guard(GLOBAL)
include(GNUInstallDirs)

set(MHD_PLUGIN_INCLUDE_DIR "${CMAKE_CURRENT_LIST_DIR}/../plugins/include")
cmake_path(NORMAL_PATH MHD_PLUGIN_INCLUDE_DIR)
file(STRINGS "${MHD_PLUGIN_INCLUDE_DIR}/mhd/plugin_abi.h" _mhd_abi_line
     REGEX "^#define MHD_PLUGIN_ABI_VERSION [0-9]+u?$")
string(REGEX REPLACE "^#define MHD_PLUGIN_ABI_VERSION ([0-9]+)u?$" "\\1" MHD_PLUGIN_ABI_VERSION "${_mhd_abi_line}")
if(NOT MHD_PLUGIN_ABI_VERSION MATCHES "^[0-9]+$")
  message(FATAL_ERROR "cannot read MHD_PLUGIN_ABI_VERSION from plugin_abi.h")
endif()
# The ABI version is part of the folder, so a host only ever sees plugins of its ABI.
set(MHD_PLUGIN_INSTALL_DIR "${CMAKE_INSTALL_LIBDIR}/mhd/plugins-abi${MHD_PLUGIN_ABI_VERSION}")

add_library(mhd_plugin_abi INTERFACE)
target_include_directories(mhd_plugin_abi INTERFACE
  "$<BUILD_INTERFACE:${MHD_PLUGIN_INCLUDE_DIR}>" "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
set_target_properties(mhd_plugin_abi PROPERTIES EXPORT_NAME plugin_abi)
add_library(MHD::plugin_abi ALIAS mhd_plugin_abi)

include(MhdPlugin)

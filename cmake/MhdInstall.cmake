# What `cmake --install` puts where (GNUInstallDirs; README.md, "Install"), in two
# components that cpack turns into two .deb packages (MhdPackaging.cmake):
#   runtime  bin/: mhd and the tools; <libdir>/mhd/plugins-abi<N>/: the plugins;
#            <libdir>/mhd/libmhd_sim_world.so: the simulated plugins' shared world;
#            share/mhd/: scenes (with scene.xsd), their meshes, DDS configs, plot scripts;
#            share/doc/mhd/: README, LICENSE, licensing notes and docs/.
#   dev      include/mhd/plugin_abi.h and include/mhd/engine/<layer>/*.h; the engine's
#            static libraries; <libdir>/cmake/MHD/ (find_package(MHD): MHD:: targets and
#            mhd_add_plugin); <libdir>/pkgconfig/mhd-plugin.pc.
# The engine is linked statically and mhd finds the plugins relative to itself
# (engine/plugin_host/plugin_search_path.h). The one shared library of ours is the
# simulated plugins' world (libs/sim_world), in <libdir>/mhd/: the simulated plugins
# and mhd (its tracker server) find it through a relative RUNPATH.
include_guard(GLOBAL)
include(CMakePackageConfigHelpers)

set(MHD_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/MHD")
set(MHD_INSTALL_DATADIR "${CMAKE_INSTALL_DATADIR}/mhd")

# ---- runtime: programs, plugins (mhd_add_plugin installs each), data, docs --------------
set(_mhd_programs mhd mhd-mesh-gen mhd-popthrough-stress mhd-proxy-bench mhd-load-bench mhd-server-bench
  mhd-hand-stability)
foreach(program IN LISTS _mhd_programs)
  if(TARGET ${program})  # partial builds (MHD_SKIP_DIRS, MHD_BUILD_BENCHMARKS=OFF) lack some
    install(TARGETS ${program} RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}" COMPONENT runtime)
  endif()
endforeach()

# Scenes name their meshes as ../assets/<file>, so both keep their relative places.
install(DIRECTORY scenes DESTINATION "${MHD_INSTALL_DATADIR}" COMPONENT runtime)
# The committed meshes only: assets/generated/ (50 MB, the benchmark and large scenes)
# is made by mhd-mesh-gen and stays in the build's source tree (README.md, "Install").
install(DIRECTORY assets DESTINATION "${MHD_INSTALL_DATADIR}" COMPONENT runtime
        PATTERN generated EXCLUDE)
install(DIRECTORY config DESTINATION "${MHD_INSTALL_DATADIR}" COMPONENT runtime)
install(DIRECTORY tools/plots/ DESTINATION "${MHD_INSTALL_DATADIR}/plots" COMPONENT runtime
        FILES_MATCHING PATTERN "*.py")
install(FILES README.md LICENSE CITATION.cff DESTINATION "${CMAKE_INSTALL_DOCDIR}" COMPONENT runtime)
install(DIRECTORY docs/ DESTINATION "${CMAKE_INSTALL_DOCDIR}" COMPONENT runtime)

# ---- dev: the plugin ABI, the engine as a C++ API, the CMake package, pkg-config --------
install(FILES "${MHD_PLUGIN_INCLUDE_DIR}/mhd/plugin_abi.h" "${MHD_PLUGIN_INCLUDE_DIR}/mhd/plugin_params.hpp"
              "${MHD_PLUGIN_INCLUDE_DIR}/mhd/plugin_sdk.hpp" "${MHD_PLUGIN_INCLUDE_DIR}/mhd/plugin_sdk_params.hpp" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/mhd"
        COMPONENT dev)
install(TARGETS mhd_plugin_abi EXPORT MHDPluginTargets COMPONENT dev)
install(EXPORT MHDPluginTargets NAMESPACE MHD:: DESTINATION "${MHD_INSTALL_CMAKEDIR}" COMPONENT dev)

# Each engine layer (mhd_add_library) with its headers, and the two system libraries it
# links through targets of ours (cmake/MhdDependencies.cmake: Debian has no CMake
# config for them, so they are exported with the paths found here).
get_property(_mhd_engine_libraries GLOBAL PROPERTY MHD_ENGINE_LIBRARIES)
foreach(library IN LISTS _mhd_engine_libraries)
  get_target_property(dir ${library} SOURCE_DIR)
  cmake_path(GET dir FILENAME layer)
  file(GLOB headers CONFIGURE_DEPENDS "${dir}/*.h")
  install(FILES ${headers} DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/mhd/engine/${layer}" COMPONENT dev)
endforeach()
set_target_properties(mhd_bullet PROPERTIES EXPORT_NAME bullet)
set_target_properties(mhd_xxhash PROPERTIES EXPORT_NAME xxhash)
install(TARGETS ${_mhd_engine_libraries} mhd_bullet mhd_xxhash EXPORT MHDEngineTargets
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT dev)
install(EXPORT MHDEngineTargets NAMESPACE MHD:: DESTINATION "${MHD_INSTALL_CMAKEDIR}" COMPONENT dev)

configure_package_config_file(cmake/MHDConfig.cmake.in "${PROJECT_BINARY_DIR}/cmake/MHDConfig.cmake"
  INSTALL_DESTINATION "${MHD_INSTALL_CMAKEDIR}"
  PATH_VARS CMAKE_INSTALL_BINDIR MHD_PLUGIN_INSTALL_DIR MHD_INSTALL_DATADIR)
# 0.x: a new minor version may break the API, so only the same minor version matches.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/cmake/MHDConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/cmake/MHDConfig.cmake" "${PROJECT_BINARY_DIR}/cmake/MHDConfigVersion.cmake"
              cmake/MhdPlugin.cmake cmake/MhdWarnings.cmake
        DESTINATION "${MHD_INSTALL_CMAKEDIR}" COMPONENT dev)

# pkg-config for plugins built without CMake. Relative to its own folder, so the file is
# right for any --prefix.
set(_mhd_pc_dir "${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig")
file(RELATIVE_PATH MHD_PC_PREFIX_FROM_PCFILEDIR "${_mhd_pc_dir}" "${CMAKE_INSTALL_PREFIX}")
string(REGEX REPLACE "/$" "" MHD_PC_PREFIX_FROM_PCFILEDIR "${MHD_PC_PREFIX_FROM_PCFILEDIR}")
file(RELATIVE_PATH MHD_PC_INCLUDEDIR "${CMAKE_INSTALL_PREFIX}" "${CMAKE_INSTALL_FULL_INCLUDEDIR}")
file(RELATIVE_PATH MHD_PC_PLUGINDIR "${CMAKE_INSTALL_PREFIX}" "${CMAKE_INSTALL_FULL_LIBDIR}/mhd/plugins-abi${MHD_PLUGIN_ABI_VERSION}")
configure_file(cmake/mhd-plugin.pc.in "${PROJECT_BINARY_DIR}/mhd-plugin.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/mhd-plugin.pc" DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig" COMPONENT dev)

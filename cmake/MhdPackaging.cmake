# cpack -G DEB (run in the build folder): Debian packages from the install components of
# MhdInstall.cmake and python/CMakeLists.txt, installed under /usr:
#   mhd      the runtime component; Depends computed by dpkg-shlibdeps (dpkg-dev) from the
#            shared libraries the programs and plugins load; Recommends what its scenes
#            and scripts use.
#   mhd-dev  the dev component (headers, static engine libraries, CMake package,
#            pkg-config); Depends on mhd of the same version and on the -dev packages of
#            the libraries the engine links, which MHDConfig.cmake finds.
#   python3-mhd  the Python module `mhd` (where the build has it); Depends on mhd of the
#            same version (its plugins), python3-numpy, and what dpkg-shlibdeps finds.
# Licence: mhd contains binaries that link CGAL's GPL-3.0+ code (docs/licensing.md), so
# the package as a whole is distributed under GPL-3.0-or-later terms; mhd-dev holds only
# BSD-3-Clause code.
include_guard(GLOBAL)

set(CPACK_PACKAGE_NAME mhd)
set(CPACK_PACKAGE_VENDOR "MHD authors")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_CONTACT "MHD authors (see CITATION.cff)")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_STRIP_FILES ON)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime dev)
if(TARGET mhd_python)
  list(APPEND CPACK_COMPONENTS_ALL python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-mhd)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_SHLIBDEPS ON)
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "mhd (= ${PROJECT_VERSION}), python3, python3-numpy")
  set(CPACK_DEBIAN_PYTHON_DESCRIPTION "${PROJECT_DESCRIPTION}: the Python module mhd")
endif()
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME mhd)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
# Used by what the package ships but not linked: the bunny scenes' mesh and the
# installed plot scripts' matplotlib. Recommended, so that a plain install has them.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "glmark2-data, python3-matplotlib")
set(CPACK_DEBIAN_RUNTIME_DESCRIPTION "${PROJECT_DESCRIPTION}: mhd, tools, plugins, scenes and docs")
set(CPACK_DEBIAN_DEV_PACKAGE_NAME mhd-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEV_DESCRIPTION "${PROJECT_DESCRIPTION}: engine headers and static libraries, plugin ABI, CMake package")
# The same list as MHDConfig.cmake's find_dependency calls, plus Bullet and xxHash, whose
# files the exported MHD::bullet and MHD::xxhash name.
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS
    "mhd (= ${PROJECT_VERSION}), libeigen3-dev, libtinyxml2-dev, libassimp-dev, libfmt-dev, libspdlog-dev, libpng-dev, libbullet-dev, libxxhash-dev")

include(CPack)

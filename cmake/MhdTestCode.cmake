# How test code is compiled: the files of tests/ and the test binaries of tools/stress and
# tools/stability. Compile time is what CI spends most of, and in a test file most of it
# is GoogleTest's macros and templates and the headers every test shares.

# -Og in the optimized builds: it halves a test file's compile time, while the engine,
# plugins and tools the test links keep the build type's flags, so the tests still run
# the code that ships. GCC takes the last -O it is given, and target options come after
# CMAKE_CXX_FLAGS_<CONFIG>.
set(MHD_TEST_CODE_OPT "-Og" CACHE STRING "Optimization of test code in Release-like builds (empty: the build type's)")
function(mhd_test_code_opt target)
  if(MHD_TEST_CODE_OPT)
    target_compile_options(${target} PRIVATE "$<$<CONFIG:Release,RelWithDebInfo,MinSizeRel>:${MHD_TEST_CODE_OPT}>")
  endif()
endfunction()

# mhd_use_test_pch(<target>): <target> is test code (mhd_test_code_opt), compiled with the
# one precompiled header all test binaries share: GoogleTest, GoogleMock, Eigen, fmt and
# the standard headers the tests use, parsed once per build instead of once per test
# binary. GCC uses a precompiled header only where the macros it depends on are defined
# alike, so every user links what defines them (fmt::fmt: FMT_SHARED); -Winvalid-pch,
# which CMake adds, turns a mismatch into a build error under -Werror, not a slow build.
function(mhd_use_test_pch target)
  if(NOT TARGET mhd_test_pch)
    find_package(GTest REQUIRED)
    add_library(mhd_test_pch STATIC "${PROJECT_SOURCE_DIR}/tests/precompiled/test_headers.cpp")
    target_link_libraries(mhd_test_pch PUBLIC GTest::gtest GTest::gmock fmt::fmt Eigen3::Eigen)
    target_precompile_headers(mhd_test_pch PRIVATE
      <gtest/gtest.h> <gmock/gmock.h> <Eigen/Core> <Eigen/Geometry> <fmt/core.h> <fmt/format.h>
      <algorithm> <array> <atomic> <chrono> <cmath> <cstdint> <cstdio> <cstdlib> <filesystem>
      <fstream> <functional> <limits> <map> <memory> <numbers> <optional> <random> <sstream>
      <stdexcept> <string> <string_view> <thread> <utility> <vector>)
    set_target_properties(mhd_test_pch PROPERTIES UNITY_BUILD OFF)
    mhd_set_warnings(mhd_test_pch)
    mhd_test_code_opt(mhd_test_pch)
  endif()
  target_link_libraries(${target} PRIVATE fmt::fmt Eigen3::Eigen GTest::gmock)
  target_precompile_headers(${target} REUSE_FROM mhd_test_pch)
  mhd_test_code_opt(${target})
endfunction()

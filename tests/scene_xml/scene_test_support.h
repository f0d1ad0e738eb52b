#pragma once
// Shared by the scene_xml tests: run from the repository root (so paths given to the
// reader are relative, as a user would type them) and flatten diagnostics to strings.

#include "diagnostics/diagnostic.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace mhd::test {

inline const std::filesystem::path kSourceDir = MHD_SOURCE_DIR;

/// Fixture that makes the repository root the working directory.
class FromSourceRoot : public ::testing::Test {
 protected:
  void SetUp() override { std::filesystem::current_path(kSourceDir); }
};

inline std::vector<std::string> to_strings(const Diagnostics& diagnostics) {
  std::vector<std::string> out;
  out.reserve(diagnostics.size());
  for (const Diagnostic& d : diagnostics) out.push_back(d.to_string());
  return out;
}

}  // namespace mhd::test

#pragma once
// Shared by the scene_xml tests: run from the repository root (so paths given to the
// reader are relative, as a user would type them) and flatten diagnostics to strings.

#include "diagnostics/diagnostic.h"
#include "scene_xml/scene_reader.h"

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

/// The file name the one-box scenes below are read as.
inline const std::string kOneBoxFile = "scene.xml";

/// A scene in `unit` with one box whose children (from line 3 on) are `children`.
inline std::string one_box_scene(const std::string& children, const std::string& unit = "m") {
  return "<scene version=\"1\" unit=\"" + unit + "\">\n"
         "  <object name=\"o\"><box size=\"0.1 0.1 0.1\"/><material stiffness_N_per_m=\"1000\"/>\n" +
         children +
         "  </object>\n"
         "</scene>\n";
}

/// "scene.xml:LINE: error: MESSAGE", as the reader reports a one-box scene's problem.
inline std::string one_box_error(int line, const std::string& message) {
  return kOneBoxFile + ":" + std::to_string(line) + ": error: " + message;
}

/// The errors of a one-box scene with `children`, which must be refused.
inline std::vector<std::string> one_box_errors(const std::string& children) {
  const Result<SceneDescription> r = read_scene_string(one_box_scene(children), kOneBoxFile);
  EXPECT_FALSE(r.ok());
  return to_strings(r.diagnostics());
}

}  // namespace mhd::test

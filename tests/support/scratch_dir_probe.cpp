// Makes a scratch folder with a file in it, prints the suite's folder, and fails when
// MHD_SCRATCH_PROBE_FAIL is set: for scratch_dir_test.cpp.

#include "support/scratch_dir.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iostream>

TEST(ScratchDirProbe, WritesAFile) {
  const std::filesystem::path dir = mhd::test::scratch_dir("scratch_probe", "case");
  std::ofstream(dir / "file.txt") << "written\n";
  std::cout << "root=" << dir.parent_path().string() << std::endl;
  if (std::getenv("MHD_SCRATCH_PROBE_FAIL") != nullptr) ADD_FAILURE() << "failing on request";
}

// A test program's scratch folder is gone once it has passed, and kept when a test failed.

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;

struct ProbeRun {
  int exit_code = -1;
  fs::path root;  ///< the suite's folder the probe made
  std::string output;
};

ProbeRun run_probe(bool fail) {
  const std::string command =
      std::string(fail ? "MHD_SCRATCH_PROBE_FAIL=1 " : "") + "'" + MHD_SCRATCH_DIR_PROBE + "' 2>&1";
  ProbeRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  std::array<char, 512> buffer{};
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) run.output += buffer.data();
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  const std::size_t at = run.output.find("root=");
  if (at != std::string::npos) {
    const std::size_t end = run.output.find('\n', at);
    run.root = run.output.substr(at + 5, end - at - 5);
  }
  return run;
}

TEST(ScratchDir, APassedProgramLeavesNoFolderBehind) {
  const ProbeRun run = run_probe(/*fail=*/false);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  ASSERT_FALSE(run.root.empty()) << run.output;
  EXPECT_FALSE(fs::exists(run.root)) << run.root;
}

TEST(ScratchDir, AFailedProgramKeepsItsFilesAndSaysWhere) {
  const ProbeRun run = run_probe(/*fail=*/true);
  ASSERT_NE(run.exit_code, 0) << run.output;
  ASSERT_FALSE(run.root.empty()) << run.output;
  EXPECT_TRUE(fs::exists(run.root / "case" / "file.txt")) << run.root;
  EXPECT_NE(run.output.find("scratch files kept for reading: " + run.root.string()), std::string::npos)
      << run.output;
  fs::remove_all(run.root);
}

}  // namespace

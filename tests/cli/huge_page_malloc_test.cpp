// restart_with_huge_page_malloc() seen from the program it starts: in a child process,
// it runs a shell that writes down the GLIBC_TUNABLES it was given. The duals: where the
// tunable is set already, or the program cannot be run, it returns with the environment
// as it was.
#include "huge_page_malloc.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace mhd::cli {
namespace {

class HugePageMallocTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("mhd_huge_page_malloc_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// In a child with GLIBC_TUNABLES as `tunables` (unset: nullopt), restarts as
  /// `program` running a shell line that writes GLIBC_TUNABLES to a file. Returns what
  /// the file holds: the started program's GLIBC_TUNABLES, or "returned: " and the
  /// child's own when the call came back.
  std::string run_child(const std::optional<std::string>& tunables, const char* program) {
    const std::string out = (dir_ / "out").string();
    const std::string line = "printf '%s' \"$GLIBC_TUNABLES\" > '" + out + "'";
    const pid_t pid = ::fork();
    if (pid == 0) {
      if (tunables) {
        ::setenv("GLIBC_TUNABLES", tunables->c_str(), 1);
      } else {
        ::unsetenv("GLIBC_TUNABLES");
      }
      std::string a0 = "sh", a1 = "-c";
      char* argv[] = {a0.data(), a1.data(), const_cast<char*>(line.c_str()), nullptr};  // NOLINT
      restart_with_huge_page_malloc(program, argv);
      const char* now = std::getenv("GLIBC_TUNABLES");
      std::ofstream(out) << "returned: " << (now != nullptr ? now : "(unset)");
      ::_exit(0);
    }
    int status = 0;
    EXPECT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
    std::ifstream in(out);
    std::stringstream text;
    text << in.rdbuf();
    std::filesystem::remove(out);
    return text.str();
  }

  std::filesystem::path dir_;
};

TEST_F(HugePageMallocTest, RestartsWithTheTunableAddedToWhatWasThere) {
  EXPECT_EQ(run_child(std::nullopt, "/bin/sh"), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(run_child("glibc.malloc.arena_max=2", "/bin/sh"), "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");
}

TEST_F(HugePageMallocTest, ReturnsUnchangedWhereTheTunableIsSetAlready) {
  // A user's choice either way, or the restart's own: never a second restart.
  EXPECT_EQ(run_child("glibc.malloc.hugetlb=0", "/bin/sh"), "returned: glibc.malloc.hugetlb=0");
  EXPECT_EQ(run_child("glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1", "/bin/sh"),
            "returned: glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");
}

TEST_F(HugePageMallocTest, AProgramThatCannotRunLeavesTheEnvironmentAsItWas) {
  EXPECT_EQ(run_child(std::nullopt, "/nonexistent/mhd"), "returned: (unset)");
  EXPECT_EQ(run_child("glibc.malloc.arena_max=2", "/nonexistent/mhd"), "returned: glibc.malloc.arena_max=2");
}

// Only the subcommands that load scenes without a real-time loop restart.
TEST(HugePageMallocSubcommands, OfflineLoadsRestartAndRunsKeepGlibcsDefault) {
  for (const char* offline : {"validate", "strokes", "proxy-replay", "plan-sim", "share-sim", "cache"}) {
    EXPECT_TRUE(wants_huge_page_malloc(offline)) << offline;
  }
  for (const char* live : {"run", "try", "viewer", "tracker-server", "replay", "calibrate", "plugins", "devices",
                           "validat", "", "--help"}) {
    EXPECT_FALSE(wants_huge_page_malloc(live)) << live;
  }
  EXPECT_FALSE(wants_huge_page_malloc(nullptr));
}

}  // namespace
}  // namespace mhd::cli

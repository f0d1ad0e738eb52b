#include "support/scratch_dir.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <iostream>
#include <mutex>
#include <set>
#include <system_error>

namespace mhd::test {
namespace {

namespace fs = std::filesystem;

/// The suites' folders this process made, judged when it exits.
class ScratchRoots {
 public:
  void add(const fs::path& root) {
    const std::lock_guard lock(mutex_);
    roots_.insert(root);
  }

  ~ScratchRoots() {
    // A forked child that exits must not remove what its parent still uses. gtest's
    // UnitTest is never destroyed, so it can be asked here.
    if (::getpid() != owner_) return;
    const bool passed = ::testing::UnitTest::GetInstance()->Passed();
    for (const fs::path& root : roots_) {
      if (passed) {
        std::error_code ignored;
        fs::remove_all(root, ignored);
      } else {
        std::cerr << "scratch files kept for reading: " << root.string() << '\n';
      }
    }
  }

 private:
  std::mutex mutex_;
  std::set<fs::path> roots_;
  pid_t owner_ = ::getpid();
};

ScratchRoots& scratch_roots() {
  static ScratchRoots roots;
  return roots;
}

}  // namespace

fs::path scratch_dir(const std::string& suite, const std::string& name) {
  const fs::path root = fs::temp_directory_path() / ("mhd_" + suite + "_" + std::to_string(::getpid()));
  scratch_roots().add(root);
  const fs::path dir = root / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace mhd::test

#pragma once
// A folder for one test's files under the system's temporary folder, gone once the test
// program has passed.

#include <filesystem>
#include <string>

namespace mhd::test {

/// <tmp>/mhd_<suite>_<pid>/<name>, emptied and made. When the test program exits with
/// every test passed, <tmp>/mhd_<suite>_<pid> is removed; after a failed test it is kept,
/// and its path written to stderr, so that the run's files can be read.
std::filesystem::path scratch_dir(const std::string& suite, const std::string& name);

}  // namespace mhd::test

#pragma once
// An output file that appears whole or not at all: written to a temporary file beside it
// (same directory, so the rename stays on one file system) and renamed over it by
// commit(). Destroyed without a successful commit(), it removes the temporary file and
// leaves whatever was at the path before untouched.

#include <cstdio>
#include <filesystem>
#include <string>

namespace mhd::cli {

class StagedOutputFile {
 public:
  /// Opens the temporary file; on failure ok() is false and error() says why.
  explicit StagedOutputFile(std::filesystem::path path);
  ~StagedOutputFile();
  StagedOutputFile(const StagedOutputFile&) = delete;
  StagedOutputFile& operator=(const StagedOutputFile&) = delete;

  [[nodiscard]] bool ok() const noexcept { return file_ != nullptr && error_.empty(); }
  [[nodiscard]] const std::string& error() const noexcept { return error_; }
  /// Where to write (null when the file could not be opened).
  [[nodiscard]] std::FILE* stream() const noexcept { return file_; }
  [[nodiscard]] const std::filesystem::path& temporary_path() const noexcept { return temporary_; }

  /// Flushes, closes and renames the temporary file to the path; false (and error()) when
  /// any write failed or the rename did, and then nothing is left behind.
  [[nodiscard]] bool commit();

 private:
  void discard() noexcept;

  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::FILE* file_ = nullptr;
  std::string error_;
};

}  // namespace mhd::cli

#pragma once
// Opening a file that must be a regular file, without ever blocking on a FIFO or device.

#include <filesystem>
#include <string>

namespace mhd {

/// An open, readable regular file (fd >= 0, closed on destruction), or why not.
class RegularFile {
 public:
  /// Opens `path` read-only. Refused with `problem` set: "file not found", "is a
  /// symlink loop", "is a directory, not a regular file", "is a FIFO, not a regular
  /// file", "is a device, not a regular file", "is a socket, not a regular file",
  /// "cannot open file: <errno text>".
  explicit RegularFile(const std::filesystem::path& path);
  ~RegularFile();
  RegularFile(const RegularFile&) = delete;
  RegularFile& operator=(const RegularFile&) = delete;

  [[nodiscard]] bool ok() const { return fd_ >= 0; }
  [[nodiscard]] int fd() const { return fd_; }
  [[nodiscard]] const std::string& problem() const { return problem_; }
  [[nodiscard]] unsigned long long size_bytes() const { return size_bytes_; }
  /// Hands the descriptor over to the caller (who then closes it).
  [[nodiscard]] int release();

 private:
  int fd_ = -1;
  std::string problem_;
  unsigned long long size_bytes_ = 0;
};

/// Why `path` is not a readable regular file ("" when it is); the RegularFile messages.
[[nodiscard]] std::string regular_file_problem(const std::filesystem::path& path);

}  // namespace mhd

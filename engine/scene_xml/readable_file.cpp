#include "scene_xml/readable_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>

namespace mhd::scene_xml {
namespace {

FileProblem problem_of_errno(int error) {
  if (error == ENOENT || error == ENOTDIR) return FileProblem::NotFound;
  if (error == ELOOP) return FileProblem::SymlinkLoop;
  return FileProblem::NotReadable;
}

/// Opens a regular file without blocking on a FIFO swapped in after the check; -1 with
/// `problem` set otherwise.
int open_regular(const std::filesystem::path& path, FileProblem& problem) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    problem = problem_of_errno(errno);
    return -1;
  }
  if (!S_ISREG(st.st_mode)) {  // never open a FIFO or device: that can block
    problem = FileProblem::NotRegularFile;
    return -1;
  }
  int fd = -1;
  do {
    fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  } while (fd < 0 && errno == EINTR);
  if (fd < 0) {
    problem = problem_of_errno(errno);
    return -1;
  }
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    problem = FileProblem::NotRegularFile;
    return -1;
  }
  problem = FileProblem::None;
  return fd;
}

}  // namespace

FileProblem check_readable_file(const std::filesystem::path& path) {
  FileProblem problem{};
  const int fd = open_regular(path, problem);
  if (fd >= 0) ::close(fd);
  return problem;
}

std::string_view describe(FileProblem problem) {
  switch (problem) {
    case FileProblem::None: return "";
    case FileProblem::NotFound: return "not found";
    case FileProblem::SymlinkLoop: return "is a symlink loop";
    case FileProblem::NotRegularFile: return "is not a regular file";
    case FileProblem::NotReadable: return "is not readable";
  }
  return "";
}

std::optional<std::string> read_whole_file(const std::filesystem::path& path, FileProblem& problem) {
  const int fd = open_regular(path, problem);
  if (fd < 0) return std::nullopt;
  std::string bytes;
  std::array<char, 16384> buffer{};
  for (;;) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n < 0) {
      ::close(fd);
      problem = FileProblem::NotReadable;
      return std::nullopt;
    }
    if (n == 0) break;
    bytes.append(buffer.data(), static_cast<std::size_t>(n));
  }
  ::close(fd);
  return bytes;
}

}  // namespace mhd::scene_xml

#include "mesh_io/regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace mhd {
namespace {

std::string errno_problem(int error) {
  if (error == ENOENT || error == ENOTDIR) return "file not found";
  if (error == ELOOP) return "is a symlink loop";
  return std::string("cannot open file: ") + std::strerror(error);
}

/// "" for a regular file, else what it is instead.
std::string kind_problem(mode_t mode) {
  if (S_ISREG(mode)) return {};
  if (S_ISDIR(mode)) return "is a directory, not a regular file";
  if (S_ISFIFO(mode)) return "is a FIFO, not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "not a regular file";
}

}  // namespace

RegularFile::RegularFile(const std::filesystem::path& path) {
  // stat first, so that a device is never opened (opening some has side effects).
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    problem_ = errno_problem(errno);
    return;
  }
  if (problem_ = kind_problem(st.st_mode); !problem_.empty()) return;
  // O_NONBLOCK: a FIFO swapped in after the stat must not block the open.
  int fd = -1;
  do {
    fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  } while (fd < 0 && errno == EINTR);
  if (fd < 0) {
    problem_ = errno_problem(errno);
    return;
  }
  if (::fstat(fd, &st) != 0) {
    problem_ = errno_problem(errno);
    ::close(fd);
    return;
  }
  if (problem_ = kind_problem(st.st_mode); !problem_.empty()) {
    ::close(fd);
    return;
  }
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags >= 0) (void)::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  fd_ = fd;
  size_bytes_ = static_cast<unsigned long long>(st.st_size);
}

RegularFile::~RegularFile() {
  if (fd_ >= 0) ::close(fd_);
}

int RegularFile::release() {
  const int fd = fd_;
  fd_ = -1;
  return fd;
}

std::string regular_file_problem(const std::filesystem::path& path) {
  const RegularFile file(path);
  return file.problem();
}

}  // namespace mhd

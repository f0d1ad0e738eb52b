#include "staged_output_file.h"

#include <fmt/core.h>

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>
#include <utility>

namespace mhd::cli {

StagedOutputFile::StagedOutputFile(std::filesystem::path path) : path_(std::move(path)) {
  // The process id keeps two runs writing the same output from sharing a temporary file.
  temporary_ = path_;
  temporary_ += fmt::format(".tmp{}", ::getpid());
  file_ = std::fopen(temporary_.c_str(), "wb");
  if (file_ == nullptr) error_ = fmt::format("cannot write {}: {}", temporary_.string(), std::strerror(errno));
}

StagedOutputFile::~StagedOutputFile() { discard(); }

void StagedOutputFile::discard() noexcept {
  if (file_ != nullptr) {
    (void)std::fclose(file_);
    file_ = nullptr;
    std::error_code ec;
    std::filesystem::remove(temporary_, ec);
  }
}

bool StagedOutputFile::commit() {
  if (file_ == nullptr) return false;
  const bool written = std::ferror(file_) == 0;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  std::error_code ec;
  if (!written || !closed) {
    error_ = fmt::format("cannot write {}: {}", temporary_.string(), std::strerror(errno));
  } else {
    std::filesystem::rename(temporary_, path_, ec);
    if (!ec) return true;
    error_ = fmt::format("cannot rename {} to {}: {}", temporary_.string(), path_.string(), ec.message());
  }
  std::filesystem::remove(temporary_, ec);
  return false;
}

}  // namespace mhd::cli

#include "mesh_io/regular_file_io_system.h"

#include "mesh_io/regular_file.h"

#include <assimp/DefaultIOStream.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string>
#include <string_view>

namespace mhd {
namespace {

/// DefaultIOStream over a FILE* we opened (its constructor is protected).
class RegularFileStream final : public Assimp::DefaultIOStream {
 public:
  RegularFileStream(std::FILE* file, const std::string& name) : Assimp::DefaultIOStream(file, name) {}
};

/// A text file past its UTF-8 byte order mark, which editors on Windows write and
/// assimp's OBJ reader takes for part of the first line (losing that vertex).
class PastByteOrderMarkStream final : public Assimp::IOStream {
 public:
  static constexpr long kMarkBytes = 3;
  explicit PastByteOrderMarkStream(std::FILE* file) : file_(file) { (void)std::fseek(file_, kMarkBytes, SEEK_SET); }
  ~PastByteOrderMarkStream() override { (void)std::fclose(file_); }
  PastByteOrderMarkStream(const PastByteOrderMarkStream&) = delete;
  PastByteOrderMarkStream& operator=(const PastByteOrderMarkStream&) = delete;

  size_t Read(void* buffer, size_t size, size_t count) override { return std::fread(buffer, size, count, file_); }
  size_t Write(const void*, size_t, size_t) override { return 0; }
  aiReturn Seek(size_t offset, aiOrigin origin) override {
    const long to = static_cast<long>(offset);
    const int done = origin == aiOrigin_SET   ? std::fseek(file_, to + kMarkBytes, SEEK_SET)
                     : origin == aiOrigin_CUR ? std::fseek(file_, to, SEEK_CUR)
                                              : std::fseek(file_, to, SEEK_END);
    return done == 0 ? aiReturn_SUCCESS : aiReturn_FAILURE;
  }
  size_t Tell() const override { return static_cast<size_t>(std::ftell(file_) - kMarkBytes); }
  size_t FileSize() const override {
    const long at = std::ftell(file_);
    (void)std::fseek(file_, 0, SEEK_END);
    const long end = std::ftell(file_);
    (void)std::fseek(file_, at, SEEK_SET);
    return static_cast<size_t>(end - kMarkBytes);
  }
  void Flush() override {}

 private:
  std::FILE* file_;
};

/// True when `file` is an OBJ (by its name) whose first bytes are a UTF-8 byte order mark.
bool obj_with_byte_order_mark(std::string_view name, std::FILE* file) {
  if (name.size() < 4) return false;
  std::string extension(name.substr(name.size() - 4));
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".obj") return false;
  unsigned char mark[3] = {};
  const bool has = std::fread(mark, 1, 3, file) == 3 && mark[0] == 0xEF && mark[1] == 0xBB && mark[2] == 0xBF;
  std::rewind(file);
  return has;
}

}  // namespace

void RegularFileIoSystem::refuse(const char* file, const std::string& problem) const {
  std::string what = fmt::format("'{}' {}", file, problem);
  if (std::find(refusals_.begin(), refusals_.end(), what) == refusals_.end()) refusals_.push_back(std::move(what));
}

bool RegularFileIoSystem::Exists(const char* file) const {
  if (file == nullptr) return false;
  const std::string problem = regular_file_problem(file);
  if (problem.empty()) return true;
  if (problem != "file not found") refuse(file, problem);
  return false;
}

Assimp::IOStream* RegularFileIoSystem::Open(const char* file, const char* mode) {
  if (file == nullptr || mode == nullptr) return nullptr;
  // Loading only reads; anything else is not ours to allow.
  if (std::string_view(mode).find_first_of("wa+") != std::string_view::npos) {
    refuse(file, "cannot be opened for writing while loading a mesh");
    return nullptr;
  }
  RegularFile opened(file);
  if (!opened.ok()) {
    if (opened.problem() != "file not found") refuse(file, opened.problem());
    return nullptr;
  }
  if (on_open_) on_open_(file, opened.size_bytes());
  std::FILE* stream = ::fdopen(opened.fd(), "rb");
  if (stream == nullptr) return nullptr;
  (void)opened.release();
  if (obj_with_byte_order_mark(file, stream)) return new PastByteOrderMarkStream(stream);
  return new RegularFileStream(stream, file);
}

}  // namespace mhd

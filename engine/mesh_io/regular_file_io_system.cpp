#include "mesh_io/regular_file_io_system.h"

#include "mesh_io/regular_file.h"

#include <assimp/DefaultIOStream.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <string_view>

namespace mhd {
namespace {

/// DefaultIOStream over a FILE* we opened (its constructor is protected).
class RegularFileStream final : public Assimp::DefaultIOStream {
 public:
  RegularFileStream(std::FILE* file, const std::string& name) : Assimp::DefaultIOStream(file, name) {}
};

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
  std::FILE* stream = ::fdopen(opened.fd(), "rb");
  if (stream == nullptr) return nullptr;
  (void)opened.release();
  return new RegularFileStream(stream, file);
}

}  // namespace mhd

#pragma once
// The assimp IOSystem every mesh load goes through: it opens regular files only, so a
// side file (an OBJ's mtllib, a texture) naming a FIFO, device, directory or symlink
// loop is refused at once instead of blocking or being read as data.

#include <assimp/DefaultIOSystem.h>

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace mhd {

class RegularFileIoSystem final : public Assimp::DefaultIOSystem {
 public:
  /// False for a path that is not a readable regular file; an existing path that is
  /// refused is recorded in refusals() (assimp treats a missing side file as optional).
  bool Exists(const char* file) const override;
  /// Null, and the refusal recorded, for anything but a readable regular file.
  Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;

  /// "'<path>' <problem>" for each refused path, in order, without repeats.
  [[nodiscard]] const std::vector<std::string>& refusals() const { return refusals_; }

  /// Called with each file opened: its path and size in bytes.
  using OpenSeen = std::function<void(const std::string& path, std::uint64_t bytes)>;
  void set_on_open(OpenSeen seen) { on_open_ = std::move(seen); }

 private:
  void refuse(const char* file, const std::string& problem) const;

  mutable std::vector<std::string> refusals_;
  OpenSeen on_open_;
};

}  // namespace mhd

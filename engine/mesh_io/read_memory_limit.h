#pragma once
// The memory a mesh reader's child process may take. assimp's readers can allocate
// without end on a corrupt file (an NFF patch claiming 10^11 vertices grew to 21.8 GB
// within the read's time limit), so the child's address space is limited: to what it
// maps when it starts, plus a base, plus so much for each byte of the files it opens
// (the mesh file and side files such as a glTF's .bin), at most the memory available.

#include <cstdint>
#include <set>
#include <string>

// GCC names its sanitizers by macros, clang by __has_feature.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define MHD_READ_MEMORY_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define MHD_READ_MEMORY_SANITIZED 1
#endif
#endif

namespace mhd {

class ReadMemoryLimit {
 public:
  /// False in sanitizer builds: their allocators reserve address space up front and end
  /// the process on an allocation that fails, so a limit would only crash the reader.
#if defined(MHD_READ_MEMORY_SANITIZED)
  static constexpr bool kInThisBuild = false;
#else
  static constexpr bool kInThisBuild = true;
#endif

  /// `cap_bytes` bounds the allowance (0: no bound).
  ReadMemoryLimit(std::uint64_t base_bytes, double per_file_byte, std::uint64_t cap_bytes);

  /// Sets the limit (RLIMIT_AS) to what the process maps now plus the base. False if the
  /// process's size or the limit cannot be read or set, or not kInThisBuild; the read is
  /// then not limited.
  bool start();
  /// Raises the limit for `path`, `bytes` long, the first time it is opened. Returns true
  /// if the allowance grew.
  bool add_file(const std::string& path, std::uint64_t bytes);
  /// What the reader may take beyond what it mapped when it started.
  [[nodiscard]] std::uint64_t allowance_bytes() const { return allowance_; }

 private:
  bool apply() const;

  double per_file_byte_;
  std::uint64_t cap_bytes_;
  std::uint64_t started_bytes_ = 0;  // mapped at start()
  std::uint64_t ceiling_bytes_ = 0;  // the limit's hard value, or the soft one it had if lower
  std::uint64_t allowance_ = 0;
  bool started_ = false;
  std::set<std::string> opened_;
};

}  // namespace mhd

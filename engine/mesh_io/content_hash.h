#pragma once
// XXH3-128 of bytes fed in order, on the widest vectors the CPU has. libxxhash as Debian
// builds it uses SSE2 only; on AVX2 the same digest comes twice as fast (a cached
// 100 M-triangle mesh hashes 10.6 GB: its key and its entry). Every width gives
// libxxhash's XXH3_128bits digest, bit for bit.

#include <cstddef>
#include <cstdint>
#include <span>

namespace mhd {

class ContentHash {
 public:
  enum class Width {
    Widest,    ///< AVX2 where the CPU has it, else the library's
    Baseline,  ///< the library's own (tests compare the two)
  };

  explicit ContentHash(Width width = Width::Widest);
  ~ContentHash();
  ContentHash(const ContentHash&) = delete;
  ContentHash& operator=(const ContentHash&) = delete;

  /// False when the state could not be allocated; digest() is then {0, 0}.
  [[nodiscard]] bool ok() const { return state_ != nullptr; }
  /// Whether this hash runs on AVX2.
  [[nodiscard]] bool wide() const { return wide_; }

  void update(const void* data, std::size_t bytes);
  void update(std::span<const std::byte> bytes) { update(bytes.data(), bytes.size()); }

  struct Digest {
    std::uint64_t low64 = 0;
    std::uint64_t high64 = 0;
  };
  /// The digest of everything fed so far (feeding may go on after).
  [[nodiscard]] Digest digest() const;

 private:
  bool wide_ = false;
  void* state_ = nullptr;  // the library's XXH3_state_t, or the AVX2 build's own
};

}  // namespace mhd

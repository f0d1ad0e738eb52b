#pragma once
// Who is the authority of each shared object, and whether a state sample may be obeyed.
// A sample is obeyed only from the object's authority in its current term, newer than
// the last one obeyed. A sample of a later term from a rig allowed to hold the object
// starts that term here too (a hand-over heard through its first state). Everything else
// is ignored and counted by reason: a state from a rig that lost the authority (older
// term) never moves the object again. Fixed size, no allocation: usable on the haptic
// thread.

#include "sharing/shared_object_state.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace mhd {

inline constexpr int kMaxSharedObjects = 32;
/// Rigs that may hold one object's authority, in the order they take it over.
inline constexpr int kMaxAuthorityRigs = 8;

enum class StateVerdict : std::uint8_t {
  Obeyed,
  NotShared,     ///< the object is not a shared one here
  NotFinite,     ///< a time, pose or velocity is not finite, or the rotation is not one
  OldTerm,       ///< from a term before the current one: its rig lost the authority
  NotAuthority,  ///< the current term, but from a rig that does not hold it
  NotAllowed,    ///< a later term from a rig that may never hold the object
  Stale,         ///< not newer than the last obeyed sample of the term
};
inline constexpr std::size_t kStateVerdicts = 7;

[[nodiscard]] const char* to_string(StateVerdict v) noexcept;

class ObjectAuthority {
 public:
  /// Makes `object` shared: rigs[0] holds it in term 0, the others may take it over in
  /// that order. Returns false (and changes nothing) when object is out of
  /// [0, kMaxSharedObjects), rigs is empty or longer than kMaxAuthorityRigs, or names a
  /// rig twice.
  bool share(int object, const std::uint32_t* rigs, int rig_count) noexcept;

  [[nodiscard]] bool is_shared(int object) const noexcept;
  /// The rig holding `object` now, and its term. Precondition: is_shared(object).
  [[nodiscard]] std::uint32_t authority(int object) const noexcept;
  [[nodiscard]] std::uint32_t epoch(int object) const noexcept;

  /// `rig` takes `object` over in a new term (its predecessor is silent); returns the
  /// term, or -1 when the object is not shared or the rig may not hold it.
  std::int64_t take_over(int object, std::uint32_t rig) noexcept;

  /// Judges a state sample and, when it is obeyed, remembers it as the term's newest.
  StateVerdict judge(const SharedObjectState& state) noexcept;
  /// Samples judged so far, by verdict.
  [[nodiscard]] std::uint64_t count(StateVerdict v) const noexcept { return counts_[static_cast<std::size_t>(v)]; }

 private:
  struct Entry {
    bool shared = false;
    std::array<std::uint32_t, kMaxAuthorityRigs> rigs{};
    int rig_count = 0;
    std::uint32_t authority = 0;
    std::uint32_t epoch = 0;
    bool heard = false;            ///< a sample of this term has been obeyed
    std::uint64_t last_sequence = 0;
  };
  [[nodiscard]] static bool may_hold(const Entry& e, std::uint32_t rig) noexcept;
  std::array<Entry, kMaxSharedObjects> entries_{};
  std::array<std::uint64_t, kStateVerdicts> counts_{};
};

}  // namespace mhd

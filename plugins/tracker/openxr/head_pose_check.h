#pragma once
// Which head poses the tracker passes on: a pose the runtime does not vouch for (not valid
// or not tracked), one with a non-finite number, one out of range or one whose
// orientation is not a unit quaternion is dropped and counted by its reason, never sent.

#include <openxr/openxr.h>

#include <array>
#include <cstddef>
#include <cstdint>

namespace mhd::openxr {

enum class HeadPoseVerdict : std::size_t {
  Accepted,
  NotTracked,     ///< position or orientation not both valid and tracked
  NonFinite,
  OutOfRange,     ///< a coordinate beyond max_position_m
  BadQuaternion,  ///< |q| off 1 by more than kUnitTolerance
  Count
};

/// Counter names, one per verdict, in verdict order ("accepted", "dropped_not_tracked", ...).
inline constexpr std::array<const char*, static_cast<std::size_t>(HeadPoseVerdict::Count)> kVerdictCounterNames{
    "accepted", "dropped_not_tracked", "dropped_non_finite", "dropped_out_of_range", "dropped_bad_quaternion"};

/// How far |q| may be from 1: runtimes send floats, renormalised each frame.
inline constexpr double kUnitTolerance = 1e-3;

/// The verdict on one xrLocateSpace result (the view space in the base space).
[[nodiscard]] HeadPoseVerdict check_head_pose(const XrSpaceLocation& location, double max_position_m) noexcept;

/// Counts of each verdict.
using VerdictCounts = std::array<std::uint64_t, static_cast<std::size_t>(HeadPoseVerdict::Count)>;

}  // namespace mhd::openxr

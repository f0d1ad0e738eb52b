#pragma once
// Several rigs on one floor, faster than real time: N simulated users walk a shared room
// (seeded random walks with turns, pauses and side-steps) and each rig's
// planner follows its own user's hand while keeping its base out of every other user's and
// every other base's way (PlannerInput::keep_outs). Bases are velocity-controlled as in
// the one-rig simulator (the twist held over each 0.1 s period, exact arcs).
//
// What a rig knows of the others comes from the shared tracking, `tracking_delay_s` old,
// with each one's velocity over the period before; the server's own floor_keep_outs
// (planner/floor_view.h) makes the keep-outs of it. A rig whose view of the others is
// older than `stale_after_s` holds its base (PlannerCase::Held) until the data comes back.
//
// Figures per session, judged against the truth:
//  - base-user intrusions: a base that moves, by its own motion, into a user's contact
//    distance (robot + human radius) from that user's position as its planner had it (its
//    own user tracked now, the others extrapolated), or nearer from inside (the one-rig
//    planner safety property, for every user);
//  - base-base intrusions: two bases nearer than the sum of their radii, ever;
//  - the least base-user (true positions) and base-base distances, the ticks with a user
//    walking into a base (the user's doing, counted, not an intrusion), the ticks each rig
//    held, any motion of a held base, and how often each hand was inside its arm's usable
//    workspace.
// Deterministic per seed; nothing here touches files.

#include "planner/planner.h"

#include <cstdint>
#include <vector>

namespace mhd::plan_sim {

struct SharedFloorSpec {
  PlannerKind kind = PlannerKind::Predictive;
  int rigs = 2;
  double duration_s = 30.0;
  double room_half_size_m = 2.0;     ///< the users' walks turn back beyond +-this
  /// The users: walking speeds drawn from [min, max], side-steps up to the maximum; a
  /// third of their manoeuvres are pauses (touching), a quarter side-steps.
  double walk_speed_min_mps = 0.2;
  double walk_speed_max_mps = 0.6;
  double side_step_speed_max_mps = 0.8;
  double tracking_delay_s = 0.05;    ///< age of the others' poses when a rig plans
  double stale_after_s = 0.3;        ///< older than this: the rig holds its base
  bool see_others = true;            ///< false: every rig plans as if alone (the one-rig planner)
  /// One rig stops receiving the others' data over [start, start + length).
  int dropout_rig = -1;
  double dropout_start_s = 0.0;
  double dropout_length_s = 0.0;
};

struct SharedFloorFigures {
  std::int64_t ticks = 0;                  ///< planner ticks, all rigs
  std::int64_t base_user_intrusions = 0;   ///< sub-steps
  std::int64_t base_base_intrusions = 0;   ///< sub-steps
  double min_base_user_m = 1e9;            ///< true centres, own and other users
  double min_base_other_user_m = 1e9;      ///< true centres, other rigs' users only
  double min_base_base_m = 1e9;
  std::int64_t user_walked_into_base_ticks = 0;
  std::int64_t held_ticks = 0;
  std::int64_t held_motion_ticks = 0;      ///< a held base that moved: must stay 0
  std::int64_t followed_ticks = 0;         ///< the hand inside the usable workspace
  std::int64_t followed_ticks_after_dropout = 0;
  /// The dropout rig's ticks from one stale_after_s after the dropout's end (a dropout of
  /// length 0 counts the same window, for comparison).
  std::int64_t ticks_after_dropout = 0;
};

/// One session. Throws std::invalid_argument for rigs < 1 or more than KeepOuts holds.
[[nodiscard]] SharedFloorFigures simulate_shared_floor(const PlannerSettings& settings, const SharedFloorSpec& spec,
                                                       std::uint64_t seed);

/// Sessions with seeds first_seed .. first_seed + sessions - 1, summed (least distances:
/// the least over all).
[[nodiscard]] SharedFloorFigures simulate_shared_floors(const PlannerSettings& settings, const SharedFloorSpec& spec,
                                                        std::uint64_t first_seed, int sessions);

}  // namespace mhd::plan_sim

// Two and three rigs on one floor (tools/plan_sim/shared_floor.h): random walks of every
// user, each rig's planner seeing the others through the shared tracking, 50 ms late.
// These seeds were used while writing the planner's keep-outs; the figures in
// docs/planner.md come from `mhd plan-sim --shared-floor` on seeds from 1,000,000 on.

#include "shared_floor.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <iostream>

namespace mhd::plan_sim {
namespace {

void print(const char* name, const SharedFloorFigures& f) {
  std::cout << "[ " << name << " ] ticks " << f.ticks << ", base-user intrusions " << f.base_user_intrusions
            << ", base-base intrusions " << f.base_base_intrusions << ", least base-user " << f.min_base_user_m
            << " m (other rigs' users " << f.min_base_other_user_m << " m), least base-base " << f.min_base_base_m
            << " m, user walked into a base " << f.user_walked_into_base_ticks << " ticks, held " << f.held_ticks
            << ", followed " << 100.0 * static_cast<double>(f.followed_ticks) / static_cast<double>(f.ticks)
            << " %\n";
}

/// `count` sessions from `first_seed` with default settings, printed under `name`.
SharedFloorFigures sessions(const char* name, const SharedFloorSpec& spec, std::uint64_t first_seed, int count) {
  const SharedFloorFigures f = simulate_shared_floors(PlannerSettings{}, spec, first_seed, count);
  print(name, f);
  return f;
}

TEST(SharedFloor, NoBaseEntersAUserOrAnotherBaseInTwoRigSessions) {
  const PlannerSettings settings;
  for (const PlannerKind kind : {PlannerKind::Predictive, PlannerKind::Seed}) {
    SharedFloorSpec spec;
    spec.kind = kind;
    const SharedFloorFigures f = simulate_shared_floors(settings, spec, 1, 20);
    print(kind == PlannerKind::Seed ? "seed, 2 rigs" : "predictive, 2 rigs", f);
    EXPECT_EQ(f.base_user_intrusions, 0);
    EXPECT_EQ(f.base_base_intrusions, 0);
    EXPECT_GE(f.min_base_base_m, 2.0 * settings.robot_radius_m);
    EXPECT_EQ(f.held_ticks, 0);  // nothing went stale
    // The sessions bring the rigs together.
    EXPECT_LT(f.min_base_base_m, 2.0 * settings.robot_radius_m + 0.3);
    EXPECT_LT(f.min_base_other_user_m, settings.collision_radius_m() + 0.3);
  }
}

TEST(SharedFloor, KeepingOutOfEachOtherCostsLittleFollowing) {
  // Dual of the keep-outs: the hands are followed almost as often as by rigs blind to each
  // other (which collide, below).
  const PlannerSettings settings;
  SharedFloorSpec spec;
  const SharedFloorFigures seeing = simulate_shared_floors(settings, spec, 1, 20);
  spec.see_others = false;
  const SharedFloorFigures blind = simulate_shared_floors(settings, spec, 1, 20);
  EXPECT_GT(seeing.followed_ticks, blind.followed_ticks * 9 / 10);
  EXPECT_GT(blind.followed_ticks, blind.ticks / 4);  // and the users are followed at all
}

TEST(SharedFloor, ThreeRigsKeepOutOfEachOther) {
  SharedFloorSpec spec;
  spec.rigs = 3;
  const SharedFloorFigures f = sessions("predictive, 3 rigs", spec, 101, 10);
  EXPECT_EQ(f.base_user_intrusions, 0);
  EXPECT_EQ(f.base_base_intrusions, 0);
}

TEST(SharedFloor, BlindToEachOtherTheSameRigsCollide) {
  // Dual: the same sessions with every rig planning as if alone (the one-rig planner)
  // drive bases into each other and into the other users; the figures can fail.
  SharedFloorSpec spec;
  spec.see_others = false;
  const SharedFloorFigures f = sessions("predictive, 2 rigs, blind", spec, 1, 20);
  EXPECT_GT(f.base_base_intrusions, 0);
  EXPECT_GT(f.base_user_intrusions, 0);
}

TEST(SharedFloor, ARigLosingTheOthersDataHoldsItsBaseAndFollowsAgainAfter) {
  const PlannerSettings settings;
  SharedFloorSpec spec;
  spec.dropout_rig = 1;
  spec.dropout_start_s = 8.0;
  spec.dropout_length_s = 5.0;
  const SharedFloorFigures f = simulate_shared_floors(settings, spec, 201, 10);
  print("predictive, 2 rigs, rig 1 loses the others for 5 s", f);
  // Stale after 0.3 s: about 4.7 s of 0.1 s ticks held, in each session.
  EXPECT_GE(f.held_ticks, 10 * 46);
  EXPECT_LE(f.held_ticks, 10 * 48);
  EXPECT_EQ(f.held_motion_ticks, 0);
  EXPECT_EQ(f.base_user_intrusions, 0);
  EXPECT_EQ(f.base_base_intrusions, 0);
  // Dual: once the data is back the base follows its hand again, about as often as the
  // same rig in the same sessions without the dropout.
  spec.dropout_start_s = 13.0;  // the same window, from 13.3 s
  spec.dropout_length_s = 0.0;
  const SharedFloorFigures whole = simulate_shared_floors(settings, spec, 201, 10);
  EXPECT_EQ(whole.held_ticks, 0);
  ASSERT_EQ(f.ticks_after_dropout, whole.ticks_after_dropout);
  std::cout << "followed after the dropout " << f.followed_ticks_after_dropout << " of " << f.ticks_after_dropout
            << " ticks, without it " << whole.followed_ticks_after_dropout << "\n";
  EXPECT_GT(f.followed_ticks_after_dropout, whole.followed_ticks_after_dropout * 2 / 3);
}

TEST(SharedFloor, RefusesMoreRigsThanTheKeepOutsHold) {
  SharedFloorSpec spec;
  spec.rigs = 0;
  EXPECT_THROW((void)simulate_shared_floor(PlannerSettings{}, spec, 1), std::invalid_argument);
  spec.rigs = static_cast<int>(KeepOuts::kCapacity / 2) + 2;
  EXPECT_THROW((void)simulate_shared_floor(PlannerSettings{}, spec, 1), std::invalid_argument);
  spec.rigs = static_cast<int>(KeepOuts::kCapacity / 2) + 1;  // dual: the most it holds runs
  spec.duration_s = 1.0;
  EXPECT_EQ(simulate_shared_floor(PlannerSettings{}, spec, 1).ticks, 10 * spec.rigs);
}

}  // namespace
}  // namespace mhd::plan_sim

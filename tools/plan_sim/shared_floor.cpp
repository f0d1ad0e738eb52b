#include "shared_floor.h"

#include "planner/floor_view.h"
#include "planner/planner_geometry.h"
#include "simulation/simulated_user.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace mhd::plan_sim {

namespace g = planner_geometry;

namespace {

constexpr int kSubsteps = 10;

/// The truth at one sub-step: each rig's user and base centre, world (x, z).
struct FloorSample {
  std::vector<Eigen::Vector2d> user_W;
  std::vector<Eigen::Vector2d> base_W;
};

struct Rig {
  std::unique_ptr<simulation::SimulatedUser> user;
  std::unique_ptr<Planner> planner;
  BasePose base;
};

std::vector<Rig> start_rigs(const PlannerSettings& settings, const SharedFloorSpec& spec, std::uint64_t seed) {
  std::vector<Rig> rigs(static_cast<std::size_t>(spec.rigs));
  for (int r = 0; r < spec.rigs; ++r) {
    simulation::SimulatedUserConfig config;
    config.seed = seed * 1000u + static_cast<std::uint64_t>(r);
    const double around = 2.0 * std::numbers::pi * r / spec.rigs;
    config.start.x_m = 1.2 * std::cos(around);
    config.start.z_m = 1.2 * std::sin(around);
    config.start.heading_rad = wrap_angle(around + std::numbers::pi / 2.0 * static_cast<double>(seed % 4u));
    config.area_half_size_m = spec.room_half_size_m;
    config.walk_speed_min_mps = spec.walk_speed_min_mps;
    config.walk_speed_max_mps = spec.walk_speed_max_mps;
    config.side_step_probability = 0.25;
    config.side_step_speed_max_mps = spec.side_step_speed_max_mps;
    config.stand_probability = 0.3;
    Rig& rig = rigs[static_cast<std::size_t>(r)];
    rig.user = std::make_unique<simulation::SimulatedUser>(config);
    rig.planner = make_planner(spec.kind, settings);
    const Eigen::Vector2d u(rig.user->body().x_m, rig.user->body().z_m);
    const Eigen::Vector3d hand = rig.user->hand_W();
    const Eigen::Vector2d t =
        g::follow_target(u, {hand.x(), hand.z()}, rig.user->body().heading_rad, settings.target_distance_m());
    rig.base = BasePose{t.x(), t.y(), g::facing_heading(t, u, settings.facing_angle_rad)};
  }
  return rigs;
}

FloorSample sample_of(const std::vector<Rig>& rigs) {
  FloorSample s;
  for (const Rig& rig : rigs) {
    s.user_W.emplace_back(rig.user->body().x_m, rig.user->body().z_m);
    s.base_W.emplace_back(rig.base.x_m, rig.base.z_m);
  }
  return s;
}

/// The sub-step whose truth rig `r` sees at sub-step `k` (its delay, and a dropout).
std::int64_t view_index(const SharedFloorSpec& spec, int r, std::int64_t k, double dt_s) {
  const auto delay = static_cast<std::int64_t>(std::lround(spec.tracking_delay_s / dt_s));
  std::int64_t v = std::max<std::int64_t>(0, k - delay);
  const double t = static_cast<double>(k) * dt_s;
  if (r == spec.dropout_rig && t >= spec.dropout_start_s && t < spec.dropout_start_s + spec.dropout_length_s) {
    const auto last = static_cast<std::int64_t>(std::floor(spec.dropout_start_s / dt_s + 1e-9)) - 1 - delay;
    v = std::clamp<std::int64_t>(last, 0, v);
  }
  return v;
}

}  // namespace

SharedFloorFigures simulate_shared_floor(const PlannerSettings& settings, const SharedFloorSpec& spec,
                                         std::uint64_t seed) {
  if (spec.rigs < 1 || static_cast<std::size_t>(2 * (spec.rigs - 1)) > KeepOuts::kCapacity)
    throw std::invalid_argument("shared floor: rigs must be 1.." + std::to_string(KeepOuts::kCapacity / 2 + 1));
  std::vector<Rig> rigs = start_rigs(settings, spec, seed);
  const double period = settings.command_period_s;
  const double dt = period / kSubsteps;
  const double user_contact = settings.collision_radius_m();
  const double base_contact = 2.0 * settings.robot_radius_m;
  const std::size_t n = rigs.size();

  std::vector<FloorSample> history{sample_of(rigs)};
  SharedFloorFigures f;
  const int ticks = static_cast<int>(std::lround(spec.duration_s / period));
  std::vector<PlannerInput> inputs(n);
  std::vector<BaseTwist> twists(n);
  std::vector<std::vector<Eigen::Vector2d>> seen_users(n, std::vector<Eigen::Vector2d>(n));  ///< [rig][user]
  for (int tick = 0; tick < ticks; ++tick) {
    const auto k = static_cast<std::int64_t>(tick) * kSubsteps;
    const double t = tick * period;
    // Plan: each rig sees its own user now and the others as the shared tracking gives them.
    for (std::size_t r = 0; r < n; ++r) {
      Rig& rig = rigs[r];
      PlannerInput& in = inputs[r];
      in = PlannerInput{};
      in.time_s = t;
      in.base = rig.base;
      in.user_W = Eigen::Vector2d(rig.user->body().x_m, rig.user->body().z_m);
      in.user_heading_rad = rig.user->body().heading_rad;
      in.user_velocity_W = rig.user->velocity_W();
      in.p_W_hip = rig.user->hand_W();
      // The others, as the shared tracking gives them: measured at sub-step v, with the
      // velocity over the period before it (floor_view.h makes the keep-outs of them).
      const std::int64_t v = view_index(spec, static_cast<int>(r), k, dt);
      const FloorSample& seen = history[static_cast<std::size_t>(v)];
      const FloorSample& before = history[static_cast<std::size_t>(std::max<std::int64_t>(0, v - kSubsteps))];
      const double span_s = static_cast<double>(std::min<std::int64_t>(v, kSubsteps)) * dt;
      const auto tracked = [&](const Eigen::Vector2d& now, const Eigen::Vector2d& earlier) {
        const Eigen::Vector2d velocity =
            span_s > 0.0 ? Eigen::Vector2d((now - earlier) / span_s) : Eigen::Vector2d::Zero();
        return TrackedDisc{true, static_cast<double>(v) * dt, now, velocity};
      };
      FloorView view;
      for (std::size_t q = 0; q < n; ++q) {
        if (q == r) {
          seen_users[r][q] = in.user_W;
          continue;
        }
        const TrackedDisc user = tracked(seen.user_W[q], before.user_W[q]);
        seen_users[r][q] = user.p_W + (t - user.t_s) * user.v_W;
        view.rigs[view.count++] = OtherRigTrack{user, tracked(seen.base_W[q], before.base_W[q])};
      }
      if (!spec.see_others) continue;
      const FloorKeepOuts floor = floor_keep_outs(view, t, spec.stale_after_s, settings);
      in.keep_outs = floor.keep_outs;
      in.keep_outs_current = floor.current;
    }
    for (std::size_t r = 0; r < n; ++r) {
      const PlannerOutput out = rigs[r].planner->update(inputs[r]);
      twists[r] = out.twist_B;
      ++f.ticks;
      if (out.hip_in_usable) ++f.followed_ticks;
      if (out.status == PlannerCase::Held) {
        ++f.held_ticks;
        if (out.twist_B.vx_mps != 0.0 || out.twist_B.vz_mps != 0.0 || out.twist_B.omega_radps != 0.0)
          ++f.held_motion_ticks;
      }
      if (static_cast<int>(r) == spec.dropout_rig &&
          t >= spec.dropout_start_s + spec.dropout_length_s + spec.stale_after_s) {
        ++f.ticks_after_dropout;
        if (out.hip_in_usable) ++f.followed_ticks_after_dropout;
      }
    }
    // Move: users walk, bases drive their arcs; judge every sub-step against the truth and
    // against what each planner saw.
    std::vector<bool> walked_into(n, false);
    for (int i = 1; i <= kSubsteps; ++i) {
      const double dt_i = dt * i;
      for (Rig& rig : rigs) rig.user->advance_to(t + dt_i);
      std::vector<Eigen::Vector2d> base_now(n);
      for (std::size_t r = 0; r < n; ++r) {
        const BasePose b = integrate_twist(inputs[r].base, twists[r], dt_i);
        base_now[r] = Eigen::Vector2d(b.x_m, b.z_m);
      }
      for (std::size_t r = 0; r < n; ++r) {
        const Eigen::Vector2d start(inputs[r].base.x_m, inputs[r].base.z_m);
        for (std::size_t u = 0; u < n; ++u) {
          const Eigen::Vector2d& seen_user = seen_users[r][u];
          const double d0 = (start - seen_user).norm();
          const double d = (base_now[r] - seen_user).norm();
          if (d0 >= user_contact ? d < user_contact : d < d0 - 1e-12) ++f.base_user_intrusions;
          const Eigen::Vector2d true_user(rigs[u].user->body().x_m, rigs[u].user->body().z_m);
          const double d_true = (base_now[r] - true_user).norm();
          f.min_base_user_m = std::min(f.min_base_user_m, d_true);
          if (u != r) f.min_base_other_user_m = std::min(f.min_base_other_user_m, d_true);
          if (d_true < user_contact) walked_into[r] = true;
        }
        for (std::size_t q = r + 1; q < n; ++q) {
          const double d = (base_now[r] - base_now[q]).norm();
          f.min_base_base_m = std::min(f.min_base_base_m, d);
          if (d < base_contact) ++f.base_base_intrusions;
        }
      }
      if (i == kSubsteps) {
        for (std::size_t r = 0; r < n; ++r) rigs[r].base = integrate_twist(inputs[r].base, twists[r], period);
      }
      FloorSample truth = sample_of(rigs);
      truth.base_W = base_now;
      history.push_back(std::move(truth));
    }
    for (std::size_t r = 0; r < n; ++r)
      if (walked_into[r]) ++f.user_walked_into_base_ticks;
  }
  return f;
}

SharedFloorFigures simulate_shared_floors(const PlannerSettings& settings, const SharedFloorSpec& spec,
                                          std::uint64_t first_seed, int sessions) {
  SharedFloorFigures total;
  for (int s = 0; s < sessions; ++s) {
    const SharedFloorFigures f = simulate_shared_floor(settings, spec, first_seed + static_cast<std::uint64_t>(s));
    total.ticks += f.ticks;
    total.base_user_intrusions += f.base_user_intrusions;
    total.base_base_intrusions += f.base_base_intrusions;
    total.min_base_user_m = std::min(total.min_base_user_m, f.min_base_user_m);
    total.min_base_other_user_m = std::min(total.min_base_other_user_m, f.min_base_other_user_m);
    total.min_base_base_m = std::min(total.min_base_base_m, f.min_base_base_m);
    total.user_walked_into_base_ticks += f.user_walked_into_base_ticks;
    total.held_ticks += f.held_ticks;
    total.held_motion_ticks += f.held_motion_ticks;
    total.followed_ticks += f.followed_ticks;
    total.followed_ticks_after_dropout += f.followed_ticks_after_dropout;
    total.ticks_after_dropout += f.ticks_after_dropout;
  }
  return total;
}

}  // namespace mhd::plan_sim

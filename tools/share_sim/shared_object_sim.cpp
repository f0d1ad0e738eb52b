#include "shared_object_sim.h"

#include "geometry/primitive_mesh.h"
#include "proxy/contact_reaction.h"
#include "proxy/moving_world.h"
#include "sharing/object_authority.h"
#include "verification/moving_tick_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace mhd::share_sim {

namespace {

using V = Eigen::Vector3d;
constexpr int kBox = 1;  // box_on_floor: the floor is object 0
constexpr double kGravity_mps2 = 9.81;
constexpr double kHandOutside_m = 0.15;
/// The rester's force rising by this much is the push felt (a clear step, well above
/// the proxy's damping ripple).
constexpr double kFeltRise_N = 0.5;

std::shared_ptr<const MeshBvh> shape_of(TriangleMesh mesh) {
  return std::make_shared<MeshBvh>(std::make_shared<TriangleMesh>(std::move(mesh)));
}

struct Message {
  double arrival_s = 0.0;
  std::uint64_t order = 0;  // ties in arrival keep the sending order
  SharedObjectState state;
  SharedPush push;
};

// One direction of the link: delay, jitter, loss and the cut.
class Link {
 public:
  Link(const LinkSpec& spec, std::uint64_t seed) : spec_(spec), rng_(seed) {}

  void send(double t_s, const Message& m) {
    const bool cut = t_s >= spec_.cut_from_s && t_s < spec_.cut_from_s + spec_.cut_for_s;
    if (cut || uniform_(rng_) < spec_.loss) return;
    Message sent = m;
    sent.arrival_s = t_s + spec_.delay_s + spec_.jitter_s * uniform_(rng_);
    sent.order = next_order_++;
    in_flight_.push_back(sent);
  }

  template <class Fn>
  void deliver(double now_s, Fn&& fn) {
    arrived_.clear();
    std::erase_if(in_flight_, [&](const Message& m) {
      if (m.arrival_s > now_s + 1e-12) return false;
      arrived_.push_back(m);
      return true;
    });
    std::sort(arrived_.begin(), arrived_.end(), [](const Message& a, const Message& b) {
      return a.arrival_s != b.arrival_s ? a.arrival_s < b.arrival_s : a.order < b.order;
    });
    for (const Message& m : arrived_) fn(m);
  }

 private:
  LinkSpec spec_;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  std::vector<Message> in_flight_, arrived_;
  std::uint64_t next_order_ = 0;
};

// Where a user's hand wants to be at t_s, given the box as its own rig renders it.
V hand_target_W(const SharedObjectSpec& spec, const HandPlan& h, double t_s, const Pose& X_WO_rendered,
                const Pose& X_WO_0) {
  const double half_m = 0.5 * spec.box_side_m;
  if (!h.stroke_points_O.empty()) {
    const auto k = static_cast<std::size_t>(std::max(0.0, t_s / h.stroke_hold_s)) % h.stroke_points_O.size();
    return X_WO_rendered * h.stroke_points_O[k];
  }
  const bool pressing = t_s >= h.press_from_s && t_s < h.press_to_s;
  const double depth_m = h.force_N / spec.stiffness_N_per_m;
  const V p_O = h.n_O * (pressing ? half_m - depth_m : half_m + kHandOutside_m) + h.face_offset_O;
  return (h.follows_box ? X_WO_rendered : X_WO_0) * p_O;
}

V move_towards(const V& from, const V& to, double max_step_m) {
  const V d = to - from;
  const double n = d.norm();
  return n <= max_step_m ? to : V(from + d * (max_step_m / n));
}

double angle_between(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.linear() * b.linear().transpose()).angle();
}

// One rig's proxy and its exact judge.
struct RigLoop {
  MovingWorld moving;
  verify::MovingTickCheck check;
  ProxyState proxy;
  V p_W_hip = V::Zero();
  // Squeezed against the floor, the proxy may be overlapped by the box (docs/proxy.md
  // "Moving objects"): from the squeeze until it is clear of the box again.
  bool overlapping = false;

  RigLoop(MovingWorld m, const V& p_W_hip_0) : moving(std::move(m)), check(moving.world()), p_W_hip(p_W_hip_0) {
    reset_proxy(proxy, p_W_hip);
  }

  // Moves the objects to t_s (the caller has driven a replica), steps the proxy, judges.
  ProxyOutput tick(double t_s, double dt_s, std::span<const HapticMaterial> materials, const ProxySettings& settings,
                   std::int64_t& crossings, std::int64_t& inside, std::int64_t& overlaps, std::int64_t& first_pop,
                   std::int64_t k) {
    const CollisionWorld& w = moving.world();
    check.before_move(w);
    const V p_before_W = proxy.proxy_W;
    const CarryOutput carry = moving.advance(t_s, proxy, settings.skin_m);
    overlapping = overlapping || carry.squeezed;
    const V p_carried_W = proxy.proxy_W;
    const ProxyOutput out = step_proxy(w, materials, settings, proxy, p_W_hip, dt_s, moving.twists());
    const auto points = static_cast<std::size_t>(std::clamp(proxy.path_points, 0, kMaxProxyPath));
    const verify::MovingTickVerdict v = check.judge(
        w, p_before_W, p_carried_W, std::span<const V>(proxy.path_W.data(), points), out, p_W_hip,
        overlapping ? kBox : -1);
    overlaps += v.overlap ? 1 : 0;
    overlapping = v.overlap;
    crossings += v.crossed ? 1 : 0;
    inside += v.inside ? 1 : 0;
    if ((v.crossed || v.inside) && first_pop < 0) first_pop = k;
    return out;
  }
};

// The box on an 8 m floor, resting at the world's origin.
CollisionWorld box_on_floor(double side_m) {
  CollisionWorld world;
  Pose X_WF = Pose::Identity();
  X_WF.linear() = Eigen::AngleAxisd(-std::numbers::pi / 2, V::UnitX()).toRotationMatrix();
  world.add_object(shape_of(make_plane_mesh(8.0, 8.0)), X_WF);
  Pose X_WO_0 = Pose::Identity();
  X_WO_0.translation() = V(0.0, 0.5 * side_m, 0.0);
  world.add_object(shape_of(make_box_mesh(V::Constant(side_m))), X_WO_0);
  return world;
}

MovingWorld authority_world(const CollisionWorld& world, const SharedObjectSpec& spec) {
  const std::vector<std::optional<ObjectDynamics>> dynamics{std::nullopt, ObjectDynamics{spec.mass_kg, spec.friction}};
  return MovingWorld(world, std::vector<std::optional<ObjectMotion>>(2), dynamics);
}

MovingWorld replica_world(const CollisionWorld& world) {
  const bool driven[2] = {false, true};
  return MovingWorld(world, std::vector<std::optional<ObjectMotion>>(2), {}, std::span<const bool>(driven, 2));
}

// One session, tick by tick: rig 0 the authority, rig 1 the replica, the link between.
class Session {
 public:
  explicit Session(const SharedObjectSpec& spec)
      : spec_(spec),
        dt_s_(1.0 / spec.rate_Hz),
        world_(box_on_floor(spec.box_side_m)),
        X_WO_0_(world_.pose(kBox)),
        materials_(2, material_of(spec)),
        rig_{RigLoop(authority_world(world_, spec), start_W(spec.hands[0])),
             RigLoop(replica_world(world_), start_W(spec.hands[1]))},
        replica_(X_WO_0_, spec.replica),
        pushes_0_(spec.pushes),
        to_1_(spec.link, 0x5eed0001),
        to_0_(spec.link, 0x5eed0002) {
    proxy_settings_.max_force_N = spec.max_force_N;
    // Rig 1 held the box in term 0 and handed it to rig 0 (term 1): rig 1's old-term
    // states (forge_old_term) must be ignored.
    const std::uint32_t order[2] = {1, 0};
    (void)authority_1_.share(kBox, order, 2);
    epoch_ = static_cast<std::uint32_t>(authority_1_.take_over(kBox, 0));
    const auto ticks = static_cast<std::size_t>(std::llround(spec.duration_s * spec.rate_Hz));
    r_.disagreement_m.reserve(ticks);
    r_.force_1_N.reserve(ticks);
    r_.p_W_box.reserve(ticks);
  }

  void tick(std::int64_t k) {
    const double t_s = static_cast<double>(k) * dt_s_;
    receive(t_s);
    move_hands(t_s);
    const ProxyOutput out_0 = authority_tick(t_s, k);
    ProxyOutput out_1 = replica_tick(t_s, k);
    judge(t_s, out_0, out_1);
  }

  SharedObjectResult finish() {
    const V moved = rig_[0].moving.world().pose(kBox).translation() - X_WO_0_.translation();
    r_.box_moved_m = std::hypot(moved.x(), moved.z());
    r_.old_term_ignored = authority_1_.count(StateVerdict::OldTerm);
    return std::move(r_);
  }

 private:
  static HapticMaterial material_of(const SharedObjectSpec& spec) {
    HapticMaterial m;
    m.stiffness_N_per_m = spec.stiffness_N_per_m;
    return m;
  }
  // Each hand starts outside the face it is drawn to, in free space.
  [[nodiscard]] V start_W(const HandPlan& h) const {
    return X_WO_0_ * (h.n_O * (0.5 * spec_.box_side_m + kHandOutside_m) + h.face_offset_O);
  }

  // What the link brings: states to rig 1 (judged), pushes to rig 0.
  void receive(double t_s) {
    to_1_.deliver(t_s, [&](const Message& m) {
      if (authority_1_.judge(m.state) == StateVerdict::Obeyed) {
        replica_.accept(m.state, t_s);
        ++r_.states_obeyed;
      } else {
        ++r_.states_ignored;
      }
    });
    to_0_.deliver(t_s, [&](const Message& m) { r_.pushes_kept += pushes_0_.receive(m.push) ? 1 : 0; });
  }

  // Each user's hand, towards what its own rig renders.
  void move_hands(double t_s) {
    for (int i = 0; i < 2; ++i) {
      RigLoop& rig = rig_[i];
      const V target = hand_target_W(spec_, spec_.hands[i], t_s, rig.moving.world().pose(kBox), X_WO_0_);
      rig.p_W_hip = move_towards(rig.p_W_hip, target, spec_.hand_speed_mps * dt_s_);
    }
  }

  // Rig 0: physics with its own user's reaction and rig 1's pushes; its state sent.
  ProxyOutput authority_tick(double t_s, std::int64_t k) {
    RigLoop& rig = rig_[0];
    const ProxyOutput out = rig.tick(t_s, dt_s_, materials_, proxy_settings_, r_.crossings[0], r_.inside[0],
                                     r_.overlaps[0], r_.first_pop_tick[0], k);
    rig.moving.apply_reaction(rig.proxy, out.force_W);
    X_WO_truth_ = rig.moving.world().pose(kBox);
    pushes_0_.for_each_acting(t_s, [&](const SharedPush& p) {
      rig.moving.add_push(p.object, p.f_W_N, X_WO_truth_ * p.p_O_m);
    });
    const std::span<const ObjectTwist> twists = rig.moving.twists();
    twist_truth_ = twists.size() > kBox ? twists[kBox] : ObjectTwist{};
    Message state;
    state.state = SharedObjectState{kBox, 0, epoch_, ++state_sequence_, t_s, X_WO_truth_, twist_truth_};
    to_1_.send(t_s, state);
    ++r_.states_sent;
    if (spec_.forge_old_term && k % 50 == 0) {
      Message forged = state;
      forged.state.authority_rig = 1;
      forged.state.epoch = epoch_ - 1;
      forged.state.sequence = state_sequence_ + 1000000;
      forged.state.X_WO.translation() += V(0.2, 0.0, 0.0);
      to_1_.send(t_s, forged);
    }
    return out;
  }

  // Rig 1: the replica, its proxy, and its user's push sent to the authority.
  ProxyOutput replica_tick(double t_s, std::int64_t k) {
    RigLoop& rig = rig_[1];
    rig.moving.drive(kBox, replica_.X_WO_at(t_s), replica_.twist_at(t_s));
    ProxyOutput out = rig.tick(t_s, dt_s_, materials_, proxy_settings_, r_.crossings[1], r_.inside[1],
                               r_.overlaps[1], r_.first_pop_tick[1], k);
    X_WO_replica_ = rig.moving.world().pose(kBox);
    // Stale data fades the force from the replica; the scene's pose is its state at 0.
    const double age_s = replica_.has_state() ? replica_.age_s(t_s) : t_s;
    const double gain = spec_.fade_stale_replica ? fade_.update(age_s, dt_s_) : 1.0;
    if (touches_box(rig.proxy, out.force_W)) {
      out.force_W *= gain;
      if (age_s > spec_.fade.stale_after_s + spec_.fade.fade_out_s + dt_s_) {
        r_.max_force_on_stale_N = std::max(r_.max_force_on_stale_N, out.force_W.norm());
      }
    }
    V f_box_W = V::Zero();
    const ContactReactions reactions = contact_reactions(rig.proxy, out.force_W);
    for (int i = 0; i < reactions.count; ++i) {
      const ContactReaction& on = reactions.on[static_cast<std::size_t>(i)];
      if (on.object == kBox) f_box_W += on.f_W_N;
    }
    Message push;
    push.push = SharedPush{kBox, 1, ++push_sequence_, t_s, f_box_W, X_WO_replica_.inverse() * rig.proxy.proxy_W};
    to_0_.send(t_s, push);
    ++r_.pushes_sent;
    return out;
  }

  static bool touches_box(const ProxyState& proxy, const V& force_W) {
    const ContactReactions reactions = contact_reactions(proxy, force_W);
    for (int i = 0; i < reactions.count; ++i) {
      if (reactions.on[static_cast<std::size_t>(i)].object == kBox) return true;
    }
    return false;
  }

  // Judged from outside: forces, agreement of the two boxes, the push felt.
  void judge(double t_s, const ProxyOutput& out_0, const ProxyOutput& out_1) {
    ++r_.ticks;
    const ProxyOutput* out[2] = {&out_0, &out_1};
    for (int i = 0; i < 2; ++i) {
      r_.contact_ticks[i] += out[i]->in_contact ? 1 : 0;
      r_.max_force_N[i] = std::max(r_.max_force_N[i], out[i]->force_W.norm());
    }
    r_.force_1_N.push_back(out_1.force_W.norm());
    const double d_m = (X_WO_replica_.translation() - X_WO_truth_.translation()).norm();
    if (link_up(t_s)) {
      if (replica_.has_state()) r_.max_state_age_s = std::max(r_.max_state_age_s, replica_.age_s(t_s));
      r_.disagreement_m.push_back(d_m);
      r_.max_disagreement_m = std::max(r_.max_disagreement_m, d_m);
      r_.max_disagreement_rad = std::max(r_.max_disagreement_rad, angle_between(X_WO_replica_, X_WO_truth_));
    } else {
      r_.max_disagreement_stale_m = std::max(r_.max_disagreement_stale_m, d_m);
    }
    r_.p_W_box.push_back(X_WO_truth_.translation());
    r_.max_box_speed_mps = std::max(r_.max_box_speed_mps, twist_truth_.v_W_origin_mps.norm());
    if (spec_.kind == SessionKind::PushAndRest) judge_felt(t_s, out[spec_.pusher]->force_W.norm(),
                                                           out[1 - spec_.pusher]->force_W.norm());
  }

  // The link is up when nothing was cut over the replica's horizon, blend and delay before now.
  [[nodiscard]] bool link_up(double t_s) const {
    const LinkSpec& l = spec_.link;
    const double recovery_s = spec_.replica.max_extrapolation_s + spec_.replica.blend_s + l.delay_s + l.jitter_s;
    return l.cut_for_s <= 0.0 || t_s < l.cut_from_s || t_s >= l.cut_from_s + l.cut_for_s + recovery_s;
  }

  // From the pusher's force passing the box's friction to the rester's rising by kFeltRise_N.
  void judge_felt(double t_s, double f_push_N, double f_rest_N) {
    const double friction_force_N = spec_.friction * spec_.mass_kg * kGravity_mps2;
    if (!t_push_s_ && f_push_N > friction_force_N + kFeltRise_N) {
      t_push_s_ = t_s;
      rest_force_N_ = f_rest_N;
    } else if (t_push_s_ && !r_.felt_delay_s && f_rest_N > rest_force_N_ + kFeltRise_N) {
      r_.felt_delay_s = t_s - *t_push_s_;
    }
  }

  const SharedObjectSpec& spec_;
  double dt_s_;
  CollisionWorld world_;
  Pose X_WO_0_;
  std::vector<HapticMaterial> materials_;
  ProxySettings proxy_settings_;
  RigLoop rig_[2];
  ObjectAuthority authority_1_;
  std::uint32_t epoch_ = 0;
  ObjectReplica replica_;
  ReplicaFade fade_{spec_.fade};
  RemotePushes pushes_0_;
  Link to_1_, to_0_;
  std::uint64_t state_sequence_ = 0, push_sequence_ = 0;
  Pose X_WO_truth_ = Pose::Identity(), X_WO_replica_ = Pose::Identity();
  ObjectTwist twist_truth_;
  std::optional<double> t_push_s_;
  double rest_force_N_ = 0.0;
  SharedObjectResult r_;
};

struct Draw {
  std::mt19937_64 rng;
  double u(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); }
};

// A box the pusher's full force moves, and a rest force its friction holds.
void draw_push_and_rest(Draw& d, SharedObjectSpec& s) {
  s.mass_kg = d.u(0.6, 1.2);
  s.friction = d.u(0.3, 0.45);
  s.pusher = d.pick(2);
  HandPlan& pusher = s.hands[s.pusher];
  HandPlan& rester = s.hands[1 - s.pusher];
  pusher.force_N = 1.5 * s.max_force_N;
  pusher.press_from_s = 1.5;
  pusher.press_to_s = 4.0;
  rester.force_N = 1.0;
  rester.follows_box = false;
  rester.face_offset_O = V::UnitY() * pusher.face_offset_O.y();
  rester.press_from_s = 0.2;
  rester.press_to_s = s.duration_s;
}

// Points on the top or a side face, a quarter of them on an edge, from 2 cm outside to
// 1 cm in.
void draw_strokes(Draw& d, double half_m, HandPlan& h) {
  h.stroke_hold_s = d.u(0.2, 0.6);
  for (int k = 0; k < 24; ++k) {
    V p_O(d.u(-1.0, 1.0) * half_m, d.u(-0.8, 1.0) * half_m, d.u(-1.0, 1.0) * half_m);
    const int axis = d.pick(4) == 0 ? 1 : 2 * d.pick(2);
    const double sign = axis == 1 ? 1.0 : (d.pick(2) == 0 ? -1.0 : 1.0);
    p_O[axis] = sign * (half_m + d.u(-0.01, 0.02));
    if (d.pick(4) == 0) p_O[(axis + 1) % 3] = (d.pick(2) == 0 ? -1.0 : 1.0) * (half_m + d.u(-0.005, 0.005));
    h.stroke_points_O.push_back(p_O);
  }
}

void check_spec(const SharedObjectSpec& s) {
  const bool ok = s.rate_Hz > 0.0 && std::isfinite(s.rate_Hz) && s.duration_s > 0.0 && std::isfinite(s.duration_s) &&
                  s.box_side_m > 0.0 && s.mass_kg > 0.0 && s.stiffness_N_per_m > 0.0 && s.friction >= 0.0 &&
                  s.max_force_N > 0.0 && s.hand_speed_mps > 0.0;
  if (!ok) throw std::invalid_argument("simulate_shared_object: rate, duration, box, mass, stiffness, force and hand speed must be positive");
}

}  // namespace

const char* to_string(SessionKind kind) noexcept {
  switch (kind) {
    case SessionKind::Opposite: return "opposite";
    case SessionKind::SameSide: return "same_side";
    case SessionKind::Adjacent: return "adjacent";
    case SessionKind::PushAndRest: return "push_and_rest";
    case SessionKind::Strokes: return "strokes";
  }
  return "unknown";
}

SharedObjectResult simulate_shared_object(const SharedObjectSpec& spec) {
  check_spec(spec);
  Session session(spec);
  const auto ticks = static_cast<std::int64_t>(std::llround(spec.duration_s * spec.rate_Hz));
  for (std::int64_t k = 1; k <= ticks; ++k) session.tick(k);
  return session.finish();
}

SharedObjectSpec draw_session(std::uint64_t seed) {
  Draw d{std::mt19937_64(seed)};
  SharedObjectSpec s;
  s.kind = static_cast<SessionKind>(d.pick(kSessionKinds));
  s.link.delay_s = d.u(0.001, 0.02);
  s.link.jitter_s = d.u(0.0, 0.005);
  s.link.loss = d.u(0.0, 0.05);
  if (d.pick(5) == 0) {
    s.link.cut_from_s = d.u(0.5, 4.0);
    s.link.cut_for_s = d.u(0.1, 1.0);
  }
  s.box_side_m = d.u(0.3, 0.6);
  s.mass_kg = d.u(0.6, 2.0);
  s.friction = d.u(0.3, 0.6);
  const V faces[4] = {V::UnitX(), V::UnitZ(), -V::UnitX(), -V::UnitZ()};
  const int f0 = d.pick(4);
  int f1 = f0;
  switch (s.kind) {
    case SessionKind::Opposite: f1 = (f0 + 2) % 4; break;
    case SessionKind::SameSide: f1 = f0; break;
    case SessionKind::Adjacent: f1 = (f0 + 1 + 2 * d.pick(2)) % 4; break;
    case SessionKind::PushAndRest: f1 = (f0 + 2) % 4; break;
    case SessionKind::Strokes: break;
  }
  for (int i = 0; i < 2; ++i) {
    HandPlan& h = s.hands[i];
    h.n_O = faces[i == 0 ? f0 : f1];
    const V side = V::UnitY().cross(h.n_O);
    const double half_m = 0.5 * s.box_side_m;
    h.face_offset_O = side * d.u(-0.6, 0.6) * half_m + V::UnitY() * d.u(-0.5, 0.5) * half_m;
    h.force_N = d.u(2.0, 10.0);  // beyond max_force_N: the device's limit
    h.press_from_s = d.u(0.3, 1.5);
    h.press_to_s = h.press_from_s + d.u(1.0, 0.7 * s.duration_s);
  }
  if (s.kind == SessionKind::PushAndRest) draw_push_and_rest(d, s);
  if (s.kind == SessionKind::Strokes) {
    for (HandPlan& h : s.hands) draw_strokes(d, 0.5 * s.box_side_m, h);
  }
  return s;
}

std::string csv_header() {
  return "seed,kind,delay_s,jitter_s,loss,cut_s,box_side_m,mass_kg,friction,ticks,contact_ticks_0,contact_ticks_1,"
         "pop_throughs,max_disagreement_m,max_disagreement_rad,max_state_age_s,max_box_speed_mps,box_moved_m,"
         "felt_delay_s,felt_delay_no_link_s,old_term_ignored,overlaps_0,overlaps_1";
}

SessionsSummary simulate_sessions(std::uint64_t first_seed, int sessions, double duration_s) {
  SessionsSummary s;
  std::vector<double> all_disagreements_m;
  for (int i = 0; i < sessions; ++i) {
    const std::uint64_t seed = first_seed + static_cast<std::uint64_t>(i);
    SharedObjectSpec spec = draw_session(seed);
    spec.duration_s = duration_s;
    spec.forge_old_term = true;
    const SharedObjectResult r = simulate_shared_object(spec);
    ++s.sessions;
    s.ticks += 2 * r.ticks;
    s.contact_ticks += r.contact_ticks[0] + r.contact_ticks[1];
    const std::int64_t pops = r.crossings[0] + r.crossings[1] + r.inside[0] + r.inside[1];
    s.pop_throughs += pops;
    s.overlaps[0] += r.overlaps[0];
    s.overlaps[1] += r.overlaps[1];
    s.disagreement_max_m = std::max(s.disagreement_max_m, r.max_disagreement_m);
    s.disagreement_max_rad = std::max(s.disagreement_max_rad, r.max_disagreement_rad);
    s.disagreement_stale_max_m = std::max(s.disagreement_stale_max_m, r.max_disagreement_stale_m);
    s.max_state_age_s = std::max(s.max_state_age_s, r.max_state_age_s);
    s.old_term_ignored += r.old_term_ignored;
    s.max_force_on_stale_N = std::max(s.max_force_on_stale_N, r.max_force_on_stale_N);
    all_disagreements_m.insert(all_disagreements_m.end(), r.disagreement_m.begin(), r.disagreement_m.end());
    std::optional<double> no_link_s;
    if (r.felt_delay_s && spec.link.cut_for_s <= 0.0) {
      SharedObjectSpec ideal = spec;
      ideal.link = LinkSpec{0.0, 0.0, 0.0, 0.0, 0.0};
      no_link_s = simulate_shared_object(ideal).felt_delay_s;
      if (no_link_s) {
        s.felt_delay_s.push_back(*r.felt_delay_s);
        s.felt_delay_no_link_s.push_back(*no_link_s);
        s.felt_link_delay_s.push_back(spec.link.delay_s + spec.link.jitter_s);
      }
    }
    const auto opt = [](const std::optional<double>& v) { return v ? fmt::format("{:.4f}", *v) : std::string(); };
    s.csv_rows.push_back(fmt::format("{},{},{:.4f},{:.4f},{:.4f},{:.3f},{:.3f},{:.3f},{:.3f},{},{},{},{},{:.6f},{:.6f},{:.4f},{:.4f},{:.4f},{},{},{},{},{}",
                                     seed, to_string(spec.kind), spec.link.delay_s, spec.link.jitter_s, spec.link.loss,
                                     spec.link.cut_for_s, spec.box_side_m, spec.mass_kg, spec.friction, r.ticks,
                                     r.contact_ticks[0], r.contact_ticks[1], pops, r.max_disagreement_m,
                                     r.max_disagreement_rad, r.max_state_age_s, r.max_box_speed_mps, r.box_moved_m,
                                     opt(r.felt_delay_s), opt(no_link_s), r.old_term_ignored, r.overlaps[0],
                                     r.overlaps[1]));
  }
  if (!all_disagreements_m.empty()) {
    const auto k = static_cast<std::size_t>(0.99 * static_cast<double>(all_disagreements_m.size() - 1));
    std::nth_element(all_disagreements_m.begin(), all_disagreements_m.begin() + static_cast<std::ptrdiff_t>(k),
                     all_disagreements_m.end());
    s.disagreement_p99_m = all_disagreements_m[k];
  }
  return s;
}

}  // namespace mhd::share_sim

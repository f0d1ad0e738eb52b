#pragma once
// Two rigs sharing one pushable box, faster than real time (docs/shared-objects.md).
// Rig 0 is the box's authority: it runs the box's physics (RigidBodyWorld, through
// MovingWorld as the haptic tick drives it) with its own user's reaction and the pushes
// rig 1 sends. Rig 1 renders a replica of the states rig 0 sends (ObjectReplica: dead
// reckoning, blended corrections) and sends its user's push (the reaction of the force
// its hand feels, at the touched point in the box's frame). Each rig runs its own
// god-object proxy at 1 kHz against its own rendering. The link delays every message by
// `delay_s` plus up to `jitter_s`, loses a fraction `loss`, and may be cut for a while;
// both rigs judge what arrives as the haptic server would (ObjectAuthority, RemotePushes).
//
// Judged per tick, from outside: each rig's proxy against its own rendering by the exact
// oracle in the box's frame (crossings, ending inside); the rendered box against the
// authority's at the same instant (position and angle), and the age of the state rig 1
// renders. A session of kind PushAndRest measures how long a push takes to be felt: one
// user pushes the box towards the other's resting hand; from the pusher's force passing
// the box's friction to the rester's force rising by 0.5 N.
// Deterministic per seed; nothing here touches files.

#include "sharing/object_replica.h"
#include "sharing/remote_pushes.h"
#include "sharing/replica_fade.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mhd::share_sim {

enum class SessionKind {
  Opposite,     ///< the users push opposite faces
  SameSide,     ///< both push one face
  Adjacent,     ///< faces at right angles
  PushAndRest,  ///< one pushes towards the other's still hand
  Strokes,      ///< both stroke the box's faces and edges, pressing in and letting go
};
inline constexpr int kSessionKinds = 5;
[[nodiscard]] const char* to_string(SessionKind kind) noexcept;

struct LinkSpec {
  double delay_s = 0.005;   ///< one way
  double jitter_s = 0.002;  ///< each message a further uniform [0, jitter_s]
  double loss = 0.0;        ///< fraction of messages lost
  /// Every message sent in [cut_from_s, cut_from_s + cut_for_s) is lost, both ways.
  double cut_from_s = 0.0;
  double cut_for_s = 0.0;
};

/// What one user does: press the face with outward normal n_O (box frame, unit,
/// horizontal) at the point face_offset_O (in the face's plane, from its centre), with
/// force_N, over [press_from_s, press_to_s); before and after, the hand waits 0.15 m
/// outside. A following hand moves with the box as its own rig renders it (a user walking
/// with the box); a resting one stays where the box first was. Strokes instead visits
/// stroke_points_O (box frame, each held stroke_hold_s).
struct HandPlan {
  Eigen::Vector3d n_O = Eigen::Vector3d::UnitX();
  Eigen::Vector3d face_offset_O = Eigen::Vector3d::Zero();
  double force_N = 5.0;
  double press_from_s = 0.5;
  double press_to_s = 4.0;
  bool follows_box = true;
  std::vector<Eigen::Vector3d> stroke_points_O;
  double stroke_hold_s = 0.5;
};

struct SharedObjectSpec {
  SessionKind kind = SessionKind::Opposite;
  double duration_s = 6.0;
  double rate_Hz = 1000.0;
  LinkSpec link;
  double box_side_m = 0.4;
  double mass_kg = 1.2;
  double friction = 0.4;
  double stiffness_N_per_m = 1000.0;
  double max_force_N = 8.5;
  double hand_speed_mps = 1.0;  ///< a hand moves to its target at most this fast
  HandPlan hands[2];
  int pusher = 0;               ///< PushAndRest: whose hand pushes; the other rests
  ReplicaSettings replica;
  RemotePushSettings pushes;
  /// Rig 1's force from its replica fades while the replica's state is stale (and comes
  /// back); false: full force whatever the replica's age, for comparison.
  bool fade_stale_replica = true;
  ReplicaFadeSettings fade;
  /// Rig 1 also receives a forged state of every 50th tick from a rig that held the box
  /// in an older term: it must never move the replica.
  bool forge_old_term = false;
};

struct SharedObjectResult {
  std::int64_t ticks = 0;                   ///< per rig
  std::int64_t contact_ticks[2] = {0, 0};
  std::int64_t crossings[2] = {0, 0};       ///< ticks a proxy's chord or leg touched a surface
  std::int64_t inside[2] = {0, 0};          ///< ticks a proxy ended inside the box
  std::int64_t first_pop_tick[2] = {-1, -1};  ///< each rig's first tick crossed or inside
  /// Ticks the box, having squeezed a proxy against the floor, overlapped it: allowed, as
  /// for any moving object (docs/proxy.md "Moving objects"), and counted apart.
  std::int64_t overlaps[2] = {0, 0};
  /// Rig 1's box against rig 0's at the same instant, over the ticks with the link up
  /// (no cut since the replica's horizon, blend and the link's delay): what the protocol
  /// promises.
  double max_disagreement_m = 0.0;
  double max_disagreement_rad = 0.0;
  std::vector<double> disagreement_m;       ///< each of those ticks'
  double max_disagreement_stale_m = 0.0;    ///< over the other ticks (a cut and its recovery)
  double max_state_age_s = 0.0;             ///< of the state rig 1 rendered, link up
  std::vector<Eigen::Vector3d> p_W_box;     ///< the authority's box origin, every tick
  double max_box_speed_mps = 0.0;
  double box_moved_m = 0.0;                 ///< the box's horizontal travel, start to end (authority)
  std::optional<double> felt_delay_s;       ///< PushAndRest: push passing friction to felt
  std::uint64_t states_sent = 0, states_obeyed = 0, states_ignored = 0, old_term_ignored = 0;
  std::uint64_t pushes_sent = 0, pushes_kept = 0;
  double max_force_N[2] = {0.0, 0.0};
  std::vector<double> force_1_N;            ///< rig 1's force, every tick
  /// Rig 1's largest force from touching the replica once its state has been stale for
  /// the whole fade (stale_after_s + fade_out_s): 0 with the fade.
  double max_force_on_stale_N = 0.0;
};

/// One session. Throws std::invalid_argument for a non-positive rate, duration, box, mass
/// or stiffness.
[[nodiscard]] SharedObjectResult simulate_shared_object(const SharedObjectSpec& spec);

/// A session drawn from `seed`: its kind, link (delay 1-20 ms, jitter up to 5 ms, loss up
/// to 5 %, a cut of 0.1-1 s in one session of five), box and hands.
[[nodiscard]] SharedObjectSpec draw_session(std::uint64_t seed);

struct SessionsSummary {
  int sessions = 0;
  std::int64_t ticks = 0;
  std::int64_t contact_ticks = 0;
  std::int64_t pop_throughs = 0;             ///< crossings and insides, both rigs
  std::int64_t overlaps[2] = {0, 0};         ///< squeezed against the floor, per rig
  double disagreement_p99_m = 0.0, disagreement_max_m = 0.0, disagreement_max_rad = 0.0;
  double disagreement_stale_max_m = 0.0;
  double max_state_age_s = 0.0;
  std::vector<double> felt_delay_s;          ///< PushAndRest sessions with no cut
  std::vector<double> felt_delay_no_link_s;  ///< the same sessions over a link of no delay
  std::vector<double> felt_link_delay_s;     ///< their link's delay plus jitter
  std::uint64_t old_term_ignored = 0;
  double max_force_on_stale_N = 0.0;         ///< rig 1, from a replica stale for the whole fade
  std::vector<std::string> csv_rows;         ///< one per session (csv_header())
};
[[nodiscard]] std::string csv_header();
/// Sessions drawn from seeds first_seed .. first_seed + sessions - 1.
[[nodiscard]] SessionsSummary simulate_sessions(std::uint64_t first_seed, int sessions, double duration_s);

}  // namespace mhd::share_sim

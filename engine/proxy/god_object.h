#pragma once
// God-object / virtual proxy haptic rendering (Zilles & Salisbury 1995, Ruspini et al.
// 1997). The proxy is a point that never crosses a surface and otherwise goes to the
// hand: each tick it moves from where it was towards the haptic interface point (HIP)
// by swept, conservative queries and ends at a local minimum of its distance to the HIP
// over the free space it can reach (docs/proxy.md has the whole contract). The force is
// a spring-damper between proxy and HIP. The scene is read-only; all mutable state is in
// ProxyState. step_proxy() allocates nothing and its work per tick is bounded.

#include "collision/collision_world.h"
#include "material/haptic_material.h"
#include "proxy/object_twist.h"

#include <array>
#include <span>

namespace mhd {

struct ProxySettings {
  double max_force_N = 8.5;
  /// Gap the proxy keeps from a touched plane; far below what a hand can feel
  /// (1 µm at 1 kN/m is 1 mN) and far above double rounding at metre scale.
  double skin_m = 1e-6;
  /// Cut-off of the low-pass filter on the HIP velocity used for damping.
  double velocity_cutoff_Hz = 100.0;
  /// Work budget of one tick (docs/proxy.md): sweeps, and triangles tested by them.
  /// A tick that would exceed either stops where it is (crossing-free) and says so.
  int max_sweeps_per_tick = 64;
  int max_triangle_tests_per_tick = 20000;
};

inline constexpr int kMaxConstraintPlanes = 3;
/// Most sweeps one tick may make, whatever ProxySettings::max_sweeps_per_tick says.
inline constexpr int kMaxProxySweeps = 64;
/// Waypoints a proxy can pass in one tick: its start, then at most one per sweep.
inline constexpr int kMaxProxyPath = kMaxProxySweeps + 2;

struct ConstraintPlane {
  Eigen::Vector3d normal_W = Eigen::Vector3d::Zero();  ///< points to free space
  double offset_m = 0.0;                                ///< proxy must keep normal.x >= offset
  TriangleRef triangle;
};

struct ProxyState {
  Eigen::Vector3d proxy_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_W_hip = Eigen::Vector3d::Zero();  ///< HIP of the previous tick
  Eigen::Vector3d hip_velocity_W = Eigen::Vector3d::Zero();
  bool initialised = false;
  bool sticking = false;  ///< static friction held the proxy last tick
  int plane_count = 0;
  std::array<ConstraintPlane, kMaxConstraintPlanes> planes{};
  /// The proxy's path during the last tick: path_W[0] is where it started,
  /// path_W[path_points - 1] where it ended. Each leg is a swept, crossing-free move.
  std::array<Eigen::Vector3d, kMaxProxyPath> path_W{};
  int path_points = 0;
  /// The triangles near the proxy, kept from tick to tick so that its sweeps need not walk
  /// the BVH each time (a cache: the sweeps test the same triangles either way). It names
  /// the world it was gathered from and starts again in another one.
  SweepCandidates near;
  /// The last tick ran out of work: this one sweeps in fine pieces (SweepWork::fine_pieces),
  /// so that from a spot denser than its budget it still goes part of the way.
  bool ran_out = false;
};

struct ProxyOutput {
  Eigen::Vector3d force_W = Eigen::Vector3d::Zero();  ///< clamped to max_force_N, finite
  Eigen::Vector3d proxy_W = Eigen::Vector3d::Zero();
  bool in_contact = false;
  int plane_count = 0;      ///< constraint planes active at the end of the tick
  int contact_object = -1;  ///< object of the first plane, -1 without contact
  bool force_clamped = false;
  bool sticking = false;
  int sweeps = 0;               ///< sweeps this tick made
  /// Of those, the ones answered by testing known triangles alone: a triangle that stops
  /// the leg at once (nothing can come before it), so the world was not swept.
  int sweeps_at_once = 0;
  int triangle_tests = 0;       ///< triangles those sweeps tested
  bool budget_exhausted = false;  ///< the tick hit its work budget and stopped early
};

/// Places the proxy at the HIP with no contact. Precondition: the HIP is in free space.
void reset_proxy(ProxyState& state, const Eigen::Vector3d& p_W_hip);

/// One haptic tick: moves the proxy towards p_W_hip and computes the force.
/// Promises (docs/proxy.md): every leg of the proxy's path (ProxyState::path_W) is
/// crossing-free; if the straight segment from the last proxy to p_W_hip is, the proxy
/// ends at p_W_hip with zero force; otherwise it ends where no small crossing-free move
/// brings it nearer the HIP, unless the work budget ran out (ProxyOutput says so), in
/// which case it ends at the last crossing-free point it reached and keeps its contact.
/// Friction and force shading move a proxy in contact on from that minimum along the
/// surface (to the friction cone's rim; towards the HIP's foot on the shaded planes,
/// docs/proxy.md "Force shading"), by swept motions, and never where the HIP is in view.
/// `materials[i]` is object i's material. A non-finite HIP leaves the proxy where it was
/// and returns zero force. `twists[i]`, where given (one per object), is how object i
/// moves this tick: damping then acts on the HIP's velocity relative to the touched
/// surface. Moving objects carry the proxy before this step (carry_proxy).
ProxyOutput step_proxy(const CollisionWorld& world, std::span<const HapticMaterial> materials,
                       const ProxySettings& settings, ProxyState& state,
                       const Eigen::Vector3d& p_W_hip, double dt_s, std::span<const ObjectTwist> twists = {});

}  // namespace mhd

#pragma once
// God-object / virtual proxy haptic rendering (Zilles & Salisbury 1995, Ruspini et al.
// 1997). The proxy is a point that never crosses a surface: each tick it moves towards
// the haptic interface point (HIP) by swept, conservative queries, gathering up to three
// constraint planes (faces, edges, concave corners), and the force is a spring-damper
// between proxy and HIP. The scene is read-only; all mutable state is in ProxyState.
// step_proxy() allocates nothing.

#include "collision/collision_world.h"
#include "material/haptic_material.h"

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
};

inline constexpr int kMaxConstraintPlanes = 3;
/// Waypoints a proxy can pass in one tick (one per sweep of the last pass, plus start).
inline constexpr int kMaxProxyPath = 24;
/// Sweeps one pass of the proxy may make before it stops where it is (safe).
inline constexpr int kMaxProxyIterations = 16;
static_assert(kMaxProxyPath > kMaxProxyIterations, "every pass must fit its path");

struct ConstraintPlane {
  Eigen::Vector3d normal_W = Eigen::Vector3d::Zero();  ///< points to free space
  double offset_m = 0.0;                                ///< proxy must keep normal.x >= offset
  TriangleRef triangle;
};

struct ProxyState {
  Eigen::Vector3d proxy_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d hip_W = Eigen::Vector3d::Zero();  ///< HIP of the previous tick
  Eigen::Vector3d hip_velocity_W = Eigen::Vector3d::Zero();
  bool initialised = false;
  bool sticking = false;  ///< static friction held the proxy last tick
  int plane_count = 0;
  std::array<ConstraintPlane, kMaxConstraintPlanes> planes{};
  /// The proxy's path during the last tick: path_W[0] is where it started,
  /// path_W[path_points - 1] where it ended. Each leg is a swept, crossing-free move.
  std::array<Eigen::Vector3d, kMaxProxyPath> path_W{};
  int path_points = 0;
};

struct ProxyOutput {
  Eigen::Vector3d force_W = Eigen::Vector3d::Zero();  ///< clamped to max_force_N, finite
  Eigen::Vector3d proxy_W = Eigen::Vector3d::Zero();
  bool in_contact = false;
  int plane_count = 0;      ///< constraint planes active at the end of the tick
  int contact_object = -1;  ///< object of the first plane, -1 without contact
  bool force_clamped = false;
  bool sticking = false;
};

/// Places the proxy at the HIP with no contact. Precondition: the HIP is in free space.
void reset_proxy(ProxyState& state, const Eigen::Vector3d& hip_W);

/// One haptic tick: moves the proxy towards hip_W and computes the force.
/// `materials[i]` is object i's material. A non-finite HIP leaves the proxy where it was
/// and returns zero force.
ProxyOutput step_proxy(const CollisionWorld& world, std::span<const HapticMaterial> materials,
                       const ProxySettings& settings, ProxyState& state,
                       const Eigen::Vector3d& hip_W, double dt_s);

}  // namespace mhd

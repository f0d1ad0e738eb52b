#include "dynamics/rigid_body_world.h"

#include "dynamics/body_shape.h"

#include <btBulletDynamicsCommon.h>
#include <LinearMath/btTransformUtil.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace mhd {
namespace {

btVector3 bt(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
Eigen::Vector3d eig(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

btTransform bt(const Pose& X) {
  const Eigen::Matrix3d R = X.linear();
  btMatrix3x3 basis(R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2));
  return btTransform(basis, bt(Eigen::Vector3d(X.translation())));
}

Pose eig(const btTransform& X) {
  Pose out = Pose::Identity();
  const btMatrix3x3& b = X.getBasis();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out.linear()(r, c) = b[r][c];
  }
  out.translation() = eig(X.getOrigin());
  return out;
}

// Resting contacts sleep only when truly still: a slowly pushed box must stay awake.
constexpr double kSleepLinear_mps = 1e-3;
constexpr double kSleepAngular_radps = 1e-2;

}  // namespace

struct RigidBodyWorld::Impl {
  struct Body {
    int object = -1;
    BodyHull hull;
    std::unique_ptr<btRigidBody> body;
    Pose X_BO = Pose::Identity();
    // The held force, and its impulse since the last physics step.
    Eigen::Vector3d f_W_N = Eigen::Vector3d::Zero();
    Eigen::Vector3d tau_W_Nm = Eigen::Vector3d::Zero();  // about the centre of mass
    Eigen::Vector3d impulse_W_Ns = Eigen::Vector3d::Zero();
    Eigen::Vector3d angular_impulse_W_Nms = Eigen::Vector3d::Zero();
    // Rendered at the last advance().
    Pose X_WO = Pose::Identity();
    Eigen::Vector3d v_W_origin_mps = Eigen::Vector3d::Zero();
    Eigen::Vector3d omega_W_radps = Eigen::Vector3d::Zero();
  };
  struct Static {
    StaticMeshShape shape;
    std::unique_ptr<btCollisionObject> object;
  };

  RigidBodySettings settings;
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  std::vector<Body> bodies;
  std::vector<Static> statics;
  std::vector<int> body_of_object;  // -1: not a body
  double t_physics_s = 0.0;
  double t_forces_s = 0.0;  // the held forces are integrated up to here

  explicit Impl(const RigidBodySettings& s) : settings(s) {}
  ~Impl() {
    for (Body& b : bodies) world.removeRigidBody(b.body.get());
    for (Static& s : statics) world.removeCollisionObject(s.object.get());
  }

  // The held forces act from t_forces_s to t_s.
  void integrate_forces(double t_s) {
    const double dt_s = t_s - t_forces_s;
    if (dt_s <= 0.0) return;
    for (Body& b : bodies) {
      b.impulse_W_Ns += b.f_W_N * dt_s;
      b.angular_impulse_W_Nms += b.tau_W_Nm * dt_s;
    }
    t_forces_s = t_s;
  }

  void render(Body& b, double t_s) {
    const btRigidBody& r = *b.body;
    btTransform X_WB;
    btTransformUtil::integrateTransform(r.getCenterOfMassTransform(), r.getLinearVelocity(), r.getAngularVelocity(),
                                        t_s - t_physics_s, X_WB);
    b.X_WO = eig(X_WB) * b.X_BO;
    b.omega_W_radps = eig(r.getAngularVelocity());
    b.v_W_origin_mps = eig(r.getLinearVelocity()) +
                       b.omega_W_radps.cross(Eigen::Vector3d(b.X_WO.translation()) - eig(X_WB.getOrigin()));
  }
};

RigidBodyWorld::RigidBodyWorld(const CollisionWorld& world, std::span<const std::optional<ObjectDynamics>> dynamics,
                               std::span<const bool> static_object, const RigidBodySettings& settings)
    : impl_(std::make_unique<Impl>(settings)) {
  const auto n = static_cast<std::size_t>(world.object_count());
  if (dynamics.size() != n || static_object.size() != n) {
    throw std::invalid_argument("RigidBodyWorld: one dynamics entry and one static flag per object are needed");
  }
  if (!(settings.step_s > 0.0) || !std::isfinite(settings.step_s) || settings.max_steps_per_advance < 1 ||
      !settings.gravity_W_mps2.allFinite()) {
    throw std::invalid_argument("RigidBodyWorld: the physics step must be positive and finite, at least one step per "
                                "advance, and gravity finite");
  }
  Impl& w = *impl_;
  w.world.setGravity(bt(settings.gravity_W_mps2));
  // Two friction directions: a box slid any way on the floor meets the same friction.
  w.world.getSolverInfo().m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
  w.body_of_object.assign(n, -1);
  std::size_t body_count = 0;
  for (const auto& d : dynamics) body_count += d.has_value() ? 1 : 0;
  w.bodies.reserve(body_count);  // bodies are not moved once Bullet points at them
  w.statics.reserve(n - body_count);
  for (std::size_t i = 0; i < n; ++i) {
    const int object = static_cast<int>(i);
    if (dynamics[i]) {
      const ObjectDynamics& d = *dynamics[i];
      if (!(d.mass_kg > 0.0) || !std::isfinite(d.mass_kg) || !(d.friction >= 0.0) || !std::isfinite(d.friction)) {
        throw std::invalid_argument("object " + std::to_string(i) +
                                    ": a pushable object needs a positive finite mass and a finite friction >= 0");
      }
      Impl::Body& b = w.bodies.emplace_back();
      b.object = object;
      b.hull = make_body_hull(world.shape(object).mesh());
      Pose X_OB = Pose::Identity();
      X_OB.translation() = b.hull.p_O_centre_m;
      b.X_BO = X_OB.inverse(Eigen::Isometry);
      btVector3 inertia(0, 0, 0);
      b.hull.shape->calculateLocalInertia(d.mass_kg, inertia);
      btRigidBody::btRigidBodyConstructionInfo info(d.mass_kg, nullptr, b.hull.shape.get(), inertia);
      info.m_startWorldTransform = bt(world.pose(object) * X_OB);
      // Bullet multiplies the two frictions of a contact: still objects carry 1, so the
      // body's own coefficient is its friction with them.
      info.m_friction = d.friction;
      info.m_restitution = 0.0;
      b.body = std::make_unique<btRigidBody>(info);
      b.body->setSleepingThresholds(kSleepLinear_mps, kSleepAngular_radps);
      w.world.addRigidBody(b.body.get());
      b.X_WO = world.pose(object);
      w.body_of_object[i] = static_cast<int>(w.bodies.size() - 1);
    } else if (static_object[i] && world.shape(object).mesh().triangle_count() > 0) {
      Impl::Static& s = w.statics.emplace_back();
      s.shape = make_static_mesh_shape(world.shape_ptr(object));
      s.object = std::make_unique<btCollisionObject>();
      s.object->setCollisionShape(s.shape.shape.get());
      s.object->setWorldTransform(bt(world.pose(object)));
      s.object->setFriction(1.0);
      s.object->setRestitution(0.0);
      w.world.addCollisionObject(s.object.get());
    }
  }
}

RigidBodyWorld::~RigidBodyWorld() = default;

bool RigidBodyWorld::is_body(int object) const noexcept {
  return object >= 0 && static_cast<std::size_t>(object) < impl_->body_of_object.size() &&
         impl_->body_of_object[static_cast<std::size_t>(object)] >= 0;
}

const RigidBodySettings& RigidBodyWorld::settings() const noexcept { return impl_->settings; }

void RigidBodyWorld::apply_force(int object, const Eigen::Vector3d& f_W_N, const Eigen::Vector3d& p_W_m) noexcept {
  if (!is_body(object) || !f_W_N.allFinite() || !p_W_m.allFinite()) return;
  Impl::Body& b = impl_->bodies[static_cast<std::size_t>(impl_->body_of_object[static_cast<std::size_t>(object)])];
  b.f_W_N = f_W_N;
  b.tau_W_Nm = (p_W_m - eig(b.body->getCenterOfMassPosition())).cross(f_W_N);
  if (f_W_N.squaredNorm() > 0.0) b.body->activate();
}

void RigidBodyWorld::add_force(int object, const Eigen::Vector3d& f_W_N, const Eigen::Vector3d& p_W_m) noexcept {
  if (!is_body(object) || !f_W_N.allFinite() || !p_W_m.allFinite()) return;
  Impl::Body& b = impl_->bodies[static_cast<std::size_t>(impl_->body_of_object[static_cast<std::size_t>(object)])];
  b.f_W_N += f_W_N;
  b.tau_W_Nm += (p_W_m - eig(b.body->getCenterOfMassPosition())).cross(f_W_N);
  if (f_W_N.squaredNorm() > 0.0) b.body->activate();
}

void RigidBodyWorld::clear_forces() noexcept {
  for (Impl::Body& b : impl_->bodies) {
    b.f_W_N.setZero();
    b.tau_W_Nm.setZero();
  }
}

void RigidBodyWorld::set_velocity(int object, const Eigen::Vector3d& v_W_origin_mps,
                                  const Eigen::Vector3d& omega_W_radps) noexcept {
  if (!is_body(object) || !v_W_origin_mps.allFinite() || !omega_W_radps.allFinite()) return;
  Impl::Body& b = impl_->bodies[static_cast<std::size_t>(impl_->body_of_object[static_cast<std::size_t>(object)])];
  // Bullet's linear velocity is its centre of mass's: v_C = v_O + omega x (p_C - p_O).
  const Eigen::Vector3d p_W_centre = eig(b.body->getCenterOfMassPosition());
  const Eigen::Vector3d v_W_centre = v_W_origin_mps + omega_W_radps.cross(p_W_centre - b.X_WO.translation());
  b.body->setLinearVelocity(bt(v_W_centre));
  b.body->setAngularVelocity(bt(omega_W_radps));
  b.body->activate();
  b.v_W_origin_mps = v_W_origin_mps;
  b.omega_W_radps = omega_W_radps;
}

int RigidBodyWorld::advance(double t_s) noexcept {
  Impl& w = *impl_;
  if (!(t_s > w.t_forces_s) || !std::isfinite(t_s)) return 0;
  const double h = w.settings.step_s;
  int steps = 0;
  // 1 ns of slack: a haptic clock of whole milliseconds lands on the physics step's ticks.
  while (w.t_physics_s + h <= t_s + 1e-9 && steps < w.settings.max_steps_per_advance) {
    w.integrate_forces(w.t_physics_s + h);
    for (Impl::Body& b : w.bodies) {
      // The mean force over the step: its impulse is the held forces' impulse exactly.
      b.body->applyCentralForce(bt(b.impulse_W_Ns / h));
      b.body->applyTorque(bt(b.angular_impulse_W_Nms / h));
      b.impulse_W_Ns.setZero();
      b.angular_impulse_W_Nms.setZero();
    }
    (void)w.world.stepSimulation(h, 0, h);
    w.t_physics_s += h;
    ++steps;
  }
  if (w.t_physics_s + h <= t_s) {
    // Behind by more than the bounded work allows: the physics clock slips to now, and
    // the time it skips pushes nothing.
    w.t_physics_s = t_s;
    w.t_forces_s = t_s;
  }
  w.integrate_forces(t_s);
  for (Impl::Body& b : w.bodies) w.render(b, t_s);
  return steps;
}

Pose RigidBodyWorld::X_WO(int object) const noexcept {
  if (!is_body(object)) return Pose::Identity();
  return impl_->bodies[static_cast<std::size_t>(impl_->body_of_object[static_cast<std::size_t>(object)])].X_WO;
}

Eigen::Vector3d RigidBodyWorld::v_W_origin_mps(int object) const noexcept {
  if (!is_body(object)) return Eigen::Vector3d::Zero();
  return impl_->bodies[static_cast<std::size_t>(impl_->body_of_object[static_cast<std::size_t>(object)])].v_W_origin_mps;
}

Eigen::Vector3d RigidBodyWorld::omega_W_radps(int object) const noexcept {
  if (!is_body(object)) return Eigen::Vector3d::Zero();
  return impl_->bodies[static_cast<std::size_t>(impl_->body_of_object[static_cast<std::size_t>(object)])].omega_W_radps;
}

double RigidBodyWorld::physics_time_s() const noexcept { return impl_->t_physics_s; }

}  // namespace mhd

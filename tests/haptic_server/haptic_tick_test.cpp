#include "haptic_server/haptic_tick.h"

#include "scene_compiler/scene_compiler.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>
#include <fmt/core.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>

namespace {

using namespace mhd;

const Eigen::Vector3d kQ(0.0, 0.3, 0.2);  // the PHANToM near mid-workspace

/// What a Cartesian PHANToM reports for joint angles q (ABI 3): its tool in the device frame.
Eigen::Vector3d tool(const Eigen::Vector3d& q_rad) { return phantom_tool_position(phantom_premium_1_5().geometry, q_rad); }

struct Fixture {
  std::optional<SceneDescription> description;
  std::optional<CompiledScene> scene;
  std::optional<Rig> rig;
};

/// The thesis rig, without a scene yet.
Fixture rig_fixture() {
  Fixture f;
  const auto rig_read = read_scene_file(std::string(MHD_SOURCE_DIR) + "/scenes/rigs/pomhi.xml");
  f.rig = Rig::from_scene(*rig_read).value();
  return f;
}

/// Where the tests write their scene files.
std::filesystem::path scene_dir() {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "haptic_tick_test";
  std::filesystem::create_directories(dir);
  return dir;
}

/// Reads and compiles the scene `file` into f; every test needs its scene, so a failure
/// ends the run.
void compile_into(Fixture& f, const std::filesystem::path& file) {
  auto read = read_scene_file(file);
  if (!read.ok()) {
    ADD_FAILURE() << "cannot read " << file;
    std::abort();
  }
  f.description = *read;
  CompileOptions options;
  options.use_cache = false;
  auto compiled = compile_scene(*f.description, options);
  if (!compiled.ok()) {
    ADD_FAILURE() << "cannot compile " << file;
    std::abort();
  }
  f.scene = std::move(*compiled.value());
}

/// The thesis rig and a 1 m box whose top face lies `gap_m` below the HIP at kQ with the
/// base at the origin (stiffness 500 N/m, no friction).
/// `motion`, where given, is a <motion> element for the box.
Fixture make_fixture(double gap_m, const std::string& motion = "") {
  Fixture f = rig_fixture();
  const Eigen::Vector3d hip = f.rig->p_W_hip(f.rig->X_W_robot_from_base({}), kQ);
  const std::filesystem::path dir = scene_dir();
  // ctest runs each case as its own process, perhaps at once: a file per process and gap.
  const auto file = dir / fmt::format("box_{}_{}_{}.xml", ::getpid(), gap_m, motion.size());
  std::ofstream(file) << fmt::format(R"(<?xml version="1.0"?>
<scene version="1" unit="m">
  <include file="{}/scenes/rigs/pomhi.xml"/>
  <object name="box">
    <material stiffness_N_per_m="500" damping_Ns_per_m="0" static_friction="0" dynamic_friction="0"/>
    <box size="1 1 1"/>
    <pose position="{} {} {}"/>
    {}
  </object>
</scene>
)", MHD_SOURCE_DIR, hip.x(), hip.y() - gap_m - 0.5, hip.z(), motion);
  compile_into(f, file);
  return f;
}

HapticTickSettings no_fade_in() {
  HapticTickSettings s;
  s.safety.fade_in_s = 0.0;
  return s;
}

TEST(HapticTick, NoForceAndNoHipBeforeTheFirstBasePose) {
  Fixture f = make_fixture(0.005);
  HapticTick tick(*f.scene, *f.rig, no_fade_in());
  const auto out = tick.tick(0.0, 0.001, tool(kQ));
  EXPECT_FALSE(out.p_W_hip.allFinite());
  EXPECT_EQ(out.force_W_N, Eigen::Vector3d::Zero());
  EXPECT_EQ(out.force_D_N, Eigen::Vector3d::Zero());
  // Start-up, counted apart: not stale tracking and not a fault.
  EXPECT_TRUE(out.startup);
  EXPECT_FALSE(out.stale);
  EXPECT_EQ(tick.startup_ticks(), 1u);
  EXPECT_EQ(tick.safety().counters().stale_ticks, 0u);
  EXPECT_EQ(tick.safety().counters().fault_ticks, 0u);
  // The first pose ends start-up.
  ASSERT_NE(tick.add_base_sensor_sample(0.001, f.rig->X_is900_base_sensor_from_base({})), BaseSampleStatus::Invalid);
  const auto tracked = tick.tick(0.002, 0.001, tool(kQ));
  EXPECT_FALSE(tracked.startup);
  EXPECT_TRUE(tracked.p_W_hip.allFinite());
  EXPECT_EQ(tick.startup_ticks(), 1u);
}

TEST(HapticTick, AMovingBoxRisesIntoTheStillHandAndPushesItUp) {
  // The box's top 20 mm below the HIP rises at 0.1 m/s from the first tick: it reaches the
  // hand at 0.2 s and is 10 mm past it at 0.3 s, where the spring (500 N/m) pushes up 5 N.
  Fixture f = make_fixture(0.02, R"(<motion velocity="0 0.1 0"/>)");
  HapticTick tick(*f.scene, *f.rig, no_fade_in());
  ASSERT_NE(tick.add_base_sensor_sample(0.0, f.rig->X_is900_base_sensor_from_base({})), BaseSampleStatus::Invalid);
  const double y0_m = tick.world().pose(0).translation().y();
  HapticTickOutput out;
  for (int k = 0; k <= 300; ++k) {
    tick.add_base_sensor_sample(1e-3 * k, f.rig->X_is900_base_sensor_from_base({}));
    out = tick.tick(1e-3 * k, 0.001, tool(kQ));
    if (k == 150) {
      EXPECT_FALSE(out.in_contact);  // still 5 mm below the hand
      EXPECT_EQ(out.force_W_N, Eigen::Vector3d::Zero());
    }
  }
  EXPECT_NEAR(tick.world().pose(0).translation().y() - y0_m, 0.03, 1e-9);
  ASSERT_TRUE(out.in_contact);
  EXPECT_NEAR(out.force_W_N.y(), 500.0 * 0.01, 1e-3);
  EXPECT_LT(out.force_W_N.cwiseAbs().x() + out.force_W_N.cwiseAbs().z(), 1e-6);
  EXPECT_NEAR(out.proxy_W_m.y() - out.p_W_hip.y(), 0.01, 2e-6);  // the proxy rode the face up
  EXPECT_EQ(tick.squeeze_ticks(), 0u);
}

TEST(HapticTick, APushableBoxWithNothingUnderItFallsAwayFromTheHand) {
  // The tick steps the scene's bodies: a pushable box 20 mm below the hand, with no floor,
  // falls g t^2 / 2 from the first tick and never reaches the hand.
  Fixture f = make_fixture(0.02, R"(<dynamics mass_kg="2"/>)");
  HapticTick tick(*f.scene, *f.rig, no_fade_in());
  ASSERT_NE(tick.add_base_sensor_sample(0.0, f.rig->X_is900_base_sensor_from_base({})), BaseSampleStatus::Invalid);
  const double y0_m = tick.world().pose(0).translation().y();
  HapticTickOutput out;
  for (int k = 0; k <= 300; ++k) {
    tick.add_base_sensor_sample(1e-3 * k, f.rig->X_is900_base_sensor_from_base({}));
    out = tick.tick(1e-3 * k, 0.001, tool(kQ));
    ASSERT_FALSE(out.in_contact) << "tick " << k;
    ASSERT_EQ(out.force_W_N, Eigen::Vector3d::Zero()) << "tick " << k;
  }
  EXPECT_NEAR(y0_m - tick.world().pose(0).translation().y(), 0.5 * 9.81 * 0.3 * 0.3, 0.01 * 0.5 * 9.81 * 0.09);
}

TEST(HapticTick, HipFollowsTheRigChainFromTheTrackedBasePose) {
  Fixture f = make_fixture(0.05);
  HapticTick tick(*f.scene, *f.rig, no_fade_in());
  const BasePose base{0.0, 0.0, 0.0};
  ASSERT_NE(tick.add_base_sensor_sample(0.0, f.rig->X_is900_base_sensor_from_base(base)), BaseSampleStatus::Invalid);
  const auto out = tick.tick(0.001, 0.001, tool(kQ));
  const Eigen::Vector3d expected = f.rig->p_W_hip(f.rig->X_W_robot_from_base(base), kQ);
  EXPECT_LT((out.p_W_hip - expected).norm(), 1e-9);
  EXPECT_FALSE(out.in_contact);
  EXPECT_EQ(out.force_W_N, Eigen::Vector3d::Zero());
}

TEST(HapticTick, PressingIntoTheBoxGivesTheSpringForceAndItsJointTorques) {
  Fixture f = make_fixture(0.002);
  HapticTick tick(*f.scene, *f.rig, no_fade_in());
  ASSERT_NE(tick.add_base_sensor_sample(0.0, f.rig->X_is900_base_sensor_from_base({})), BaseSampleStatus::Invalid);
  (void)tick.tick(0.001, 0.001, tool(kQ));  // free, 2 mm above the top face
  // Lower the arm (theta2 down) until the HIP is below the face.
  Eigen::Vector3d q = kQ;
  HapticTickOutput out;
  const Pose sensor = f.rig->X_is900_base_sensor_from_base({});
  double t = 0.001;
  for (int i = 0; i < 40 && !out.in_contact; ++i) {
    q.y() -= 0.001;
    (void)tick.add_base_sensor_sample(t, sensor);  // fresh tracking throughout
    out = tick.tick(t += 0.001, 0.001, tool(q));
  }
  for (int i = 0; i < 20; ++i) {
    q.y() -= 0.0005;
    (void)tick.add_base_sensor_sample(t, sensor);
    out = tick.tick(t += 0.001, 0.001, tool(q));
  }
  ASSERT_TRUE(out.in_contact);
  const double face_y = out.proxy_W_m.y();
  const double depth = face_y - out.p_W_hip.y();
  ASSERT_GT(depth, 0.001);
  EXPECT_NEAR(out.force_W_N.y(), 500.0 * depth, 500.0 * 2e-6 + 1e-9);  // k * depth (skin 1 um)
  EXPECT_NEAR(out.force_W_N.x(), 0.0, 1e-9);
  EXPECT_NEAR(out.force_W_N.z(), 0.0, 1e-9);
  // What the device gets: the same force in its own frame.
  const Eigen::Vector3d expected_force_D = f.rig->force_P_from_W(f.rig->X_W_robot_from_base({}), out.force_W_N);
  EXPECT_LT((out.force_D_N - expected_force_D).norm(), 1e-12);
  EXPECT_NEAR(out.force_D_N.norm(), out.force_W_N.norm(), 1e-12);
  EXPECT_GT(out.force_D_N.norm(), 0.0);
}

TEST(HapticTick, ForceFadesToZeroWhenTheBasePoseGoesStale) {
  Fixture f = make_fixture(0.002);
  HapticTick tick(*f.scene, *f.rig, no_fade_in());
  const Pose sensor = f.rig->X_is900_base_sensor_from_base({});
  Eigen::Vector3d q = kQ;
  q.y() -= 0.03;  // into the box (the proxy starts above it and is caught on the way)
  ASSERT_NE(tick.add_base_sensor_sample(0.0, sensor), BaseSampleStatus::Invalid);
  (void)tick.tick(0.0005, 0.001, tool(kQ));
  HapticTickOutput out;
  for (int i = 1; i <= 60; ++i) {
    const double t = 0.001 * i;
    out = tick.tick(t, 0.001, tool(q));
    if (t <= 0.03 + 1e-9) {
      EXPECT_GT(out.force_W_N.norm(), 1.0) << "t = " << t;  // no samples since t = 0
    }
  }
  EXPECT_TRUE(out.stale);
  EXPECT_EQ(out.force_W_N, Eigen::Vector3d::Zero());
  EXPECT_EQ(out.force_D_N, Eigen::Vector3d::Zero());
}

TEST(HapticTick, AHandStartingInsideAnObjectGetsNoForceUntilItLeaves) {
  Fixture f = make_fixture(-0.01);  // the box's top face 1 cm above the HIP: the HIP is inside
  HapticTick tick(*f.scene, *f.rig, no_fade_in());
  const Pose sensor = f.rig->X_is900_base_sensor_from_base({});
  Eigen::Vector3d q = kQ;
  double t = 0.0;
  HapticTickOutput out;
  for (int i = 0; i < 20; ++i) {
    (void)tick.add_base_sensor_sample(t, sensor);
    out = tick.tick(t += 0.001, 0.001, tool(q));
    EXPECT_TRUE(out.hip_inside_object);
    EXPECT_EQ(out.force_W_N, Eigen::Vector3d::Zero());  // never pulled further in
  }
  // Raise the arm out through the top face: the proxy starts above it, in free space.
  for (int i = 0; i < 200 && out.hip_inside_object; ++i) {
    q.y() += 0.001;
    (void)tick.add_base_sensor_sample(t, sensor);
    out = tick.tick(t += 0.001, 0.001, tool(q));
  }
  ASSERT_FALSE(out.hip_inside_object);
  EXPECT_FALSE(out.in_contact);
  // Pressing back down now meets the top face from outside: the force pushes up.
  for (int i = 0; i < 60; ++i) {
    q.y() -= 0.0005;
    (void)tick.add_base_sensor_sample(t, sensor);
    out = tick.tick(t += 0.001, 0.001, tool(q));
  }
  ASSERT_TRUE(out.in_contact);
  EXPECT_GT(out.force_W_N.y(), 0.0);
}

/// The thesis rig and a 1 m square sheet `gap_m` above the HIP at kQ (normal along y),
/// its two triangles each in the file twice, wound both ways (a two-sided face), the
/// upward-facing pair first where `up_first`.
Fixture make_two_sided_sheet_fixture(double gap_m, bool up_first) {
  Fixture f = rig_fixture();
  const Eigen::Vector3d hip = f.rig->p_W_hip(f.rig->X_W_robot_from_base({}), kQ);
  const std::filesystem::path dir = scene_dir();
  const std::string stem = fmt::format("sheet_{}_{}_{}", ::getpid(), gap_m, up_first);
  {
    std::ofstream obj(dir / (stem + ".obj"));
    const double y = hip.y() + gap_m;
    for (const auto& [dx, dz] : {std::pair{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}) {
      obj << fmt::format("v {} {} {}\n", hip.x() + dx, y, hip.z() + dz);
    }
    // 1 2 3 seen from +y is clockwise (x right, z towards the viewer): it faces down.
    const std::string down = "f 1 2 3\nf 1 3 4\n";
    const std::string up = "f 1 3 2\nf 1 4 3\n";
    obj << (up_first ? up + down : down + up);
  }
  const auto file = dir / (stem + ".xml");
  std::ofstream(file) << fmt::format(R"(<?xml version="1.0"?>
<scene version="1" unit="m">
  <include file="{}/scenes/rigs/pomhi.xml"/>
  <object name="sheet">
    <material stiffness_N_per_m="500" damping_Ns_per_m="0" static_friction="0" dynamic_friction="0"/>
    <mesh file="{}"/>
  </object>
</scene>
)", MHD_SOURCE_DIR, (dir / (stem + ".obj")).string());
  compile_into(f, file);
  return f;
}

TEST(HapticTick, AHandUnderATwoSidedSheetStartsAndIsHeldUnderIt) {
  for (const bool up_first : {false, true}) {
    Fixture f = make_two_sided_sheet_fixture(0.01, up_first);
    HapticTick tick(*f.scene, *f.rig, no_fade_in());
    const Pose sensor = f.rig->X_is900_base_sensor_from_base({});
    Eigen::Vector3d q = kQ;
    double t = 0.0;
    HapticTickOutput out;
    for (int i = 0; i < 5; ++i) {
      (void)tick.add_base_sensor_sample(t, sensor);
      out = tick.tick(t += 0.001, 0.001, tool(q));
      EXPECT_FALSE(out.hip_inside_object) << "up_first " << up_first;  // a sheet encloses nothing
    }
    // Raise the arm until the HIP is 5 mm through the sheet 1 cm above it: the proxy
    // stays under the sheet and the device is pushed back down.
    const double sheet_y = out.p_W_hip.y() + 0.01;
    for (int i = 0; i < 1000 && out.p_W_hip.y() < sheet_y + 0.005; ++i) {
      q.y() += 0.0005;
      (void)tick.add_base_sensor_sample(t, sensor);
      out = tick.tick(t += 0.001, 0.001, tool(q));
    }
    ASSERT_GE(out.p_W_hip.y(), sheet_y + 0.005);
    EXPECT_TRUE(out.in_contact) << "up_first " << up_first;
    EXPECT_LT(out.force_W_N.y(), -1.0) << "up_first " << up_first;
    EXPECT_GT(out.force_D_N.norm(), 1.0) << "up_first " << up_first;
  }
}

TEST(HapticTick, CarriesTheProxyWorkBudgetFlagOfEveryTick) {
  // A budget of one sweep a tick: pressing into the box needs more, so ticks run out.
  // The tick must pass on what step_proxy says: a twin proxy stepped directly with the
  // same HIP and dt gives the flag to compare against.
  Fixture f = make_fixture(0.002);
  f.scene->proxy.max_sweeps_per_tick = 1;
  HapticTick tick(*f.scene, *f.rig, no_fade_in());
  const Pose sensor = f.rig->X_is900_base_sensor_from_base({});
  ProxyState twin;
  Eigen::Vector3d q = kQ;
  double t = 0.0;
  int exhausted_ticks = 0;
  for (int i = 0; i < 120; ++i) {
    q.y() -= 0.0005;
    (void)tick.add_base_sensor_sample(t, sensor);
    const auto out = tick.tick(t += 0.001, 0.001, tool(q));
    ASSERT_TRUE(out.p_W_hip.allFinite());
    if (!twin.initialised) reset_proxy(twin, out.p_W_hip);
    const ProxyOutput direct =
        step_proxy(f.scene->world, f.scene->materials, f.scene->proxy, twin, out.p_W_hip, 0.001);
    ASSERT_EQ(out.proxy_W_m, direct.proxy_W) << "tick " << i;
    EXPECT_EQ(out.proxy_budget_exhausted, direct.budget_exhausted) << "tick " << i;
    if (out.proxy_budget_exhausted) ++exhausted_ticks;
  }
  EXPECT_GT(exhausted_ticks, 0);
}

TEST(HapticTick, NonFiniteJointAnglesGiveZeroForce) {
  Fixture f = make_fixture(0.002);
  HapticTick tick(*f.scene, *f.rig, no_fade_in());
  ASSERT_NE(tick.add_base_sensor_sample(0.0, f.rig->X_is900_base_sensor_from_base({})), BaseSampleStatus::Invalid);
  const Eigen::Vector3d nan_q(0.0, std::numeric_limits<double>::quiet_NaN(), 0.2);
  const auto out = tick.tick(0.001, 0.001, tool(nan_q));
  EXPECT_EQ(out.force_W_N, Eigen::Vector3d::Zero());
  EXPECT_EQ(out.force_D_N, Eigen::Vector3d::Zero());
  EXPECT_EQ(tick.safety().counters().fault_ticks, 1u);  // a fault, not start-up
  EXPECT_EQ(tick.startup_ticks(), 0u);
  EXPECT_FALSE(out.startup);
}

TEST(HapticTick, ADesktopRigRendersFromTheFirstTickAndNeverGoesStale) {
  // The same box, the device fixed where the mobile rig's PHANToM is with the base at the origin.
  Fixture f = make_fixture(0.002);
  const Rig desk = Rig::desktop(f.rig->X_W_phantom(f.rig->X_W_robot_from_base({})));
  HapticTick tick(*f.scene, desk, no_fade_in());
  const auto first = tick.tick(0.0, 0.001, tool(kQ));
  EXPECT_FALSE(first.startup);
  EXPECT_LT((first.p_W_hip - f.rig->p_W_hip(f.rig->X_W_robot_from_base({}), kQ)).norm(), 1e-9);
  EXPECT_TRUE(std::isnan(first.tracker_age_s));  // none, rather than a made-up age
  // 10 s without any tracker sample, 4 mm into the box's top (P's y is up): pushed out all along.
  const Eigen::Vector3d pressed = tool(kQ) - Eigen::Vector3d(0.0, 0.006, 0.0);
  for (int i = 1; i <= 10000; ++i) {
    const auto out = tick.tick(0.001 * i, 0.001, pressed);
    ASSERT_FALSE(out.stale) << "tick " << i;
    ASSERT_TRUE(out.in_contact) << "tick " << i;
    ASSERT_NEAR(out.force_W_N.y(), 500.0 * 0.004, 0.05) << "tick " << i;
  }
  EXPECT_EQ(tick.startup_ticks(), 0u);
  EXPECT_EQ(tick.safety().counters().stale_ticks, 0u);
  EXPECT_EQ(tick.safety().counters().fault_ticks, 0u);
}


TEST(HapticTick, TheLookAheadBetweenTicksChangesNothingTheDeviceGets) {
  // Two ticks on one input: one looks ahead after every tick, as the haptic thread does,
  // one never does. What goes to the device must be the same, bit for bit, while the
  // look-ahead does the work of a tick in contact (it presses into the box as the hand does).
  Fixture f = make_fixture(0.002);
  const Rig desk = Rig::desktop(f.rig->X_W_phantom(f.rig->X_W_robot_from_base({})));
  HapticTick looking(*f.scene, desk, no_fade_in());
  HapticTick plain(*f.scene, desk, no_fade_in());
  Eigen::Vector3d p = tool(kQ);
  int ticks_in_contact = 0;
  int look_aheads_in_contact = 0;
  for (int i = 0; i < 200; ++i) {
    p += Eigen::Vector3d(0.0002, i < 100 ? -0.0001 : 0.0001, 0.0);  // down 10 mm and up again, sliding
    const HapticTickOutput a = looking.tick(0.001 * i, 0.001, p);
    const HapticTickOutput b = plain.tick(0.001 * i, 0.001, p);
    ASSERT_EQ(a.force_D_N, b.force_D_N) << "tick " << i;
    ASSERT_EQ(a.proxy_W_m, b.proxy_W_m) << "tick " << i;
    if (a.in_contact) ++ticks_in_contact;
    const LookAheadReport ahead = looking.look_ahead();
    ASSERT_TRUE(ahead.ran) << "tick " << i;
    if (ahead.sweeps > 1) ++look_aheads_in_contact;
  }
  EXPECT_GT(ticks_in_contact, 100);
  EXPECT_GT(look_aheads_in_contact, 100);
}

}  // namespace

namespace {

/// The fixture's rig with a lift from -0.5 m to 0.5 m.
Rig lifted_rig(const Fixture& f) {
  SceneDescription scene = *f.description;
  scene.rig_lift = LiftDescription{-0.5, 0.5, 0.3, 1.5, {}};
  return Rig::from_scene(scene).value();
}

TEST(HapticTick, ARigWithALiftRendersNothingUntilTheLiftHeightIsKnown) {
  Fixture f = make_fixture(0.005);
  HapticTick tick(*f.scene, lifted_rig(f), no_fade_in());
  ASSERT_NE(tick.add_base_sensor_sample(0.0, f.rig->X_is900_base_sensor_from_base({})), BaseSampleStatus::Invalid);
  const auto unknown = tick.tick(0.001, 0.001, tool(kQ));
  EXPECT_TRUE(unknown.startup);  // the arm's place is not known: start-up, neither stale nor a fault
  EXPECT_FALSE(unknown.p_W_hip.allFinite());
  EXPECT_EQ(unknown.force_D_N, Eigen::Vector3d::Zero());
  EXPECT_TRUE(std::isnan(unknown.lift_m));
  tick.set_lift_m(0.0);
  const auto known = tick.tick(0.002, 0.001, tool(kQ));
  EXPECT_FALSE(known.startup);
  EXPECT_TRUE(known.p_W_hip.allFinite());
  EXPECT_EQ(known.lift_m, 0.0);
}

TEST(HapticTick, TheLiftCarriesTheHipAndTheSameToolTouchesOnlyWhereTheLiftPutsIt) {
  // The box's top is 5 mm below the HIP with the lift at 0: raised 0.2 m the hand is in
  // free space; lowered 10 mm the HIP is 5 mm into the box and is pushed up.
  Fixture f = make_fixture(0.005);
  HapticTick tick(*f.scene, lifted_rig(f), no_fade_in());
  const Eigen::Vector3d hip_at_0 = f.rig->p_W_hip(f.rig->X_W_robot_from_base({}), kQ);
  tick.set_lift_m(0.2);
  HapticTickOutput out;
  for (int k = 0; k < 10; ++k) {
    tick.add_base_sensor_sample(1e-3 * k, f.rig->X_is900_base_sensor_from_base({}));
    out = tick.tick(1e-3 * k, 0.001, tool(kQ));
  }
  EXPECT_NEAR((out.p_W_hip - hip_at_0 - Eigen::Vector3d(0.0, 0.2, 0.0)).norm(), 0.0, 1e-12);
  EXPECT_FALSE(out.in_contact);
  // Down at 0.3 m/s, one tick at a time (the proxy never jumps), to 10 mm below 0.
  double lift_m = 0.2;
  for (int k = 10; lift_m > -0.01; ++k) {
    lift_m = std::max(-0.01, lift_m - 0.3e-3);
    tick.set_lift_m(lift_m);
    tick.add_base_sensor_sample(1e-3 * k, f.rig->X_is900_base_sensor_from_base({}));
    out = tick.tick(1e-3 * k, 0.001, tool(kQ));
  }
  ASSERT_TRUE(out.in_contact);
  EXPECT_NEAR(out.p_W_hip.y(), hip_at_0.y() - 0.01, 1e-12);
  EXPECT_NEAR(out.force_W_N.y(), 500.0 * 0.005, 0.05);
  // The lift only translates: the force in the device frame is the unlifted rig's.
  EXPECT_NEAR((out.force_D_N - f.rig->force_P_from_W(f.rig->X_W_robot_from_base({}), out.force_W_N)).norm(), 0.0,
              1e-12);
}

TEST(HapticTick, ALiftHeightGivenToARigWithoutALiftChangesNothing) {
  Fixture f = make_fixture(0.005);
  HapticTick tick(*f.scene, *f.rig, no_fade_in());
  tick.set_lift_m(0.3);
  ASSERT_NE(tick.add_base_sensor_sample(0.0, f.rig->X_is900_base_sensor_from_base({})), BaseSampleStatus::Invalid);
  const auto out = tick.tick(0.001, 0.001, tool(kQ));
  EXPECT_EQ(out.lift_m, 0.0);
  EXPECT_NEAR((out.p_W_hip - f.rig->p_W_hip(f.rig->X_W_robot_from_base({}), kQ)).norm(), 0.0, 1e-12);
}

}  // namespace

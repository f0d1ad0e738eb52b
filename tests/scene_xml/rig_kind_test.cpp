// <rig kind="...">: what a desktop rig refuses, each at its file:line, and what both kinds
// accept (docs/desktop.md).
#include "scene/rig_kind_check.h"
#include "scene_xml/scene_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mhd {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

std::vector<std::string> messages_of(const Result<SceneDescription>& r) {
  std::vector<std::string> out;
  for (const Diagnostic& d : r.diagnostics()) out.push_back(d.to_string());
  return out;
}

/// A scene with a sphere and the given rig and plugins; line 3 is the <rig> line.
std::string scene(const std::string& rig_and_more) {
  return "<?xml version=\"1.0\"?>\n<scene version=\"1\" unit=\"m\">\n" + rig_and_more +
         "\n  <object name=\"ball\"><material stiffness_N_per_m=\"500\"/><sphere radius=\"0.05\"/></object>\n</scene>\n";
}

constexpr const char* kDesktopRig = R"(  <rig kind="desktop">
    <frame name="device" parent="world" position="0 0.75 0"/>
  </rig>)";

TEST(RigKind, ADesktopRigWithADeviceIsAccepted) {
  const Result<SceneDescription> r = read_scene_string(
      scene(std::string(kDesktopRig) + R"(
  <plugins><plugin kind="device" name="sim_phantom"/></plugins>)"),
      "mem/desk.xml");
  ASSERT_TRUE(r.ok()) << testing::PrintToString(messages_of(r));
  EXPECT_EQ(r->rig_kind.kind, RigKind::Desktop);
  ASSERT_TRUE(r->rig_kind.where);
  EXPECT_EQ(r->rig_kind.where->line, 3);
  EXPECT_THAT(check_rig_plugins_for_run(*r), IsEmpty());
}

TEST(RigKind, MobileIsTheDefaultAndMayBeSaid) {
  for (const std::string rig : {"", "  <rig kind=\"mobile\"/>"}) {
    const Result<SceneDescription> r = read_scene_string(scene(rig), "mem/mobile.xml");
    ASSERT_TRUE(r.ok()) << rig << testing::PrintToString(messages_of(r));
    EXPECT_EQ(r->rig_kind.kind, RigKind::Mobile);
    EXPECT_EQ(r->rig_kind.where.has_value(), !rig.empty());
  }
}

TEST(RigKind, ADesktopRigRefusesATrackerABaseAndAPlannerEachAtItsLine) {
  const Result<SceneDescription> r = read_scene_string(scene(std::string(kDesktopRig) + R"(
  <plugins>
    <plugin kind="device" name="sim_phantom"/>
    <plugin kind="tracker" name="sim_is900"/>
    <plugin kind="base" name="sim_omni3"/>
  </plugins>
  <planner kind="predictive"/>)"),
                                              "mem/desk.xml");
  EXPECT_FALSE(r.ok());
  EXPECT_THAT(messages_of(r),
              ElementsAre("mem/desk.xml:8: error: tracker plugin 'sim_is900' in a desktop rig (declared at "
                          "mem/desk.xml:3): a desktop device is fixed in the world and has no tracker (use <rig "
                          "kind=\"mobile\">)",
                          "mem/desk.xml:9: error: base plugin 'sim_omni3' in a desktop rig (declared at "
                          "mem/desk.xml:3): a desktop device is fixed in the world and has no base (use <rig "
                          "kind=\"mobile\">)",
                          "mem/desk.xml:11: error: <planner> in a desktop rig (declared at mem/desk.xml:3): there is "
                          "no base to plan for (use <rig kind=\"mobile\">)"));
}

TEST(RigKind, ADesktopRigNeedsItsDeviceFrameOnTheWorldAndNoOther) {
  const Result<SceneDescription> missing = read_scene_string(scene("  <rig kind=\"desktop\"/>"), "mem/desk.xml");
  EXPECT_THAT(messages_of(missing), ElementsAre("mem/desk.xml:3: error: a desktop rig needs the device's pose: <frame "
                                             "name=\"device\" parent=\"world\" .../>"));
  const Result<SceneDescription> other = read_scene_string(scene(R"(  <rig kind="desktop">
    <frame name="table" parent="world"/>
    <frame name="device" parent="table"/>
  </rig>)"),
                                                  "mem/desk.xml");
  EXPECT_THAT(messages_of(other),
              ElementsAre("mem/desk.xml:4: error: rig frame 'table' in a desktop rig (declared at mem/desk.xml:3): its "
                          "only frame is 'device' (parent 'world')",
                          "mem/desk.xml:5: error: rig frame 'device' of a desktop rig must have parent 'world', not "
                          "'table'",
                          "mem/desk.xml:3: error: a desktop rig needs the device's pose: <frame name=\"device\" "
                          "parent=\"world\" .../>"));
}

TEST(RigKind, AnUnknownOrContradictingKindIsAnError) {
  EXPECT_THAT(messages_of(read_scene_string(scene("  <rig kind=\"boat\"/>"), "mem/s.xml")),
              ElementsAre("mem/s.xml:3: error: invalid rig kind 'boat' (expected mobile or desktop)"));
  EXPECT_THAT(messages_of(read_scene_string(scene(std::string(kDesktopRig) + "\n  <rig kind=\"mobile\"/>"), "mem/s.xml")),
              ElementsAre("mem/s.xml:6: error: <rig kind=\"mobile\"> contradicts the rig kind declared at mem/s.xml:3"));
}

TEST(RigKind, AMobileSceneToRunNeedsATrackerAtItsPluginsLine) {
  const Result<SceneDescription> r = read_scene_string(scene(R"(  <rig kind="mobile"/>
  <plugins>
    <plugin kind="device" name="sim_phantom"/>
  </plugins>)"),
                                              "mem/mobile.xml");
  ASSERT_TRUE(r.ok()) << testing::PrintToString(messages_of(r));  // valid as a file: the rig may come later
  std::vector<std::string> run;
  for (const Diagnostic& d : check_rig_plugins_for_run(*r)) run.push_back(d.to_string());
  EXPECT_THAT(run, ElementsAre("mem/mobile.xml:4: error: the scene names no tracker plugin (<plugin "
                               "kind=\"tracker\">), which a mobile rig needs (a desk with the device alone: <rig "
                               "kind=\"desktop\">, docs/desktop.md)"));
}

}  // namespace
}  // namespace mhd

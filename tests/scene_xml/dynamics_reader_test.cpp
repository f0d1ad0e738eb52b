// <dynamics> on an object: what the reader makes of it, and the exact message, at
// file:line, for each bad one (missing, negative, zero or NaN mass, negative friction, a
// scripted object made pushable); good dynamics are never refused.

#include "scene_test_support.h"
#include "scene_xml/dynamics_reader.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mhd {
namespace {

using test::to_strings;
using Lines = std::vector<std::string>;

const std::string& kFile = test::kOneBoxFile;

std::string scene_with(const std::string& children, const std::string& unit = "m") {
  return test::one_box_scene(children, unit);
}
std::string at(int line, const std::string& message) { return test::one_box_error(line, message); }
Lines errors_of(const std::string& children) { return test::one_box_errors(children); }

TEST(DynamicsReader, MassAndFrictionAreRead) {
  const Result<SceneDescription> r = read_scene_string(scene_with("    <dynamics mass_kg=\"0.6\" friction=\"0.4\"/>\n"), kFile);
  ASSERT_TRUE(r.ok()) << testing::PrintToString(to_strings(r.diagnostics()));
  ASSERT_TRUE(r->objects[0].dynamics);
  EXPECT_DOUBLE_EQ(r->objects[0].dynamics->mass_kg, 0.6);
  EXPECT_DOUBLE_EQ(r->objects[0].dynamics->friction, 0.4);
}

TEST(DynamicsReader, FrictionDefaultsAndZeroFrictionIsAccepted) {
  const Result<SceneDescription> d = read_scene_string(scene_with("    <dynamics mass_kg=\"2\"/>\n"), kFile);
  ASSERT_TRUE(d.ok());
  EXPECT_DOUBLE_EQ(d->objects[0].dynamics->friction, scene_xml::kDefaultBodyFriction);
  const Result<SceneDescription> ice = read_scene_string(scene_with("    <dynamics mass_kg=\"2\" friction=\"0\"/>\n"), kFile);
  ASSERT_TRUE(ice.ok());
  EXPECT_DOUBLE_EQ(ice->objects[0].dynamics->friction, 0.0);
  EXPECT_FALSE(read_scene_string(scene_with(""), kFile)->objects[0].dynamics);  // still objects stay still
}

TEST(DynamicsReader, BadDynamicsAreRefusedAtTheirLine) {
  EXPECT_EQ(errors_of("    <dynamics friction=\"0.3\"/>\n"),
            Lines{at(3, "missing required attribute 'mass_kg' on <dynamics>")});
  EXPECT_EQ(errors_of("    <dynamics mass_kg=\"-1\"/>\n"),
            Lines{at(3, "attribute 'mass_kg' on <dynamics> must be > 0, got -1")});
  EXPECT_EQ(errors_of("    <dynamics mass_kg=\"0\"/>\n"),
            Lines{at(3, "attribute 'mass_kg' on <dynamics> must be > 0, got 0")});
  EXPECT_EQ(errors_of("    <dynamics mass_kg=\"nan\"/>\n"),
            Lines{at(3, "non-finite number 'nan' for attribute 'mass_kg' on <dynamics>")});
  EXPECT_EQ(errors_of("    <dynamics mass_kg=\"1\" friction=\"-0.1\"/>\n"),
            Lines{at(3, "attribute 'friction' on <dynamics> must be >= 0, got -0.1")});
  EXPECT_EQ(errors_of("    <dynamics mass_kg=\"1\" density=\"3\"/>\n"),
            Lines{at(3, "unknown attribute 'density' on <dynamics>")});
  EXPECT_EQ(errors_of("    <motion velocity=\"0 0 0.1\"/>\n"
                      "    <dynamics mass_kg=\"1\"/>\n"),
            Lines{at(4, "object 'o' has both <motion> (line 3) and <dynamics>: it is scripted or pushed, not both")});
}

}  // namespace
}  // namespace mhd

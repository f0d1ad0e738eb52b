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

using test::kOneBoxFile;
using test::one_box_error;
using test::one_box_errors;
using test::one_box_scene;
using test::to_strings;
using Lines = std::vector<std::string>;

TEST(DynamicsReader, MassAndFrictionAreRead) {
  const Result<SceneDescription> r = read_scene_string(one_box_scene("    <dynamics mass_kg=\"0.6\" friction=\"0.4\"/>\n"), kOneBoxFile);
  ASSERT_TRUE(r.ok()) << testing::PrintToString(to_strings(r.diagnostics()));
  ASSERT_TRUE(r->objects[0].dynamics);
  EXPECT_DOUBLE_EQ(r->objects[0].dynamics->mass_kg, 0.6);
  EXPECT_DOUBLE_EQ(r->objects[0].dynamics->friction, 0.4);
}

TEST(DynamicsReader, FrictionDefaultsAndZeroFrictionIsAccepted) {
  const Result<SceneDescription> d = read_scene_string(one_box_scene("    <dynamics mass_kg=\"2\"/>\n"), kOneBoxFile);
  ASSERT_TRUE(d.ok());
  EXPECT_DOUBLE_EQ(d->objects[0].dynamics->friction, scene_xml::kDefaultBodyFriction);
  const Result<SceneDescription> ice = read_scene_string(one_box_scene("    <dynamics mass_kg=\"2\" friction=\"0\"/>\n"), kOneBoxFile);
  ASSERT_TRUE(ice.ok());
  EXPECT_DOUBLE_EQ(ice->objects[0].dynamics->friction, 0.0);
  EXPECT_FALSE(read_scene_string(one_box_scene(""), kOneBoxFile)->objects[0].dynamics);  // still objects stay still
}

TEST(DynamicsReader, BadDynamicsAreRefusedAtTheirLine) {
  EXPECT_EQ(one_box_errors("    <dynamics friction=\"0.3\"/>\n"),
            Lines{one_box_error(3, "missing required attribute 'mass_kg' on <dynamics>")});
  EXPECT_EQ(one_box_errors("    <dynamics mass_kg=\"-1\"/>\n"),
            Lines{one_box_error(3, "attribute 'mass_kg' on <dynamics> must be > 0, got -1")});
  EXPECT_EQ(one_box_errors("    <dynamics mass_kg=\"0\"/>\n"),
            Lines{one_box_error(3, "attribute 'mass_kg' on <dynamics> must be > 0, got 0")});
  EXPECT_EQ(one_box_errors("    <dynamics mass_kg=\"nan\"/>\n"),
            Lines{one_box_error(3, "non-finite number 'nan' for attribute 'mass_kg' on <dynamics>")});
  EXPECT_EQ(one_box_errors("    <dynamics mass_kg=\"1\" friction=\"-0.1\"/>\n"),
            Lines{one_box_error(3, "attribute 'friction' on <dynamics> must be >= 0, got -0.1")});
  EXPECT_EQ(one_box_errors("    <dynamics mass_kg=\"1\" density=\"3\"/>\n"),
            Lines{one_box_error(3, "unknown attribute 'density' on <dynamics>")});
  EXPECT_EQ(one_box_errors("    <motion velocity=\"0 0 0.1\"/>\n"
                      "    <dynamics mass_kg=\"1\"/>\n"),
            Lines{one_box_error(4, "object 'o' has both <motion> (line 3) and <dynamics>: it is scripted or pushed, not both")});
}

}  // namespace
}  // namespace mhd

// <sharing rig_id> and its <shared_object object id rigs>: what the reader makes of a
// good one, and the exact message, at file:line, for each bad one (a rig id or object id
// out of range, NaN or negative; rigs empty, repeated, too many or without this rig; an
// object missing, not pushable, shared twice; an id taken; a second <sharing>).

#include "scene_test_support.h"
#include "scene_xml/scene_reader.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mhd::sharing_reader_test {

using test::to_strings;
using Lines = std::vector<std::string>;

const std::string kFile = "scene.xml";

// A scene with a pushable box (line 2), a still wall (line 3), and `sharing` from line 4 on.
std::string scene_with(const std::string& sharing) {
  return "<scene version=\"1\" unit=\"m\">\n"
         "  <object name=\"box\"><box size=\"0.1 0.1 0.1\"/><material stiffness_N_per_m=\"1000\"/><dynamics mass_kg=\"1\"/></object>\n"
         "  <object name=\"wall\"><box size=\"1 1 0.1\"/><material stiffness_N_per_m=\"1000\"/></object>\n" +
         sharing + "</scene>\n";
}

std::string error_at(int line, const std::string& message) {
  return kFile + ":" + std::to_string(line) + ": error: " + message;
}

Lines errors_of(const std::string& sharing) {
  const Result<SceneDescription> r = read_scene_string(scene_with(sharing), kFile);
  EXPECT_FALSE(r.ok());
  return to_strings(r.diagnostics());
}

TEST(SharingReader, ASharedObjectIsReadWithItsRigsInOrder) {
  const Result<SceneDescription> r = read_scene_string(
      scene_with("  <sharing rig_id=\"2\">\n    <shared_object object=\"box\" id=\"7\" rigs=\" 3  2 999999\"/>\n"
                 "  </sharing>\n"),
      kFile);
  ASSERT_TRUE(r.ok()) << testing::PrintToString(to_strings(r.diagnostics()));
  ASSERT_TRUE(r->sharing);
  EXPECT_EQ(r->sharing->rig_id, 2u);
  ASSERT_EQ(r->sharing->objects.size(), 1u);
  const SharedObjectDescription& o = r->sharing->objects[0];
  EXPECT_EQ(o.object, "box");
  EXPECT_EQ(o.id, 7u);
  EXPECT_EQ(o.rigs, (std::vector<std::uint32_t>{3, 2, 999999}));
  EXPECT_EQ(o.where.line, 5);
  EXPECT_FALSE(read_scene_string(scene_with(""), kFile)->sharing);  // none: nothing shared
}

TEST(SharingReader, BadRigIdsAndObjectIdsAreRefusedAtTheirLine) {
  const std::string box = "    <shared_object object=\"box\" id=\"1\" rigs=\"1 2\"/>\n";
  EXPECT_EQ(errors_of("  <sharing>\n" + box + "  </sharing>\n"),
            Lines{error_at(4, "missing required attribute 'rig_id' on <sharing>")});
  for (const std::string bad : {"-1", "nan", "1.5", "1000000", "inf"}) {
    SCOPED_TRACE(bad);
    const Lines e = errors_of("  <sharing rig_id=\"" + bad + "\">\n" + box + "  </sharing>\n");
    ASSERT_FALSE(e.empty());
    EXPECT_NE(e[0].find("scene.xml:4: error: "), std::string::npos) << e[0];
    EXPECT_NE(e[0].find("rig_id"), std::string::npos) << e[0];
  }
  for (const std::string bad : {"-1", "nan", "2147483648", "x"}) {
    SCOPED_TRACE(bad);
    const Lines e =
        errors_of("  <sharing rig_id=\"1\">\n    <shared_object object=\"box\" id=\"" + bad + "\" rigs=\"1\"/>\n"
                  "  </sharing>\n");
    ASSERT_FALSE(e.empty());
    EXPECT_NE(e[0].find("scene.xml:5: error: "), std::string::npos) << e[0];
    EXPECT_NE(e[0].find("'id'"), std::string::npos) << e[0];
  }
}

TEST(SharingReader, BadRigListsAreRefusedAtTheirLine) {
  const auto with_rigs = [](const std::string& rigs) {
    return errors_of("  <sharing rig_id=\"1\">\n    <shared_object object=\"box\" id=\"1\" rigs=\"" + rigs +
                     "\"/>\n  </sharing>\n");
  };
  EXPECT_EQ(with_rigs(" "), Lines{error_at(5, "rigs must name at least one rig")});
  EXPECT_EQ(with_rigs("1 2 1"), Lines{error_at(5, "rigs names rig 1 twice")});
  EXPECT_EQ(with_rigs("1 -2"), Lines{error_at(5, "rigs must be rig ids in [0, 999999], got '1 -2'")});
  EXPECT_EQ(with_rigs("1 1000000"), Lines{error_at(5, "rigs must be rig ids in [0, 999999], got '1 1000000'")});
  EXPECT_EQ(with_rigs("1 nan"), Lines{error_at(5, "rigs must be rig ids in [0, 999999], got '1 nan'")});
  EXPECT_EQ(with_rigs("1 2 3 4 5 6 7 8 9"), Lines{error_at(5, "rigs names more than 8 rigs")});
  EXPECT_EQ(with_rigs("2 3"),
            Lines{error_at(5, "shared object 'box': rigs does not name this rig (<sharing rig_id=\"1\">)")});
  // The dual: eight distinct rigs, this one among them, are accepted.
  EXPECT_TRUE(read_scene_string(scene_with("  <sharing rig_id=\"8\">\n    <shared_object object=\"box\" id=\"1\" "
                                           "rigs=\"1 2 3 4 5 6 7 8\"/>\n  </sharing>\n"),
                                kFile)
                  .ok());
}

TEST(SharingReader, ObjectsMustExistBePushableAndBeSharedOnceUnderIdsOfTheirOwn) {
  const auto shared = [](const std::string& objects) {
    return errors_of("  <sharing rig_id=\"1\">\n" + objects + "  </sharing>\n");
  };
  EXPECT_EQ(shared("    <shared_object object=\"crate\" id=\"1\" rigs=\"1\"/>\n"),
            Lines{error_at(5, "shared object 'crate' is not an <object> of the scene")});
  EXPECT_EQ(shared("    <shared_object object=\"wall\" id=\"1\" rigs=\"1\"/>\n"),
            Lines{error_at(5, "shared object 'wall' is not pushable: only an object with <dynamics> can be shared "
                              "(its authority runs its physics)")});
  EXPECT_EQ(shared("    <shared_object object=\"box\" id=\"1\" rigs=\"1\"/>\n"
                   "    <shared_object object=\"box\" id=\"2\" rigs=\"1\"/>\n"),
            Lines{error_at(6, "object 'box' is shared twice (the first at line 5)")});
  EXPECT_EQ(errors_of("  <object name=\"box2\"><box size=\"0.1 0.1 0.1\"/><material stiffness_N_per_m=\"1000\"/><dynamics mass_kg=\"1\"/></object>\n"
                      "  <sharing rig_id=\"1\">\n"
                      "    <shared_object object=\"box\" id=\"4\" rigs=\"1\"/>\n"
                      "    <shared_object object=\"box2\" id=\"4\" rigs=\"1\"/>\n  </sharing>\n"),
            Lines{error_at(7, "shared object id 4 is taken by 'box' (line 6)")});
  EXPECT_EQ(shared("    <share object=\"box\"/>\n"),
            (Lines{error_at(5, "unknown element <share> in <sharing> (expected <shared_object>)"),
                   error_at(4, "<sharing> names no <shared_object>")}));
}

TEST(SharingReader, AScenesSecondSharingIsRefused) {
  EXPECT_EQ(errors_of("  <sharing rig_id=\"1\"><shared_object object=\"box\" id=\"1\" rigs=\"1\"/></sharing>\n"
                      "  <sharing rig_id=\"2\"><shared_object object=\"box\" id=\"1\" rigs=\"2\"/></sharing>\n"),
            Lines{error_at(5, "a scene has one <sharing> (the first is at scene.xml:4)")});
}

}  // namespace mhd::sharing_reader_test

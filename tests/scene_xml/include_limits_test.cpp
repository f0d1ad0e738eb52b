// Includes within bounds: nesting deeper than 64 is refused with the
// chain (4,000 levels give that error, not a stack overflow), a symlink loop is named as
// one, and a FIFO is refused without being opened.
#include "scene_xml/scene_reader.h"

#include "../mesh_io/test_mesh_files.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <string>
#include <vector>

namespace mhd {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

std::vector<std::string> messages(const Result<SceneDescription>& r) {
  std::vector<std::string> lines;
  for (const auto& d : r.diagnostics()) lines.push_back(d.to_string());
  return lines;
}

using Lines = std::vector<std::string>;

std::string level(int i) {
  std::string name = "d";
  name += std::to_string(i);
  return name + ".xml";
}

/// A scene file that includes `next` on line 2.
std::string including(const std::string& next) {
  std::string xml = "<scene version=\"1\">\n  <include file=\"";
  xml += next;
  return xml + "\"/>\n</scene>\n";
}

TEST(IncludeLimits, FourThousandLevelsStopAtSixtyFourWithTheChain) {
  TempDir dir;
  constexpr int kLevels = 4000;
  for (int i = 0; i < kLevels; ++i) {
    test::write_text(dir / level(i), including(level(i + 1)));
  }
  test::write_text(dir / level(kLevels), "<scene version=\"1\"/>\n");
  std::string chain;
  for (int i = 0; i <= 65; ++i) {
    if (i > 0) chain += " -> ";
    chain += (dir / level(i)).string();
  }
  EXPECT_EQ(messages(read_scene_file(dir / level(0))),
            (Lines{(dir / level(64)).string() + ":2: error: includes nested deeper than 64: " + chain}));
}

// A diamond: each of 40 files includes the next twice (2^40 paths through it). Each file is
// read once, so it is read at once, and the material at its bottom is defined once.
TEST(IncludeLimits, ADiamondOfFortyLevelsIsReadOnceAFile) {
  TempDir dir;
  constexpr int kLevels = 40;
  for (int i = 0; i < kLevels; ++i) {
    std::string xml = "<scene version=\"1\">\n  <include file=\"" + level(i + 1) + "\"/>\n  <include file=\"" +
                      level(i + 1) + "\"/>\n</scene>\n";
    test::write_text(dir / level(i), xml);
  }
  test::write_text(dir / level(kLevels),
                   "<scene version=\"1\">\n  <material name=\"bottom\" stiffness_N_per_m=\"500\"/>\n</scene>\n");
  const Result<SceneDescription> r = read_scene_file(dir / level(0));
  ASSERT_TRUE(r.ok()) << ::testing::PrintToString(messages(r));
  EXPECT_EQ(r->materials.count("bottom"), 1u);
}

// The dual: a file included once, and one included by two parts, still defines what it
// defines (once), and a part that is not read twice still counts everything it holds.
TEST(IncludeLimits, AFileTwoPartsIncludeDefinesItsMaterialOnce) {
  TempDir dir;
  test::write_text(dir / "materials.xml",
                   "<scene version=\"1\">\n  <material name=\"shared\" stiffness_N_per_m=\"500\"/>\n</scene>\n");
  test::write_text(dir / "a.xml", including("materials.xml"));
  test::write_text(dir / "b.xml", including("materials.xml"));
  test::write_text(dir / "root.xml",
                   "<scene version=\"1\">\n  <include file=\"a.xml\"/>\n  <include file=\"b.xml\"/>\n"
                   "  <object name=\"ball\" material=\"shared\"><sphere radius=\"0.1\"/></object>\n</scene>\n");
  const Result<SceneDescription> r = read_scene_file(dir / "root.xml");
  ASSERT_TRUE(r.ok()) << ::testing::PrintToString(messages(r));
  EXPECT_EQ(r->materials.count("shared"), 1u);
  ASSERT_EQ(r->objects.size(), 1u);
}

TEST(IncludeLimits, SixtyFourLevelsAreAllowed) {
  TempDir dir;
  for (int i = 0; i < 64; ++i) {
    test::write_text(dir / level(i), including(level(i + 1)));
  }
  test::write_text(dir / level(64), "<scene version=\"1\"/>\n");
  const Result<SceneDescription> r = read_scene_file(dir / level(0));
  EXPECT_TRUE(r.ok()) << messages(r).front();
}

TEST(IncludeLimits, SymlinkLoopIsNamedAsOne) {
  TempDir dir;
  fs::create_symlink("b.xml", dir / "a.xml");
  fs::create_symlink("a.xml", dir / "b.xml");
  test::write_text(dir / "root.xml", "<scene version=\"1\">\n  <include file=\"a.xml\"/>\n</scene>\n");
  EXPECT_EQ(messages(read_scene_file(dir / "root.xml")),
            (Lines{(dir / "root.xml").string() + ":2: error: included file 'a.xml' is a symlink loop (resolved to '" +
                   (dir / "a.xml").string() + "')"}));
  EXPECT_EQ(messages(read_scene_file(dir / "a.xml")),
            (Lines{(dir / "a.xml").string() + ": error: scene file is a symlink loop"}));
}

TEST(IncludeLimits, MeshFileThatIsASymlinkLoopIsNamedAsOne) {
  TempDir dir;
  fs::create_symlink("loop.obj", dir / "loop.obj");
  test::write_text(dir / "root.xml",
                   "<scene version=\"1\">\n  <object name=\"o\">\n    <material stiffness_N_per_m=\"100\"/>\n"
                   "    <mesh file=\"loop.obj\"/>\n  </object>\n</scene>\n");
  const Lines got = messages(read_scene_file(dir / "root.xml"));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].find((dir / "root.xml").string() + ":4: error: mesh file 'loop.obj' is a symlink loop"), 0u)
      << got[0];
}

TEST(IncludeLimits, FifoIsRefusedWithoutBlocking) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "pipe.xml").c_str(), 0600), 0);
  test::write_text(dir / "root.xml", "<scene version=\"1\">\n  <include file=\"pipe.xml\"/>\n</scene>\n");
  EXPECT_EQ(messages(read_scene_file(dir / "root.xml")),
            (Lines{(dir / "root.xml").string() + ":2: error: included file 'pipe.xml' is not a regular file (resolved "
                                                 "to '" + (dir / "pipe.xml").string() + "')"}));
  EXPECT_EQ(messages(read_scene_file(dir / "pipe.xml")),
            (Lines{(dir / "pipe.xml").string() + ": error: scene file is not a regular file"}));
}

}  // namespace
}  // namespace mhd

#pragma once
// GoogleTest fixture for tests that touch a scene file: loads and compiles it (BVH cache
// in the build tree, never the user's), builds the exact oracle over it, drives the
// proxy along HIP paths and counts pop-throughs.
//
//   class BunnyTest : public mhd::test::SceneFixture {};
//   TEST_F(BunnyTest, NoPopThrough) {
//     ASSERT_NO_FATAL_FAILURE(load("tests/data/scenes/bunny.xml"));
//     for (const auto& s : anchor_strokes(1, 200).strokes)
//       EXPECT_EQ(count_crossings(drive(s.p_W_hip, 1000.0)), 0U);
//   }

#include "verification/proxy_drive.h"
#include "scene_compiler/compiled_scene.h"
#include "verification/stroke_set.h"
#include "verification/surface_crossing_oracle.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace mhd::test {

// The fixture is written in terms of the verification tools.
using namespace mhd::verify;

class SceneFixture : public ::testing::Test {
 protected:
  /// Reads and compiles a scene; a fatal test failure listing every diagnostic if either
  /// step reports any (wrap in ASSERT_NO_FATAL_FAILURE to stop the test there).
  void load(const std::string& scene_path_relative_to_repo);

  /// Resets the proxy at hip_path_W[0] and steps it once per sample at rate_Hz.
  /// Fails the test (and returns nothing) when no scene is loaded or the first sample
  /// is not in free space.
  TickRecord drive(const std::vector<Eigen::Vector3d>& hip_path_W, double rate_Hz);

  /// Legs of the recorded proxy path that touch the surface (0 means no pop-through).
  [[nodiscard]] std::size_t count_crossings(const TickRecord& records) const;
  [[nodiscard]] std::vector<Crossing> find_crossings(const TickRecord& records) const;
  /// Ticks that ended with the proxy inside or on a closed object.
  [[nodiscard]] std::size_t count_ticks_inside(const TickRecord& records) const;

  /// The benchmark protocol's strokes (docs/benchmarks.md) and the fast stress strokes over the loaded scene.
  [[nodiscard]] StrokeSet anchor_strokes(std::uint64_t seed, int count, const AnchorStrokeParams& params = {}) const;
  [[nodiscard]] StrokeSet fast_strokes(std::uint64_t seed, int count, const FastStrokeParams& params = {}) const;

  /// The loaded scene and its oracle; throw std::logic_error (a test failure) if none.
  [[nodiscard]] CompiledScene& scene();
  [[nodiscard]] const SurfaceCrossingOracle& oracle() const;
  /// The index of the loaded scene's object `name`; a test failure (and 0) when it has none.
  [[nodiscard]] int object(const std::string& name);
  /// Re-snapshots the world after objects were moved with set_pose().
  void rebuild_oracle();

  /// `relative` resolved against the source tree's root (MHD_SOURCE_DIR).
  [[nodiscard]] static std::filesystem::path source_path(const std::string& relative);
  /// The BVH cache the fixture compiles with, under the build tree.
  [[nodiscard]] static std::filesystem::path bvh_cache_dir();

 private:
  std::unique_ptr<CompiledScene> scene_;
  std::unique_ptr<SurfaceCrossingOracle> oracle_;
};

}  // namespace mhd::test

#pragma once
// The procedural bottlenose dolphin as a continuous closed surface, before tessellation.
//
// Construction (docs/assets.md): in a "straight" frame the body is a stack of planar
// cross-sections along a straight axis, from the beak tip to the tail end. Each section
// is star-shaped about its centre: a radial function that is the smooth union (p-norm) of
// the body (two super-ellipse halves) and thin ellipses for the fins (the dorsal fin
// pointing up, the pectoral fins pointing down and out, the fluke along z). Every section
// is a simple closed curve in its own plane, so the surface is embedded and of genus 0.
// Shears along x (each one-to-one on the surface) then sweep the pectoral fins and the
// fluke lobes back, which cuts the fluke's notch, and hook the dorsal fin (falcate).

#include <Eigen/Core>

#include <vector>

namespace mhd::mesh_gen {

/// Points for checking a dolphin mesh, in the output frame (metres).
struct DolphinLandmarks {
  Eigen::Vector3d p_body_centre_m;     ///< inside: the middle of the thickest section
  Eigen::Vector3d p_dorsal_fin_m;      ///< inside: halfway up the dorsal fin
  Eigen::Vector3d p_pectoral_fin_m;    ///< inside: halfway out along one pectoral fin
  Eigen::Vector3d p_fluke_lobe_m;      ///< inside: well out on one fluke lobe
  Eigen::Vector3d p_fluke_notch_m;     ///< outside: between the fluke lobes, behind the notch
  Eigen::Vector3d p_above_back_m;      ///< outside: just above the back, in front of the dorsal fin
  Eigen::Vector3d p_beak_tip_m;        ///< the nose pole (on the surface)
};

/// Output frame: nose towards +x, back towards +y, flukes in the x-z plane, centred on
/// the bounding box of the continuous surface, 2.0 m from beak tip to fluke tips.
class DolphinShape {
 public:
  DolphinShape();

  /// Surface point for s in (0, 1) along the body (0 = beak tip, 1 = tail end) and theta
  /// round it (-pi/2 = belly, pi/2 = back, 0 and pi the flanks).
  [[nodiscard]] Eigen::Vector3d point(double s, double theta) const;
  /// The two poles: s = 0 (beak tip) and s = 1 (tail end, the fluke notch).
  [[nodiscard]] Eigen::Vector3d nose() const;
  [[nodiscard]] Eigen::Vector3d tail() const;

  [[nodiscard]] const DolphinLandmarks& landmarks() const& { return landmarks_; }
  // A reference into a temporary shape would dangle.
  const DolphinLandmarks& landmarks() const&& = delete;

  /// Evaluates a whole ring at once (faster than point() per vertex).
  void ring(double s, const std::vector<double>& thetas, std::vector<Eigen::Vector3d>& out) const;

  static constexpr double kLength_m = 2.0;
  /// The pectoral fins point this far below the horizontal (straight frame), radians.
  static constexpr double kPectoralDihedral = 0.52;
  /// Angles in [-pi/2, pi/2) that every ring should sample exactly: the belly, the right
  /// pectoral fin and the right flank (fluke); the back (pi/2) and the mirror images
  /// (pi - theta) complete the set.
  [[nodiscard]] static std::vector<double> feature_angles();

 private:
  struct Section;
  [[nodiscard]] static double body_radius(const Section& s, double cz, double sy);
  [[nodiscard]] Section section(double u) const;
  [[nodiscard]] Eigen::Vector3d straight_point(const Section& sec, double theta) const;
  [[nodiscard]] Eigen::Vector3d to_output(const Eigen::Vector3d& p_straight) const;

  double scale_ = 1.0;
  Eigen::Vector3d offset_ = Eigen::Vector3d::Zero();
  DolphinLandmarks landmarks_;
};

}  // namespace mhd::mesh_gen

#pragma once
// A smooth 1-D profile through control points: monotone piecewise-cubic (Fritsch-Carlson)
// interpolation, so a profile never overshoots between its control values. Outside the
// control range it holds the end values.

#include <utility>
#include <vector>

namespace mhd::mesh_gen {

class ProfileCurve {
 public:
  /// Control points (t, value) with strictly increasing t; at least two.
  explicit ProfileCurve(std::vector<std::pair<double, double>> points);

  [[nodiscard]] double operator()(double t) const;

 private:
  std::vector<double> t_;
  std::vector<double> v_;
  std::vector<double> slope_;  ///< dv/dt at each control point
};

}  // namespace mhd::mesh_gen

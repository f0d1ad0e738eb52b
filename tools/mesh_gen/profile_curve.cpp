#include "mesh_gen/profile_curve.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mhd::mesh_gen {

ProfileCurve::ProfileCurve(std::vector<std::pair<double, double>> points) {
  if (points.size() < 2) throw std::invalid_argument("ProfileCurve needs at least two points");
  for (const auto& [t, v] : points) {
    if (!t_.empty() && !(t > t_.back())) throw std::invalid_argument("ProfileCurve: t must increase");
    t_.push_back(t);
    v_.push_back(v);
  }
  const std::size_t n = t_.size();
  std::vector<double> secant(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) secant[i] = (v_[i + 1] - v_[i]) / (t_[i + 1] - t_[i]);
  slope_.assign(n, 0.0);
  slope_[0] = secant[0];
  slope_[n - 1] = secant[n - 2];
  for (std::size_t i = 1; i + 1 < n; ++i) {
    // Zero slope at local extrema; otherwise a weighted harmonic mean (Fritsch-Butland),
    // which keeps every interval monotone.
    if (secant[i - 1] * secant[i] <= 0.0) continue;
    const double h0 = t_[i] - t_[i - 1];
    const double h1 = t_[i + 1] - t_[i];
    const double w0 = 2.0 * h1 + h0;
    const double w1 = h1 + 2.0 * h0;
    slope_[i] = (w0 + w1) / (w0 / secant[i - 1] + w1 / secant[i]);
  }
}

double ProfileCurve::operator()(double t) const {
  if (t <= t_.front()) return v_.front();
  if (t >= t_.back()) return v_.back();
  const auto upper = std::upper_bound(t_.begin(), t_.end(), t);
  const auto i = static_cast<std::size_t>(upper - t_.begin()) - 1;
  const double h = t_[i + 1] - t_[i];
  const double s = (t - t_[i]) / h;
  const double s2 = s * s;
  const double s3 = s2 * s;
  const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
  const double h10 = s3 - 2.0 * s2 + s;
  const double h01 = -2.0 * s3 + 3.0 * s2;
  const double h11 = s3 - s2;
  return h00 * v_[i] + h10 * h * slope_[i] + h01 * v_[i + 1] + h11 * h * slope_[i + 1];
}

}  // namespace mhd::mesh_gen

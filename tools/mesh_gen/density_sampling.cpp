#include "mesh_gen/density_sampling.h"

#include <algorithm>
#include <stdexcept>

namespace mhd::mesh_gen {

std::vector<double> sample_by_density(const std::vector<double>& density, double begin, double end,
                                      int count, double offset) {
  if (density.empty() || count < 0 || !(end > begin)) throw std::invalid_argument("sample_by_density: bad arguments");
  const std::size_t bins = density.size();
  std::vector<double> cdf(bins + 1, 0.0);
  for (std::size_t i = 0; i < bins; ++i) cdf[i + 1] = cdf[i] + std::max(density[i], 0.0);
  const bool uniform = !(cdf.back() > 0.0);
  if (uniform) {
    for (std::size_t i = 0; i <= bins; ++i) cdf[i] = static_cast<double>(i);
  }
  const double total = cdf.back();
  const double bin_width = (end - begin) / static_cast<double>(bins);
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(count));
  std::size_t bin = 0;
  for (int k = 0; k < count; ++k) {
    const double target = total * (static_cast<double>(k) + offset) / static_cast<double>(count);
    while (bin + 1 < bins && cdf[bin + 1] <= target) ++bin;
    const double mass = cdf[bin + 1] - cdf[bin];
    const double frac = mass > 0.0 ? std::clamp((target - cdf[bin]) / mass, 0.0, 1.0) : 0.0;
    out.push_back(begin + (static_cast<double>(bin) + frac) * bin_width);
  }
  return out;
}

}  // namespace mhd::mesh_gen

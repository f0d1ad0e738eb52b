#pragma once
// Places samples on an interval so that their spacing follows a given density: used to
// put rings and ring vertices where a surface bends or stretches most.

#include <vector>

namespace mhd::mesh_gen {

/// `density` holds non-negative weights of equal-width bins covering [begin, end]
/// (piecewise constant). Returns `count` increasing positions at the quantiles
/// (k + offset) / count, k = 0..count-1, of that density (offset in [0, 1)).
/// A zero-sum density is treated as uniform.
[[nodiscard]] std::vector<double> sample_by_density(const std::vector<double>& density, double begin,
                                                    double end, int count, double offset);

}  // namespace mhd::mesh_gen

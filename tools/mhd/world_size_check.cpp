#include "world_size_check.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstddef>

namespace mhd::cli {

WorldSize check_world_size(const SceneDescription& description, const CompiledScene& scene) {
  WorldSize result;
  for (int i = 0; i < scene.world.object_count(); ++i) {
    ObjectExtents e;
    e.name = scene.object_names[static_cast<std::size_t>(i)];
    e.size_m = scene.world.shape(i).bounds().sizes();
    const auto named = std::find_if(description.objects.begin(), description.objects.end(),
                                    [&](const ObjectDescription& o) { return o.name == e.name; });
    if (named != description.objects.end()) e.where = named->where;
    result.objects.push_back(std::move(e));
  }
  if (result.objects.empty()) return result;
  const auto by_largest_extent = [](const ObjectExtents& a, const ObjectExtents& b) {
    return a.size_m.maxCoeff() < b.size_m.maxCoeff();
  };
  const ObjectExtents& largest = *std::max_element(result.objects.begin(), result.objects.end(), by_largest_extent);
  const ObjectExtents& smallest = *std::min_element(result.objects.begin(), result.objects.end(), by_largest_extent);
  const std::size_t n = result.objects.size();
  if (largest.size_m.maxCoeff() < kSmallestPlausibleWorld_m) {
    result.warning = Diagnostic{
        largest.where,
        fmt::format("{} '{}', is {:.3g} mm across): is the scene's unit right? (metre values in a "
                    "unit=\"mm\" scene are 1000x too small)",
                    n == 1 ? "the only object is under 1 cm (it," : fmt::format("all {} objects are under 1 cm (the largest,", n),
                    largest.name, largest.size_m.maxCoeff() * 1e3)};
  } else if (smallest.size_m.maxCoeff() > kLargestPlausibleObject_m) {
    result.warning = Diagnostic{
        smallest.where,
        fmt::format("{} '{}', is {:.3g} km across): is the scene's unit right? (millimetre values in a "
                    "unit=\"m\" scene are 1000x too large)",
                    n == 1 ? "the only object is over 1 km (it," : fmt::format("all {} objects are over 1 km (the smallest,", n),
                    smallest.name, smallest.size_m.maxCoeff() * 1e-3)};
  }
  return result;
}

}  // namespace mhd::cli

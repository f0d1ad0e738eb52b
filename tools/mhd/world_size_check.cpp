#include "world_size_check.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstddef>
#include <string_view>
#include <unordered_map>

namespace mhd::cli {

WorldSize check_world_size(const SceneDescription& description, const CompiledScene& scene) {
  WorldSize result;
  // Each object's line by its name, looked up once each: linear in the objects.
  std::unordered_map<std::string_view, const SourceLocation*> where_of;
  where_of.reserve(description.objects.size());
  for (const ObjectDescription& o : description.objects) where_of.emplace(o.name, &o.where);
  result.objects.reserve(static_cast<std::size_t>(scene.world.object_count()));
  for (int i = 0; i < scene.world.object_count(); ++i) {
    ObjectExtents e;
    e.name = scene.object_names[static_cast<std::size_t>(i)];
    e.size_m = scene.world.shape(i).bounds().sizes();
    if (const auto named = where_of.find(e.name); named != where_of.end()) e.where = *named->second;
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

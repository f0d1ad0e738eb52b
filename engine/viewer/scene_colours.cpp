#include "viewer/scene_colours.h"

#include <array>
#include <cstdint>
#include <utility>

namespace mhd::viewer {
namespace {

constexpr std::array<std::pair<std::string_view, std::array<float, 3>>, 6> kKnown = {{
    {"dolphin_skin", {0.42f, 0.55f, 0.68f}},
    {"wall", {0.80f, 0.76f, 0.70f}},
    {"rubber", {0.85f, 0.45f, 0.20f}},
    {"floor", {0.36f, 0.38f, 0.40f}},
    {"smooth", {0.75f, 0.75f, 0.80f}},
    {"benchmark", {0.60f, 0.70f, 0.45f}},
}};

std::uint32_t fnv1a(std::string_view s) {
  std::uint32_t h = 2166136261u;
  for (const char c : s) {
    h ^= static_cast<std::uint8_t>(c);
    h *= 16777619u;
  }
  return h;
}

}  // namespace

Eigen::Vector4f material_colour(std::string_view material_name, std::string_view object_name) {
  const std::string_view key = material_name.empty() ? object_name : material_name;
  for (const auto& [name, rgb] : kKnown) {
    if (name == key) return {rgb[0], rgb[1], rgb[2], 1.0f};
  }
  // Mid-saturation colours: each channel in [0.35, 0.85], never black or white.
  const std::uint32_t h = fnv1a(key);
  auto channel = [](std::uint32_t bits) { return 0.35f + 0.5f * static_cast<float>(bits & 0xffu) / 255.0f; };
  return {channel(h), channel(h >> 8), channel(h >> 16), 1.0f};
}

}  // namespace mhd::viewer

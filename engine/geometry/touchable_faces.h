#pragma once
// Which side of an object's triangles the hand can touch. A range scan is the visible
// side of a solid: touched from the front only, it is not there from behind, and a proxy
// that slipped past its boundary comes back out instead of being held behind it.
// The front of a triangle is the side its counter-clockwise normal points to.

#include <optional>
#include <string_view>

namespace mhd {

enum class TouchableFaces { Both, Front, Back };

/// "both", "front" or "back".
[[nodiscard]] constexpr std::string_view touchable_faces_name(TouchableFaces faces) {
  switch (faces) {
    case TouchableFaces::Front: return "front";
    case TouchableFaces::Back: return "back";
    case TouchableFaces::Both: break;
  }
  return "both";
}

/// The value of a touchable="..." attribute; nullopt for anything else.
[[nodiscard]] constexpr std::optional<TouchableFaces> parse_touchable_faces(std::string_view text) {
  if (text == "both") return TouchableFaces::Both;
  if (text == "front") return TouchableFaces::Front;
  if (text == "back") return TouchableFaces::Back;
  return std::nullopt;
}

/// Whether a surface approached from the side its normal points to (from_front) or from
/// the other is there for the hand.
[[nodiscard]] constexpr bool touchable_from(TouchableFaces faces, bool from_front) {
  return faces == TouchableFaces::Both || (faces == TouchableFaces::Front) == from_front;
}

}  // namespace mhd

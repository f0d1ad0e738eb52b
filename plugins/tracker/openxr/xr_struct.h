#pragma once
// An OpenXR input or output struct, zeroed with its type set: the C idiom `T s{TYPE}`
// leaves the rest zero too, but GCC warns of every member it does not name.

#include <openxr/openxr.h>

namespace mhd::openxr {

template <class T>
[[nodiscard]] T xr_struct(XrStructureType type) noexcept {
  T s{};
  s.type = type;
  return s;
}

}  // namespace mhd::openxr

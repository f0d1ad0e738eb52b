#pragma once
// Names of OpenXR result codes, for messages that must name the cause even where no
// instance exists to ask (xrResultToString needs one: a failed xrCreateInstance has none).

#include <openxr/openxr.h>

#include <string>

namespace mhd::openxr {

/// "XR_ERROR_SESSION_LOST", or "XrResult -123" for a code this loader's headers lack.
[[nodiscard]] std::string result_name(XrResult result);

/// Whether xrCreateInstance's result means no runtime is installed or active (the loader
/// found no manifest, or the one it found names no loadable library).
[[nodiscard]] bool means_no_runtime(XrResult result) noexcept;

}  // namespace mhd::openxr

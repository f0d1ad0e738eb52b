#pragma once
// The loader–runtime negotiation of the OpenXR loader (the loader's runtime interface,
// version 1), declared here from its specification: Debian's libopenxr-dev ships no
// loader_interfaces.h. The loader calls the runtime's exported
// xrNegotiateLoaderRuntimeInterface with what it supports; the runtime fills the request
// with its interface version, API version and xrGetInstanceProcAddr.

#include <openxr/openxr.h>

#include <cstddef>
#include <cstdint>

extern "C" {

enum XrLoaderInterfaceStructs : std::int32_t {
  XR_LOADER_INTERFACE_STRUCT_UNINTIALIZED = 0,
  XR_LOADER_INTERFACE_STRUCT_LOADER_INFO = 1,
  XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST = 2,
  XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST = 3,
};

inline constexpr std::uint32_t kLoaderInfoStructVersion = 1;
inline constexpr std::uint32_t kRuntimeInfoStructVersion = 1;
inline constexpr std::uint32_t kLoaderRuntimeInterfaceVersion = 1;

struct XrNegotiateLoaderInfo {
  XrLoaderInterfaceStructs structType;  ///< LOADER_INFO
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t minInterfaceVersion;
  std::uint32_t maxInterfaceVersion;
  XrVersion minApiVersion;
  XrVersion maxApiVersion;
};

struct XrNegotiateRuntimeRequest {
  XrLoaderInterfaceStructs structType;  ///< RUNTIME_REQUEST
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t runtimeInterfaceVersion;  ///< filled by the runtime
  XrVersion runtimeApiVersion;            ///< filled by the runtime
  PFN_xrGetInstanceProcAddr getInstanceProcAddr;  ///< filled by the runtime
};

}  // extern "C"

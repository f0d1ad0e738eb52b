#pragma once
// The parameters every DDS plugin takes: rig_id, domain_id, config_file and identity_dir.
// Header-only, for plugins written with the SDK (mhd/plugin_sdk.hpp), which has checked
// the values against kEndpointParams before read_endpoint reads them.

#include "dds_common/dds_entity.h"

#include <mhd/plugin_params.hpp>
#include <mhd/plugin_sdk_params.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace mhd::dds {

struct DdsEndpoint {
  std::uint32_t rig_id = 0;
  dds_domainid_t domain_id = DDS_DOMAIN_DEFAULT;
  std::string config;  ///< Cyclone configuration URI "file://PATH"; empty: $CYCLONEDDS_URI
  /// DDS Security identity folder; not given: $MHD_DDS_IDENTITY, else unsecured.
  std::optional<std::filesystem::path> identity_dir;
};

/// The parameters read_endpoint reads, for a DDS plugin's declarations (sdk::join).
inline constexpr std::array kEndpointParams{
    sdk::integer("rig_id", "", "0", "the rig whose topics this plugin uses (a DDS partition)",
                 sdk::between(0, 4294967295.0)),
    sdk::integer("domain_id", "", nullptr, "the DDS domain (default: Cyclone's)", sdk::between(0, 232)),
    sdk::text("config_file", nullptr, "a Cyclone XML configuration, relative to the scene (needs domain_id)"),
    sdk::text("identity_dir", nullptr, "DDS Security identity folder, relative to the scene (docs/networking.md)"),
};

/// Reads rig_id (default 0), domain_id (0..232, which keeps Cyclone's port numbers
/// 7400 + 250 * id + ... in range; default: the configuration's) and config_file (a
/// relative path is relative to the scene file). config_file needs domain_id.
/// identity_dir: a DDS Security identity folder (participant_security.h), a relative
/// path relative to the scene file's folder.
inline DdsEndpoint read_endpoint(const sdk::Params& params, const char* scene_file) {
  DdsEndpoint e;
  e.rig_id = static_cast<std::uint32_t>(params.integer("rig_id"));
  if (const auto domain_id = params.optional_integer("domain_id")) e.domain_id = static_cast<dds_domainid_t>(*domain_id);
  if (const auto file = params.optional_text("config_file")) {
    if (e.domain_id == DDS_DOMAIN_DEFAULT) throw sdk::ParamError("parameter 'config_file' needs 'domain_id'");
    e.config = config_file_uri(*file, scene_file);
  }
  if (const auto dir = params.optional_text("identity_dir")) {
    std::filesystem::path path(*dir);
    if (path.is_relative() && scene_file != nullptr && scene_file[0] != '\0') {
      path = std::filesystem::path(scene_file).parent_path() / path;
    }
    e.identity_dir = path;
  }
  return e;
}

/// A ROS name: letters, digits, '_' and '/' (ROS 2's rules, which DDS topic names take too).
inline std::string checked_ros_name(const char* parameter, std::string value) {
  for (const char c : value) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '/';
    if (!ok) {
      throw sdk::ParamError("parameter '" + std::string(parameter) + "' = '" + value +
                            "': a ROS name has letters, digits, '_' and '/' only");
    }
  }
  return value;
}

}  // namespace mhd::dds

#pragma once
// The parameters every DDS plugin takes: rig_id, domain_id, config_file and identity_dir. Header-only
// and for plugins that link mhd_plugin_sim_common (ParamReader).

#include "dds_common/dds_entity.h"
#include "sim_common/plugin_params.h"

#include <mhd/plugin_params.hpp>

#include <array>

#include <mhd/plugin_abi.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace mhd::dds {

struct DdsEndpoint {
  std::uint32_t rig_id = 0;
  dds_domainid_t domain_id = DDS_DOMAIN_DEFAULT;
  std::string config;  ///< Cyclone configuration URI "file://PATH"; empty: $CYCLONEDDS_URI
  /// DDS Security identity folder; not given: $MHD_DDS_IDENTITY, else unsecured.
  std::optional<std::filesystem::path> identity_dir;
};

/// An optional text parameter. ParamReader has no optional_text; required_text marks the
/// name as known (for reject_unknown's list) before it throws for a missing one.
inline std::optional<std::string> optional_text(plugin_support::ParamReader& reader, const mhd_param* params,
                                                std::size_t count, const char* name) {
  for (std::size_t i = 0; i < count; ++i) {
    if (params[i].name != nullptr && std::string_view(params[i].name) == name) return reader.required_text(name);
  }
  try {
    (void)reader.required_text(name);
  } catch (const plugin_support::ParamError&) {
  }
  return std::nullopt;
}

/// Reads rig_id (default 0), domain_id (0..232, which keeps Cyclone's port numbers
/// 7400 + 250 * id + ... in range; default: the configuration's) and config_file (a
/// relative path is relative to the scene file). config_file needs domain_id.
/// identity_dir: a DDS Security identity folder (participant_security.h), a relative
/// path relative to the scene file's folder.
/// The parameters read_endpoint reads, for a DDS plugin's declarations (sdk::join).
inline constexpr std::array kEndpointParams{
    sdk::integer("rig_id", "", "0", "the rig whose topics this plugin uses (a DDS partition)",
                 sdk::between(0, 4294967295.0)),
    sdk::integer("domain_id", "", nullptr, "the DDS domain (default: Cyclone's)", sdk::between(0, 232)),
    sdk::text("config_file", nullptr, "a Cyclone XML configuration, relative to the scene (needs domain_id)"),
    sdk::text("identity_dir", nullptr, "DDS Security identity folder, relative to the scene (docs/networking.md)"),
};

inline DdsEndpoint read_endpoint(plugin_support::ParamReader& reader, const mhd_param* params, std::size_t count,
                                 const char* scene_file) {
  constexpr std::uint64_t kNoDomain = UINT64_MAX;
  DdsEndpoint e;
  e.rig_id = static_cast<std::uint32_t>(reader.unsigned_integer("rig_id", 0, UINT32_MAX));
  const std::uint64_t domain_id = reader.unsigned_integer("domain_id", kNoDomain, 232);
  if (domain_id != kNoDomain) e.domain_id = static_cast<dds_domainid_t>(domain_id);
  if (const auto file = optional_text(reader, params, count, "config_file")) {
    if (e.domain_id == DDS_DOMAIN_DEFAULT) throw plugin_support::ParamError("parameter 'config_file' needs 'domain_id'");
    e.config = config_file_uri(*file, scene_file);
  }
  if (const auto dir = optional_text(reader, params, count, "identity_dir")) {
    std::filesystem::path path(*dir);
    if (path.is_relative() && scene_file != nullptr && scene_file[0] != '\0') {
      path = std::filesystem::path(scene_file).parent_path() / path;
    }
    e.identity_dir = path;
  }
  return e;
}

}  // namespace mhd::dds

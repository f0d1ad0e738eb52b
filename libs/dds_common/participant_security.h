#pragma once
// Which DDS Security identity a process's participants present (docs/networking.md,
// "Security"). An identity is a folder made by tools/dds_security/make_rig_security.sh:
// the CA certificates, the signed governance, the process's certificate and key and
// its signed permissions. It is given per participant as the DDS Security QoS
// properties (dds.sec.*), so every process carries its own identity while all share
// one Cyclone configuration; Cyclone then loads its builtin auth, access-control and
// crypto plugins (Debian: /usr/lib/x86_64-linux-gnu/libddsc0debian/).

#include <dds/dds.h>

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace mhd::dds {

/// A missing or unreadable identity file; what() names the file.
class DdsSecurityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The environment variable naming the identity folder when no explicit one is given.
inline constexpr const char* kIdentityEnv = "MHD_DDS_IDENTITY";

/// The files of one identity folder, checked to be readable regular files.
struct IdentityFiles {
  std::filesystem::path identity_ca;
  std::filesystem::path permissions_ca;
  std::filesystem::path governance;
  std::filesystem::path certificate;
  std::filesystem::path private_key;
  std::filesystem::path permissions;

  /// Throws DdsSecurityError "DDS identity 'DIR': cannot read FILE (…)" for the first
  /// file that is missing or unreadable, or when DIR is not a folder.
  [[nodiscard]] static IdentityFiles in_folder(const std::filesystem::path& dir);
};

/// The identity folder a participant uses: `explicit_dir` when given, else
/// $MHD_DDS_IDENTITY when set and not empty, else none (unsecured).
[[nodiscard]] std::optional<std::filesystem::path> resolve_identity_dir(
    const std::optional<std::filesystem::path>& explicit_dir);

/// Sets the dds.sec.* properties that make a participant created with `qos` secure.
void apply_identity(dds_qos_t* qos, const IdentityFiles& files);

/// The line an unsecured process prints once when it joins a domain.
inline constexpr const char* kUnsecuredWarning =
    "DDS: unsecured (development only): any process on the network can publish to this rig; "
    "set MHD_DDS_IDENTITY (docs/networking.md, \"Security\")";

/// Prints kUnsecuredWarning to stderr, once per process.
void warn_unsecured_once();

}  // namespace mhd::dds

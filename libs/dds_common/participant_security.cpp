#include "dds_common/participant_security.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <system_error>

namespace mhd::dds {
namespace {

std::filesystem::path readable_file(const std::filesystem::path& dir, const char* name) {
  const std::filesystem::path file = dir / name;
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  std::string why;
  if (ec || !std::filesystem::exists(status)) {
    why = "no such file";
  } else if (!std::filesystem::is_regular_file(status)) {
    why = "not a regular file";
  } else if (!std::ifstream(file).good()) {
    why = "not readable";
  }
  if (!why.empty()) {
    throw DdsSecurityError("DDS identity '" + dir.string() + "': cannot read " + file.string() + " (" + why + ")");
  }
  return std::filesystem::absolute(file);
}

std::string file_uri(const std::filesystem::path& file) { return "file:" + file.string(); }

}  // namespace

IdentityFiles IdentityFiles::in_folder(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw DdsSecurityError("DDS identity '" + dir.string() +
                           "' is not a folder (make one with tools/dds_security/make_rig_security.sh)");
  }
  IdentityFiles f;
  f.identity_ca = readable_file(dir, "identity_ca.pem");
  f.permissions_ca = readable_file(dir, "permissions_ca.pem");
  f.governance = readable_file(dir, "governance.p7s");
  f.certificate = readable_file(dir, "cert.pem");
  f.private_key = readable_file(dir, "key.pem");
  f.permissions = readable_file(dir, "permissions.p7s");
  return f;
}

std::optional<std::filesystem::path> resolve_identity_dir(const std::optional<std::filesystem::path>& explicit_dir) {
  if (explicit_dir) return explicit_dir;
  const char* env = std::getenv(kIdentityEnv);
  if (env != nullptr && env[0] != '\0') return std::filesystem::path(env);
  return std::nullopt;
}

void apply_identity(dds_qos_t* qos, const IdentityFiles& files) {
  // Library names without path: Debian's libddsc looks in its own libddsc0debian folder.
  dds_qset_prop(qos, "dds.sec.auth.library.path", "dds_security_auth");
  dds_qset_prop(qos, "dds.sec.auth.library.init", "init_authentication");
  dds_qset_prop(qos, "dds.sec.auth.library.finalize", "finalize_authentication");
  dds_qset_prop(qos, "dds.sec.crypto.library.path", "dds_security_crypto");
  dds_qset_prop(qos, "dds.sec.crypto.library.init", "init_crypto");
  dds_qset_prop(qos, "dds.sec.crypto.library.finalize", "finalize_crypto");
  dds_qset_prop(qos, "dds.sec.access.library.path", "dds_security_ac");
  dds_qset_prop(qos, "dds.sec.access.library.init", "init_access_control");
  dds_qset_prop(qos, "dds.sec.access.library.finalize", "finalize_access_control");
  dds_qset_prop(qos, "dds.sec.auth.identity_ca", file_uri(files.identity_ca).c_str());
  dds_qset_prop(qos, "dds.sec.auth.identity_certificate", file_uri(files.certificate).c_str());
  dds_qset_prop(qos, "dds.sec.auth.private_key", file_uri(files.private_key).c_str());
  dds_qset_prop(qos, "dds.sec.access.permissions_ca", file_uri(files.permissions_ca).c_str());
  dds_qset_prop(qos, "dds.sec.access.governance", file_uri(files.governance).c_str());
  dds_qset_prop(qos, "dds.sec.access.permissions", file_uri(files.permissions).c_str());
}

void warn_unsecured_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    std::fprintf(stderr, "%s\n", kUnsecuredWarning);
    std::fflush(stderr);
  });
}

}  // namespace mhd::dds

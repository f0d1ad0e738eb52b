// DDS Security with real processes on loopback (docs/networking.md, "Security"): the
// certificates are made at test time by tools/dds_security/make_rig_security.sh; rig 1's
// haptic side is the `dds` tracker plugin through dlopen, as haptic-rig1; `mhd
// tracker-server` publishes as tracker-rig1; intruders are dds_security_rig_writer
// processes writing rig 1's base sensor at a marker position with higher sequence
// numbers (a rig takeover). Each test takes a domain of its own.

#include "../sim_backends/plugin_file.h"
#include "dds_common/participant_security.h"
#include "dds_test_support.h"
#include "tracker_plugin_on_clock.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace mhd::dds {
namespace {

using namespace std::chrono_literals;
using test::ChildProcess;

constexpr double kMarker_m = 3.21;  // the intruders' x; the simulated tracker never sits exactly there

const std::string kLoopbackUri = std::string("file://") + MHD_SOURCE_DIR + "/config/cyclonedds-loopback.xml";
const std::string kSecureUri = kLoopbackUri + ",file://" + MHD_SOURCE_DIR + "/config/cyclonedds-secure.xml";

/// make_rig_security.sh's output for rigs 1 and 2, made once per test process.
class SecurityFiles : public ::testing::Environment {
 public:
  static const std::filesystem::path& dir() { return dir_; }
  static std::filesystem::path identity(const char* name) { return dir_ / "identities" / name; }

  void SetUp() override {
    dir_ = std::filesystem::path(MHD_DDS_SECURITY_TEST_DIR) / ("certs_" + std::to_string(getpid()));
    const std::string command = std::string(MHD_SOURCE_DIR) + "/tools/dds_security/make_rig_security.sh '" +
                                dir_.string() + "' 1 2 > '" + dir_.string() + ".log' 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << test::read_file(dir_.string() + ".log");
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
    std::filesystem::remove(dir_.string() + ".log", ec);
  }

 private:
  static inline std::filesystem::path dir_;
};
[[maybe_unused]] ::testing::Environment* const kSecurityFiles = ::testing::AddGlobalTestEnvironment(new SecurityFiles);

/// Sets an environment variable for the children started while it lives (posix_spawn
/// copies this process's environment).
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_) {
      setenv(name_, old_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

/// A child's output file, removed when the test ends.
struct OutputFile : test::OutputFile {
  explicit OutputFile(const char* name) : test::OutputFile(MHD_DDS_SECURITY_TEST_DIR, name) {}
};

/// Rig `rig`'s haptic side: the `dds` tracker plugin through dlopen, as `identity`.
struct RigServer : test::TrackerPluginOnClock {
  RigServer(std::uint32_t domain, std::uint32_t rig, const std::filesystem::path& identity)
      : TrackerPluginOnClock(MHD_DDS_TRACKER_PLUGIN, {{"domain_id", std::to_string(domain).c_str()},
                                                      {"rig_id", std::to_string(rig).c_str()},
                                                      {"identity_dir", identity.c_str()}}) {}
};

/// The counters once `name` reaches `at_least`, or after `timeout` (a refused peer is
/// counted once it has gone unadmitted for the plugin's 2 s grace).
std::map<std::string, std::uint64_t> counters_once(RigServer& server, const char* name, std::uint64_t at_least,
                                                   std::chrono::milliseconds timeout = 6s) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  std::map<std::string, std::uint64_t> c = server.counters();
  while (c.at(name) < at_least && std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(100ms);
    c = server.counters();
  }
  return c;
}

std::size_t markers(const std::vector<mhd_tracker_sample>& samples) {
  std::size_t n = 0;
  for (const mhd_tracker_sample& s : samples) n += s.p_T_m[0] == kMarker_m ? 1 : 0;
  return n;
}

/// Samples refused for anything but age. A loaded machine (ASan on two cores) can
/// delay a few of the real tracker's samples past `max_age_s`; the intruders write
/// fresh samples, so theirs would show here or as markers, never as stale.
std::uint64_t dropped_but_stale(const std::map<std::string, std::uint64_t>& c) {
  std::uint64_t n = 0;
  for (const auto& [name, value] : c) {
    n += name.rfind("dropped_", 0) == 0 && name != "dropped_stale" ? value : 0;
  }
  return n;
}

/// The stale refusals stay a small fraction (1 %) of what the rig accepted: a delay,
/// not a tracker the rig cannot hear.
void expect_few_stale(const std::map<std::string, std::uint64_t>& c) {
  EXPECT_LE(c.at("dropped_stale") * 100, c.at("accepted")) << "stale " << c.at("dropped_stale");
}

std::vector<std::string> tracker_server_args(std::uint32_t domain, const std::filesystem::path& identity,
                                             double duration_s) {
  return {MHD_DDS_TEST_TRACKER_SERVER, "tracker-server", std::string(MHD_SOURCE_DIR) + "/tests/dds/data/sim_tracker_rig1.xml",
          "--domain-id", std::to_string(domain), "--rig-id", "1", "--duration", std::to_string(duration_s),
          "--plugin-path", MHD_DDS_TEST_PLUGIN_DIR, "--dds-identity", identity.string()};
}

std::vector<std::string> writer_args(std::uint32_t domain, const std::string& identity, double seconds,
                                     int strength = 10) {
  return {MHD_DDS_SECURITY_RIG_WRITER, "--domain-id", std::to_string(domain), "--rig-id", "1",
          "--identity", identity, "--seconds", std::to_string(seconds), "--strength", std::to_string(strength),
          "--x-m", "3.21"};
}

/// A secured domain for this test: loopback plus config/cyclonedds-secure.xml.
std::uint32_t secured_domain(std::uint32_t salt) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(salt);
  setenv("CYCLONEDDS_URI", kSecureUri.c_str(), 1);
  unsetenv(kIdentityEnv);
  return domain;
}

/// Rig 1's tracker server running and heard by the rig's server (the good input).
struct SecuredRig {
  explicit SecuredRig(std::uint32_t salt)
      : domain(secured_domain(salt)),
        server(domain, 1, SecurityFiles::identity("haptic-rig1")),
        tracker(tracker_server_args(domain, SecurityFiles::identity("tracker-rig1"), 20.0), tracker_log.path()) {}

  std::uint32_t domain;
  RigServer server;
  OutputFile tracker_log{"tracker"};
  ChildProcess tracker;
};

TEST(DdsSecurity, SecuredTrackerServerFeedsTheRigsServerWithoutAnyRefusal) {
  SecuredRig rig(1);
  const std::vector<mhd_tracker_sample> got = rig.server.read_for(8s, 300);
  ASSERT_GE(got.size(), 300u) << rig.tracker_log.text();
  EXPECT_EQ(markers(got), 0u);
  const auto c = rig.server.counters();
  EXPECT_EQ(dropped_but_stale(c), 0u);
  expect_few_stale(c);
  EXPECT_EQ(c.at("writers_matched"), 1u);
  EXPECT_EQ(c.at("writers_matched_total"), 1u);
  // The dual of the refusal counts below: an admitted peer is heard and never refused,
  // even long past the grace.
  std::this_thread::sleep_for(2500ms);
  const auto later = rig.server.counters();
  EXPECT_GE(later.at("peers_heard"), 1u);
  EXPECT_EQ(later.at("peers_refused"), 0u);
  EXPECT_EQ(later.at("security_refusals"), 0u);
  EXPECT_NE(rig.tracker_log.text().find("secured as " + SecurityFiles::identity("tracker-rig1").string()),
            std::string::npos)
      << rig.tracker_log.text();
  EXPECT_EQ(rig.tracker_log.text().find("DDS: unsecured"), std::string::npos) << rig.tracker_log.text();
}

TEST(DdsSecurity, UnauthenticatedParticipantPublishingRig1ReachesNothing) {
  SecuredRig rig(2);
  ASSERT_GE(rig.server.read_for(8s, 50).size(), 50u) << rig.tracker_log.text();
  const OutputFile log("intruder");
  std::optional<ChildProcess> intruder;
  {
    const ScopedEnv open_config("CYCLONEDDS_URI", kLoopbackUri);  // an intruder's own, unsecured configuration
    intruder.emplace(writer_args(rig.domain, "none", 2.0), log.path());
  }
  const std::vector<mhd_tracker_sample> during = rig.server.read_for(2500ms);
  ASSERT_EQ(intruder->wait_for(5s), std::optional<int>(0)) << log.text();
  EXPECT_NE(log.text().find(kUnsecuredWarning), std::string::npos) << log.text();
  EXPECT_NE(log.text().find("matched readers: 0"), std::string::npos) << log.text();
  EXPECT_EQ(markers(during), 0u);
  EXPECT_GE(during.size(), 200u) << "the real tracker kept arriving";
  const auto c = rig.server.counters();
  EXPECT_EQ(dropped_but_stale(c), 0u);
  expect_few_stale(c);
  EXPECT_EQ(c.at("writers_matched_total"), 1u) << "the intruder's writer never matched";
  // The refusal is counted: heard, never admitted.
  const auto counted = counters_once(rig.server, "peers_refused", 1);
  EXPECT_EQ(counted.at("peers_refused"), 1u);
  EXPECT_GE(counted.at("peers_heard"), 2u) << "the tracker server and the intruder";
}

TEST(DdsSecurity, Rig2sPermissionsCannotPublishRig1sSamples) {
  SecuredRig rig(3);
  ASSERT_GE(rig.server.read_for(8s, 50).size(), 50u) << rig.tracker_log.text();
  const OutputFile log("intruder");
  ChildProcess intruder(writer_args(rig.domain, SecurityFiles::identity("tracker-rig2").string(), 2.0), log.path());
  const std::vector<mhd_tracker_sample> during = rig.server.read_for(1500ms);
  ASSERT_EQ(intruder.wait_for(5s), std::optional<int>(3)) << log.text();
  EXPECT_NE(log.text().find("refused: dds_create_writer: Not Allowed By Security"), std::string::npos) << log.text();
  EXPECT_EQ(markers(during), 0u);
  const auto c = rig.server.counters();
  EXPECT_EQ(dropped_but_stale(c), 0u);
  expect_few_stale(c);
  EXPECT_EQ(c.at("writers_matched_total"), 1u);
}

/// `name` with rig 2's real certificate and key, but permissions for rig 1 and a
/// governance signed by a CA of the intruder's own: its local checks pass, so only the
/// rig's side can refuse it.
std::filesystem::path forged_identity(const char* name) {
  const std::filesystem::path dir = SecurityFiles::dir() / "forged" / name;
  const std::filesystem::path real = SecurityFiles::identity("tracker-rig2");
  std::filesystem::create_directories(dir);
  for (const char* f : {"identity_ca.pem", "cert.pem", "key.pem"}) {
    std::filesystem::copy_file(real / f, dir / f, std::filesystem::copy_options::overwrite_existing);
  }
  std::string permissions = test::read_file((SecurityFiles::identity("tracker-rig1") / "permissions.xml").string());
  const std::string subject = "CN=tracker-rig1";
  permissions.replace(permissions.find(subject), subject.size(), "CN=tracker-rig2");
  std::ofstream(dir / "permissions.xml") << permissions;
  const std::string d = "'" + dir.string() + "'";
  const std::string gov = "'" + (SecurityFiles::dir() / "governance.xml").string() + "'";
  const std::string command =
      "(cd " + d + " && openssl ecparam -name prime256v1 -genkey -noout -out ca_key.pem"
      " && openssl req -x509 -new -key ca_key.pem -days 10 -subj /CN=intruder -out permissions_ca.pem"
      " && openssl smime -sign -text -in " + gov + " -out governance.p7s -signer permissions_ca.pem -inkey ca_key.pem"
      " && openssl smime -sign -text -in permissions.xml -out permissions.p7s -signer permissions_ca.pem"
      " -inkey ca_key.pem) > " + d + "/forge.log 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << test::read_file((dir / "forge.log").string());
  return dir;
}

TEST(DdsSecurity, PermissionsForgedForRig1AreRefusedByTheRig) {
  SecuredRig rig(4);
  ASSERT_GE(rig.server.read_for(8s, 50).size(), 50u) << rig.tracker_log.text();
  const OutputFile log("intruder");
  ChildProcess intruder(writer_args(rig.domain, forged_identity("tracker-rig2").string(), 2.0), log.path());
  const std::vector<mhd_tracker_sample> during = rig.server.read_for(2500ms);
  ASSERT_EQ(intruder.wait_for(5s), std::optional<int>(0)) << log.text();
  EXPECT_NE(log.text().find("matched readers: 0"), std::string::npos) << "its own side let it write: " << log.text();
  EXPECT_EQ(markers(during), 0u);
  EXPECT_GE(during.size(), 200u);
  const auto c = rig.server.counters();
  EXPECT_EQ(dropped_but_stale(c), 0u);
  expect_few_stale(c);
  EXPECT_EQ(c.at("writers_matched_total"), 1u);
  // Counted twice over: Cyclone logged the permissions it could not verify, and the peer
  // was heard but never admitted.
  EXPECT_GE(c.at("security_refusals"), 1u);
  EXPECT_EQ(counters_once(rig.server, "peers_refused", 1).at("peers_refused"), 1u);
}

TEST(DdsSecurity, AWeakerSecondWriterForRig1DoesNotInterleaveAndTakesOverOnlyWhenTheTrackerLeaves) {
  SecuredRig rig(5);
  ASSERT_GE(rig.server.read_for(8s, 50).size(), 50u) << rig.tracker_log.text();
  const OutputFile log("second");
  // Authorised for rig 1 (tracker-rig1), weaker than the tracker server's 10.
  ChildProcess second(writer_args(rig.domain, SecurityFiles::identity("tracker-rig1").string(), 6.0, 5), log.path());
  const std::vector<mhd_tracker_sample> while_owned = rig.server.read_for(2500ms);
  EXPECT_EQ(markers(while_owned), 0u);
  EXPECT_GE(while_owned.size(), 200u);
  auto c = rig.server.counters();
  EXPECT_EQ(c.at("writers_matched"), 2u) << "the second writer is authorised and matched";
  EXPECT_EQ(c.at("peers_refused"), 0u) << "an authorised peer is not a refusal";
  EXPECT_EQ(c.at("dropped_sequence_backwards"), 0u);

  // The dual: once the stronger writer is gone, the same writer is heard. SIGKILL: no
  // goodbye on the wire, so the owner is given up when its 0.5 s liveliness lease ends.
  rig.tracker.kill_now();
  const auto killed = std::chrono::steady_clock::now();
  std::vector<mhd_tracker_sample> after;
  while (markers(after) == 0 && std::chrono::steady_clock::now() < killed + 3s) {
    const std::vector<mhd_tracker_sample> more = rig.server.read_for(10ms);
    after.insert(after.end(), more.begin(), more.end());
  }
  const double takeover_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - killed).count();
  ASSERT_GT(markers(after), 0u) << log.text();
  EXPECT_GT(takeover_s, 0.3) << "not before the lease ran out";
  EXPECT_LT(takeover_s, 1.5);
  std::cout << "weaker writer heard " << takeover_s << " s after the owner was killed\n";
  EXPECT_GT(markers(rig.server.read_for(1000ms)), 50u);
  ASSERT_EQ(second.wait_for(8s), std::optional<int>(0)) << log.text();
}

TEST(DdsSecurity, UnsecuredProcessSaysSoAndSecureConfigurationWithoutIdentityRefusesToStart) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(6);
  unsetenv(kIdentityEnv);
  {
    const OutputFile log("open");
    ChildProcess open_writer({MHD_DDS_SECURITY_RIG_WRITER, "--domain-id", std::to_string(domain), "--rig-id", "1",
                              "--identity", "none", "--seconds", "0.2"},
                             log.path());
    ASSERT_EQ(open_writer.wait_for(10s), std::optional<int>(0)) << log.text();
    EXPECT_NE(log.text().find(std::string(kUnsecuredWarning) + "\n"), std::string::npos) << log.text();
  }
  const ScopedEnv secure("CYCLONEDDS_URI", kSecureUri);
  const OutputFile log("refused");
  ChildProcess refused({MHD_DDS_SECURITY_RIG_WRITER, "--domain-id", std::to_string(domain), "--rig-id", "1",
                        "--identity", "none", "--seconds", "0.2"},
                       log.path());
  ASSERT_EQ(refused.wait_for(10s), std::optional<int>(1)) << log.text();
  EXPECT_NE(log.text().find("no DDS identity given: if the Cyclone configuration has a Security section, such as "
                            "config/cyclonedds-secure.xml, set MHD_DDS_IDENTITY"),
            std::string::npos)
      << log.text();
  EXPECT_EQ(log.text().find(kUnsecuredWarning), std::string::npos) << "it never ran unsecured: " << log.text();
}

TEST(DdsSecurity, AMissingIdentityFileIsNamed) {
  const std::uint32_t domain = secured_domain(7);
  const std::filesystem::path dir = SecurityFiles::dir() / "no_key";
  std::filesystem::copy(SecurityFiles::identity("haptic-rig1"), dir);
  std::filesystem::remove(dir / "key.pem");
  try {
    RigServer server(domain, 1, dir);
    FAIL() << "opened without a key";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "DDS identity '" + dir.string() + "': cannot read " + (dir / "key.pem").string() + " (no such file)");
  }
  try {
    RigServer server(domain, 1, dir / "nowhere");
    FAIL() << "opened without an identity folder";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "DDS identity '" + (dir / "nowhere").string() +
                                         "' is not a folder (make one with tools/dds_security/make_rig_security.sh)");
  }
}

}  // namespace
}  // namespace mhd::dds

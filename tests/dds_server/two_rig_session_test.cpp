// The README's two-rig session, secured as written (docs/networking.md, "Two rigs on one
// floor"): a tracker server per rig (--shared-world) and a haptic process per rig
// (scenes/network/pair_rig1.xml, pair_rig2.xml), each `mhd run` reading the other rig's
// tracking. Judged from the two recordings: both users touch the dolphin, both bases move,
// each haptic process gets the other rig's samples, and no base ever comes within the
// keep-out of the other base or of either user (robot 0.225 m + human 0.25 m; two bases
// 0.45 m), compared at the same instant (each recording put on one clock by its .meta).
#include "dds_test_support.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace mhd::dds::two_rig_session_test {

namespace fs = std::filesystem;
using test::ChildProcess;

struct Row {
  double t_s, base_x_m, base_z_m, user_x_m, user_z_m;
  bool contact;
};

// The rows of a recording with fresh tracking (finite poses, tracker age in [0, 0.1) s).
// A row from before the first sample records age -1 and the base's default pose, the
// same for both rigs, so it says nothing of where either base was.
std::vector<Row> read_recording(const fs::path& csv) {
  const test::CsvTable t = test::read_csv_table(csv.string());
  std::vector<Row> rows;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const auto at = [&](const char* name) { return t.at(i, name); };
    const Row r{at("t_s"), at("base_x_m"), at("base_z_m"), at("user_x_m"), at("user_z_m"), at("contact") > 0.5};
    const double age_s = at("tracker_age_s");
    if (std::isfinite(r.base_x_m) && std::isfinite(r.user_x_m) && age_s >= 0.0 && age_s < 0.1) rows.push_back(r);
  }
  return rows;
}

TEST(TwoRigSession, SecuredTwoRigsTouchTheDolphinAndNoBaseEntersAKeepOut) {
  const std::uint32_t domain = test::use_loopback_and_unique_domain(73);
  const std::string source = MHD_SOURCE_DIR;
  setenv("CYCLONEDDS_URI",
         ("file://" + source + "/config/cyclonedds-loopback.xml,file://" + source + "/config/cyclonedds-secure.xml")
             .c_str(),
         1);
  const fs::path dir = fs::path(::testing::TempDir()) / ("two_rigs_" + std::to_string(getpid()));
  fs::remove_all(dir);
  const std::string make = source + "/tools/dds_security/make_rig_security.sh '" + dir.string() + "' 1 2 > '" +
                           dir.string() + ".log' 2>&1";
  ASSERT_EQ(std::system(make.c_str()), 0) << test::read_file(dir.string() + ".log");
  const fs::path ids = dir / "identities";

  // The scenes as shipped but for the test's domain (each DDS plugin's domain_id).
  const auto scene_in_domain = [&](const std::string& name) {
    std::ifstream in(fs::path(source) / "scenes/network" / name);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const std::string plugin : {"<plugin kind=\"tracker\" name=\"dds\">", "<plugin kind=\"display\" name=\"dds_state\">"}) {
      const std::size_t at = text.find(plugin);
      text.insert(at + plugin.size(), "<param name=\"domain_id\" value=\"" + std::to_string(domain) + "\"/>");
    }
    text = std::string(text).replace(text.find("../common/"), 10, source + "/scenes/common/");
    text = std::string(text).replace(text.find("../rigs/"), 8, source + "/scenes/rigs/");
    text = std::string(text).replace(text.find("../../assets/"), 13, source + "/assets/");
    const fs::path path = dir / name;
    std::ofstream(path) << text;
    return path.string();
  };
  std::vector<std::unique_ptr<ChildProcess>> trackers;
  for (const std::string rig : {"1", "2"}) {
    trackers.push_back(std::make_unique<ChildProcess>(
        std::vector<std::string>{MHD_BIN, "tracker-server", source + "/scenes/network/tracker_rig" + rig + ".xml",
                                 "--shared-world", "--domain-id", std::to_string(domain), "--rig-id", rig,
                                 "--duration", "20", "--dds-identity", (ids / ("tracker-rig" + rig)).string()},
        (dir / ("tracker" + rig + ".log")).string()));
  }
  std::vector<std::unique_ptr<ChildProcess>> haptics;
  for (const std::string rig : {"1", "2"}) {
    setenv("MHD_DDS_IDENTITY", (ids / ("haptic-rig" + rig)).string().c_str(), 1);
    haptics.push_back(std::make_unique<ChildProcess>(
        std::vector<std::string>{MHD_BIN, "run", scene_in_domain("pair_rig" + rig + ".xml"), "--duration", "14", "-q",
                                 "--record", (dir / ("rig" + rig + ".csv")).string()},
        (dir / ("haptic" + rig + ".log")).string()));
  }
  unsetenv("MHD_DDS_IDENTITY");
  std::vector<std::vector<Row>> rows;
  for (std::size_t i = 0; i < 2; ++i) {
    const std::optional<int> rc = haptics[i]->wait_for(std::chrono::seconds(40));
    const std::string log = test::read_file((dir / ("haptic" + std::to_string(i + 1) + ".log")).string());
    ASSERT_TRUE(rc.has_value()) << log;
    EXPECT_EQ(*rc, 0) << log;
    EXPECT_NE(log.find("safe state: zero force sent, base stopped"), std::string::npos) << log;
    // The other rig's samples came too: the server took half again as many samples as
    // this rig's own tracker server sent and the dds tracker accepted.
    std::smatch own, taken;
    ASSERT_TRUE(std::regex_search(log, own, std::regex(R"(dds tracker \(rig \d\): accepted (\d+))"))) << log;
    ASSERT_TRUE(std::regex_search(log, taken, std::regex(R"(tracker: (\d+) samples)"))) << log;
    EXPECT_GT(std::stod(taken[1]), 1.5 * std::stod(own[1])) << log;
    rows.push_back(read_recording(dir / ("rig" + std::to_string(i + 1) + ".csv")));
    ASSERT_GT(rows.back().size(), 5000u) << log;
  }
  for (auto& t : trackers) t->terminate();

  // Each recording's t_s counts from its own server's opening: rig 2's rows go onto rig
  // 1's clock by the difference of their zeros.
  const std::optional<std::int64_t> zero_1 = test::recording_clock_zero_unix_ns((dir / "rig1.csv").string());
  const std::optional<std::int64_t> zero_2 = test::recording_clock_zero_unix_ns((dir / "rig2.csv").string());
  ASSERT_TRUE(zero_1 && zero_2) << "no host_clock_zero_unix_ns in the recordings' .meta";
  const double two_on_one_s = static_cast<double>(*zero_2 - *zero_1) * 1e-9;
  constexpr double kUserKeepOut_m = 0.225 + 0.25, kBaseKeepOut_m = 0.45;
  // The closest each kind of pair came, which pair it was and when (on rig 1's clock).
  struct Closest {
    double m = 1e9, t_s = 0.0;
    std::string pair;
    void take(double d_m, double at_s, const std::string& what) {
      if (d_m < m) *this = Closest{d_m, at_s, what};
    }
  };
  Closest base_base, base_user;
  double moved_m[2] = {0.0, 0.0};
  std::size_t contacts[2] = {0, 0}, compared = 0;
  std::size_t j = 0;
  for (const Row& a : rows[0]) {
    while (j + 1 < rows[1].size() && rows[1][j + 1].t_s + two_on_one_s <= a.t_s) ++j;
    const Row& b = rows[1][j];
    if (std::abs(b.t_s + two_on_one_s - a.t_s) > 0.01) continue;  // no row of rig 2's near that instant
    ++compared;
    base_base.take(std::hypot(a.base_x_m - b.base_x_m, a.base_z_m - b.base_z_m), a.t_s, "base 1 - base 2");
    base_user.take(std::hypot(a.base_x_m - b.user_x_m, a.base_z_m - b.user_z_m), a.t_s, "base 1 - user 2");
    base_user.take(std::hypot(b.base_x_m - a.user_x_m, b.base_z_m - a.user_z_m), a.t_s, "base 2 - user 1");
  }
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string rig = std::to_string(i + 1);
    for (const Row& r : rows[i]) {
      base_user.take(std::hypot(r.base_x_m - r.user_x_m, r.base_z_m - r.user_z_m),
                     r.t_s + (i == 1 ? two_on_one_s : 0.0), "base " + rig + " - user " + rig);
      moved_m[i] = std::max(moved_m[i], std::hypot(r.base_x_m - rows[i].front().base_x_m,
                                                    r.base_z_m - rows[i].front().base_z_m));
      contacts[i] += r.contact ? 1 : 0;
    }
  }
  std::cout << "over " << compared << " instants on one clock (rig 2's zero " << two_on_one_s * 1e3
            << " ms after rig 1's): bases at least " << base_base.m << " m apart (" << base_base.pair << ", t "
            << base_base.t_s << " s), a base at least " << base_user.m << " m from a user (" << base_user.pair
            << ", t " << base_user.t_s << " s); contact ticks " << contacts[0] << " and " << contacts[1] << "\n";
  const double base_base_m = base_base.m, base_user_m = base_user.m;
  EXPECT_GT(compared, 5000u);
  EXPECT_GT(base_base_m, kBaseKeepOut_m);
  EXPECT_GT(base_user_m, kUserKeepOut_m);
  EXPECT_GT(moved_m[0], 0.3);
  EXPECT_GT(moved_m[1], 0.3);
  EXPECT_GT(contacts[0], 100u);
  EXPECT_GT(contacts[1], 100u);
  // A failed run's logs and recordings are kept for a look.
  if (::testing::Test::HasFailure()) {
    std::cout << "logs and recordings kept in " << dir << "\n";
    return;
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::remove(dir.string() + ".log", ec);
}

}  // namespace mhd::dds::two_rig_session_test

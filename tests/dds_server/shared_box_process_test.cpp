// Two users push one box, with real `mhd run` processes (docs/shared-objects.md, "Two
// processes"): scenes/network/shared_box_rig1.xml (the box's authority) and
// shared_box_rig2.xml (a replica), each a desktop PHANToM whose simulated user leans in
// and presses a face of the box 3 cm deep, over the dds_link in one DDS domain. Judged
// from each process's report (where its box ended, what it sent and obeyed) and
// recording (its forces):
//   - pressed from opposite sides, the box stays put while both rigs run (a rig that
//     starts later or ends sooner leaves the other pressing alone); pressed from one
//     side, it moves; and both rigs leave it in the same place;
//   - the dual of "stays put": rig 1 pressing alone (no rig 2) moves it, so rig 2's push,
//     carried by the link, is what held it;
//   - rig 2 alone (no authority, so no state ever comes) feels its replica's force fade
//     to nothing, though its hand is in the box;
//   - tick by tick, the two rigs' boxes (each recording's shared_* columns, put on one
//     clock by each recording's host_clock_zero_unix_ns) agree within 5 mm while both
//     run, rig 2 started 0.3 s after rig 1;
//   - secured as docs/networking.md says (make_rig_security.sh), the pair runs the same,
//     and rig 2's identity may not run as rig 1.
#include "dds_test_support.h"
#include "support/scratch_dir.h"

#include <Eigen/Core>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace mhd::dds::shared_box_process_test {

namespace fs = std::filesystem;
using test::ChildProcess;

constexpr double kRunFor_s = 6.0;
/// A gap between recorded ticks this long is a stop of the loop, not a late tick: the
/// pair's physics rides through late ticks, not through a stop of the authority's loop.
constexpr double kStop_s = 0.05;

struct Placement {
  double x_m = 0.0;
  bool plus_z = true;  ///< on the table's +z side, facing -z; else -z, facing +z
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string fmt_vec(double a, double b, double c) {
  return std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c);
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
}

// The shipped scene of `rig` in `domain`, its device and user moved to `where`.
fs::path write_scene(const fs::path& dir, int rig, std::uint32_t domain, const Placement& where) {
  const fs::path network = fs::path(MHD_SOURCE_DIR) / "scenes/network";
  std::string text = read_text(network / ("shared_box_rig" + std::to_string(rig) + ".xml"));
  replace_all(text, "\"shared_box_common.xml\"", "\"" + (network / "shared_box_common.xml").string() + "\"");
  const std::string link = "<plugin kind=\"link\" name=\"dds_link\">";
  text.insert(text.find(link) + link.size(), "<param name=\"domain_id\" value=\"" + std::to_string(domain) + "\"/>");
  const double z = where.plus_z ? 0.1 : -0.1;
  const std::string device = fmt_vec(where.x_m, 0.755, z);
  const std::string yaw = where.plus_z ? "0 0 0" : "0 180 0";
  text = std::regex_replace(text, std::regex(R"(position="[^"]*" rpy_deg="[^"]*")"),
                            "position=\"" + device + "\" rpy_deg=\"" + yaw + "\"");
  text = std::regex_replace(text, std::regex(R"((name="phantom_position_m" value=")[^"]*")"), "$01" + device + "\"");
  text = std::regex_replace(text, std::regex(R"((name="phantom_rpy_deg" value=")[^"]*")"), "$01" + yaw + "\"");
  const double s = where.plus_z ? 1.0 : -1.0;
  text = std::regex_replace(text, std::regex(R"((name="path" value=")[^"]*")"),
                            "$01" + fmt_vec(where.x_m, 0.58 * s, 0.05) + "; " + fmt_vec(where.x_m, 0.42 * s, 0.05) +
                                "\"");
  text = std::regex_replace(text, std::regex(R"((name="start_heading_deg" value=")[^"]*")"),
                            std::string("$01") + (where.plus_z ? "90" : "-90") + "\"");
  const fs::path scene = dir / ("rig" + std::to_string(rig) + ".xml");
  std::ofstream(scene) << text;
  return scene;
}

struct BoxAt {
  double t_s;
  Eigen::Vector3d p_W;
};

struct RigEnd {
  std::string log;
  std::vector<BoxAt> box;      ///< the shared box as this rig rendered it, every tick
  Eigen::Vector3d p_W_box = Eigen::Vector3d::Zero();
  double moved_m = 0.0;
  double states_obeyed = 0.0, pushes_sent = 0.0, pushes_kept = 0.0;
  double max_force_N = 0.0;    ///< over the whole run, from the recording
  std::size_t contact_ticks = 0;
  double clock_zero_unix_s = 0.0;  ///< where the recording's t_s = 0 falls in Unix time
  /// Where the recording skips over kStop_s or more (the haptic loop did not run), as
  /// [from, to] on this rig's clock.
  std::vector<std::pair<double, double>> stops_s;
};

double unix_now_s() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// What a rig reported; `launched_unix_s` and `ended_unix_s` bound its process's life,
// which its recording's rows, put on Unix time by its .meta, must lie within.
RigEnd read_end(const fs::path& log_file, const fs::path& csv, double launched_unix_s, double ended_unix_s) {
  RigEnd end;
  end.log = test::read_file(log_file.string());
  std::smatch m;
  const std::regex box(R"(shared object 'box' \(id 1\): [^\n]* to \(([-0-9.]+), ([-0-9.]+), ([-0-9.]+)\) m, moved ([0-9.]+) m)");
  if (std::regex_search(end.log, m, box)) {
    end.p_W_box = Eigen::Vector3d(std::stod(m[1]), std::stod(m[2]), std::stod(m[3]));
    end.moved_m = std::stod(m[4]);
  } else {
    ADD_FAILURE() << "no shared object in the report:\n" << end.log;
  }
  const std::regex sharing(R"(sharing: sent \d+ states, (\d+) pushes; received (\d+) states obeyed, \d+ ignored, (\d+) pushes kept)");
  if (std::regex_search(end.log, m, sharing)) {
    end.pushes_sent = std::stod(m[1]);
    end.states_obeyed = std::stod(m[2]);
    end.pushes_kept = std::stod(m[3]);
  }
  const test::CsvTable t = test::read_csv_table(csv.string());
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const auto at = [&](const char* name) { return t.at(i, name); };
    end.max_force_N = std::max(end.max_force_N, Eigen::Vector3d(at("force_x_N"), at("force_y_N"), at("force_z_N")).norm());
    end.contact_ticks += at("contact") > 0.5 ? 1 : 0;
    end.box.push_back({at("t_s"), Eigen::Vector3d(at("shared_x_m"), at("shared_y_m"), at("shared_z_m"))});
    if (end.box.size() > 1 && end.box.back().t_s - end.box[end.box.size() - 2].t_s >= kStop_s) {
      end.stops_s.emplace_back(end.box[end.box.size() - 2].t_s, end.box.back().t_s);
    }
  }
  const std::optional<std::int64_t> zero_ns = test::recording_clock_zero_unix_ns(csv.string());
  EXPECT_TRUE(zero_ns.has_value()) << "no host_clock_zero_unix_ns in " << csv << ".meta";
  if (zero_ns && !end.box.empty()) {
    end.clock_zero_unix_s = static_cast<double>(*zero_ns) * 1e-9;
    EXPECT_GE(end.clock_zero_unix_s + end.box.front().t_s, launched_unix_s);
    EXPECT_LE(end.clock_zero_unix_s + end.box.back().t_s, ended_unix_s);
  }
  return end;
}

// Rig `r`'s box at `t_s` of its own clock (its first or last where t_s is outside them).
Eigen::Vector3d box_at(const RigEnd& r, double t_s) {
  const auto after = std::upper_bound(r.box.begin(), r.box.end(), t_s,
                                      [](double t, const BoxAt& b) { return t < b.t_s; });
  if (after == r.box.begin()) return r.box.front().p_W;
  if (after == r.box.end()) return r.box.back().p_W;
  const BoxAt& before = *(after - 1);
  const double w = (t_s - before.t_s) / (after->t_s - before.t_s);
  return before.p_W + w * (after->p_W - before.p_W);
}

// When both rigs ran, on rig 1's clock: each recording's t_s counts from its own
// server's opening, so rig 2's times go onto rig 1's clock by adding `two_on_one_s`.
// Before the later rig starts and after the earlier one ends, one rig presses alone.
struct BothRan {
  double two_on_one_s = 0.0;
  double from_s = 0.0, to_s = 0.0;
};

// Requires both recordings to have rows.
BothRan both_ran(const RigEnd& one, const RigEnd& two) {
  BothRan b;
  b.two_on_one_s = two.clock_zero_unix_s - one.clock_zero_unix_s;
  b.from_s = std::max(one.box.front().t_s, two.box.front().t_s + b.two_on_one_s);
  b.to_s = std::min(one.box.back().t_s, two.box.back().t_s + b.two_on_one_s);
  return b;
}

// Where both rigs' loops stopped at once (over kStop_s; a pause of the whole machine,
// as a virtual machine's host makes now and then, which no SCHED_FIFO thread outranks).
// Through such a pause the authority's box takes its hand's push alone, as a real pair
// would; so the pair's agreement is judged on runs without one. A stop of one rig alone
// is the engine's and is judged. Returns the pause as rig 1's stop within it.
std::optional<std::pair<double, double>> machine_paused(const RigEnd& one, const RigEnd& two) {
  if (one.box.empty() || two.box.empty()) return std::nullopt;
  const double two_on_one_s = two.clock_zero_unix_s - one.clock_zero_unix_s;
  for (const auto& [from1, to1] : one.stops_s) {
    for (const auto& [from2, to2] : two.stops_s) {
      if (std::max(from1, from2 + two_on_one_s) < std::min(to1, to2 + two_on_one_s)) return std::pair{from1, to1};
    }
  }
  return std::nullopt;
}

struct Agreement {
  std::size_t ticks = 0;
  double max_m = 0.0, p99_m = 0.0;
};

// Rig 2's box against rig 1's at the same instant, over the ticks both ran, from 0.5 s
// after both started (the replica's first states).
Agreement agreement(const RigEnd& one, const RigEnd& two) {
  Agreement a;
  if (one.box.empty() || two.box.empty()) return a;
  const BothRan both = both_ran(one, two);
  std::vector<double> gaps;
  for (const BoxAt& b : two.box) {
    const double t_s = b.t_s + both.two_on_one_s;
    if (t_s < both.from_s + 0.5) continue;
    if (t_s >= both.to_s) break;
    gaps.push_back((b.p_W - box_at(one, t_s)).norm());
  }
  if (gaps.empty()) return a;
  std::sort(gaps.begin(), gaps.end());
  a.ticks = gaps.size();
  a.max_m = gaps.back();
  a.p99_m = gaps[static_cast<std::size_t>(0.99 * static_cast<double>(gaps.size() - 1))];
  return a;
}

// While both rigs ran: how far rig 1's box got from where it was when the later one
// started, and rig 2's last box against rig 1's box at that instant.
struct WhileBothRan {
  double moved_m = 0.0;
  double apart_at_end_m = 0.0;
};

WhileBothRan while_both_ran(const RigEnd& one, const RigEnd& two) {
  WhileBothRan w;
  if (one.box.empty() || two.box.empty()) return w;
  const BothRan both = both_ran(one, two);
  const Eigen::Vector3d start = box_at(one, both.from_s);
  for (const BoxAt& b : one.box) {
    if (b.t_s >= both.from_s && b.t_s <= both.to_s) w.moved_m = std::max(w.moved_m, (b.p_W - start).norm());
  }
  w.apart_at_end_m = (box_at(two, both.to_s - both.two_on_one_s) - box_at(one, both.to_s)).norm();
  return w;
}

void expect_agreement(const RigEnd& one, const RigEnd& two, const char* run) {
  const Agreement a = agreement(one, two);
  EXPECT_GT(a.ticks, 3000u);
  EXPECT_LT(a.max_m, 0.005);
  std::cout << run << ": rig 2's box against rig 1's over " << a.ticks << " ticks: p99 " << a.p99_m * 1e3
            << " mm, max " << a.max_m * 1e3 << " mm\n";
}

class SharedBoxProcess : public ::testing::Test {
 protected:
  void SetUp() override {
    domain_ = test::use_loopback_and_unique_domain(91);
    dir_ = mhd::test::scratch_dir("shared_box", ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }

  /// DDS Security from here on: identities for rigs 1 and 2, the secure configuration.
  void secure() {
    const std::string make = std::string(MHD_SOURCE_DIR) + "/tools/dds_security/make_rig_security.sh '" +
                             (dir_ / "security").string() + "' 1 2 > '" + (dir_ / "security.log").string() + "' 2>&1";
    ASSERT_EQ(std::system(make.c_str()), 0) << test::read_file((dir_ / "security.log").string());
    const std::string config = std::string(MHD_SOURCE_DIR) + "/config";
    setenv("CYCLONEDDS_URI",
           ("file://" + config + "/cyclonedds-loopback.xml,file://" + config + "/cyclonedds-secure.xml").c_str(), 1);
    identities_ = dir_ / "security" / "identities";
  }

  void TearDown() override { unsetenv("MHD_DDS_IDENTITY"); }

  /// Starts rig `rig`'s `mhd run` (as `identity`'s haptic process when secured).
  std::unique_ptr<ChildProcess> start(int rig, const Placement& where, int identity) {
    const std::string name = "rig" + std::to_string(rig);
    if (!identities_.empty()) {
      setenv("MHD_DDS_IDENTITY", (identities_ / ("haptic-rig" + std::to_string(identity))).c_str(), 1);
    }
    return std::make_unique<ChildProcess>(
        std::vector<std::string>{MHD_BIN, "run", write_scene(dir_, rig, domain_, where).string(), "--duration",
                                 std::to_string(kRunFor_s), "-q", "--record", (dir_ / (name + ".csv")).string()},
        (dir_ / (name + ".log")).string());
  }

  /// Runs the rigs placed so (an empty optional: that rig does not run), each for
  /// kRunFor_s, each started `apart_s` after the one before; what each reported, in rig
  /// order (absent rigs: nullopt).
  std::vector<std::optional<RigEnd>> run(const std::vector<std::optional<Placement>>& rigs, double apart_s = 0.0) {
    std::vector<std::unique_ptr<ChildProcess>> processes;
    std::vector<double> launched_unix_s(rigs.size(), 0.0);
    for (std::size_t i = 0; i < rigs.size(); ++i) {
      if (!rigs[i]) {
        processes.push_back(nullptr);
        continue;
      }
      if (i > 0) std::this_thread::sleep_for(std::chrono::duration<double>(apart_s));
      const int rig = static_cast<int>(i) + 1;
      launched_unix_s[i] = unix_now_s();
      processes.push_back(start(rig, *rigs[i], rig));
    }
    std::vector<std::optional<RigEnd>> ends;
    for (std::size_t i = 0; i < rigs.size(); ++i) {
      if (!processes[i]) {
        ends.emplace_back();
        continue;
      }
      const std::string name = "rig" + std::to_string(i + 1);
      const std::optional<int> rc = processes[i]->wait_for(std::chrono::seconds(60));
      const double ended_unix_s = unix_now_s();
      const std::string log = test::read_file((dir_ / (name + ".log")).string());
      EXPECT_TRUE(rc.has_value() && *rc == 0) << name << ":\n" << log;
      EXPECT_NE(log.find("safe state: zero force sent"), std::string::npos) << log;
      ends.push_back(read_end(dir_ / (name + ".log"), dir_ / (name + ".csv"), launched_unix_s[i], ended_unix_s));
    }
    return ends;
  }

  /// run() for a pair, again where the machine paused both rigs at once (at most
  /// kTries runs in all); nullopt where every run was paused, with what was seen in
  /// `paused`.
  std::optional<std::vector<std::optional<RigEnd>>> run_unpaused(const std::vector<std::optional<Placement>>& rigs,
                                                                 double apart_s, std::string& paused) {
    constexpr int kTries = 3;
    for (int i = 0; i < kTries; ++i) {
      auto ends = run(rigs, apart_s);
      const auto pause = ends[0] && ends[1] ? machine_paused(*ends[0], *ends[1]) : std::nullopt;
      if (!pause) return ends;
      const auto [from_s, to_s] = *pause;
      paused += "run " + std::to_string(i + 1) + ": both loops stopped, rig 1's from " + std::to_string(from_s) +
                " s for " + std::to_string((to_s - from_s) * 1e3) + " ms\n";
      std::cout << "the machine paused both rigs: " << paused;
    }
    return std::nullopt;
  }

  std::uint32_t domain_ = 0;
  fs::path dir_;
  fs::path identities_;  ///< empty: unsecured
};

constexpr Placement kPlusZ{0.0, true}, kMinusZ{0.0, false};

TEST_F(SharedBoxProcess, SecuredPressedFromOppositeSidesTheBoxStaysAndBothRigsAgree) {
  secure();
  std::string paused;
  const auto tried = run_unpaused({kPlusZ, kMinusZ}, 0.0, paused);
  if (!tried) GTEST_SKIP() << "the machine paused both rigs in every run:\n" << paused;
  const auto& ends = *tried;
  ASSERT_TRUE(ends[0] && ends[1]);
  const RigEnd& r1 = *ends[0];
  const RigEnd& r2 = *ends[1];
  // Both hands pressed the box for seconds, each through its own rendering of it.
  EXPECT_GT(r1.contact_ticks, 1500u) << r1.log;
  EXPECT_GT(r2.contact_ticks, 1500u) << r2.log;
  EXPECT_GT(r2.states_obeyed, 3000.0) << r2.log;
  EXPECT_GT(r1.pushes_kept, 1000.0) << r1.log;
  // Judged while both pressed: a rig that opens later or ends sooner leaves the other
  // pressing alone, which moves the box (PressedByOneRigAloneTheBoxMoves).
  const WhileBothRan both = while_both_ran(r1, r2);
  std::cout << "opposite sides: while both ran, rig 1's box moved " << both.moved_m * 1e3 << " mm (" << r1.moved_m * 1e3
            << " mm over its whole run); the boxes " << both.apart_at_end_m * 1e3 << " mm apart as the first rig ended\n";
  EXPECT_LT(both.moved_m, 0.01) << r1.log;
  EXPECT_LT(both.apart_at_end_m, 0.005) << r1.log << r2.log;
  EXPECT_EQ(r1.log.find("unsecured"), std::string::npos) << r1.log;
  expect_agreement(r1, r2, "opposite sides");
}

TEST_F(SharedBoxProcess, SecuredRig2sIdentityMayNotRunAsRig1) {
  secure();
  const std::unique_ptr<ChildProcess> p = start(1, kPlusZ, /*identity=*/2);
  const std::optional<int> rc = p->wait_for(std::chrono::seconds(30));
  const std::string log = test::read_file((dir_ / "rig1.log").string());
  ASSERT_TRUE(rc.has_value()) << log;
  EXPECT_NE(*rc, 0) << log;
  EXPECT_NE(log.find("plugin 'dds_link': open failed: dds_create_writer: Not Allowed By Security"), std::string::npos)
      << log;
}

TEST_F(SharedBoxProcess, PressedFromOneSideTheBoxMovesAndBothRigsAgree) {
  // Rig 2 starts 0.3 s after rig 1, as two users would: each recording's times are its
  // own process's, so the rigs' boxes are compared on one clock, or they would seem to
  // be 0.3 s apart wherever the box moves.
  std::string paused;
  const auto tried = run_unpaused({Placement{-0.06, true}, Placement{0.06, true}}, 0.3, paused);
  if (!tried) GTEST_SKIP() << "the machine paused both rigs in every run:\n" << paused;
  const auto& ends = *tried;
  ASSERT_TRUE(ends[0] && ends[1]);
  const RigEnd& r1 = *ends[0];
  const RigEnd& r2 = *ends[1];
  EXPECT_GT(r1.moved_m, 0.02) << r1.log;
  EXPECT_LT(r1.p_W_box.z(), -0.02) << r1.log;  // away from both users, along -z
  EXPECT_GT(r2.pushes_sent, 100.0) << r2.log;
  EXPECT_LT((r1.p_W_box - r2.p_W_box).norm(), 0.005) << r1.log << r2.log;
  expect_agreement(r1, r2, "one side");
}

TEST_F(SharedBoxProcess, PressedByOneRigAloneTheBoxMoves) {
  // The dual of staying put: without rig 2's push the same hand moves the box.
  const auto ends = run({kPlusZ, std::nullopt});
  ASSERT_TRUE(ends[0]);
  EXPECT_GT(ends[0]->moved_m, 0.02) << ends[0]->log;
}

TEST_F(SharedBoxProcess, AReplicaWithNoAuthorityFadesItsForce) {
  // Rig 2 alone: no state ever comes, so the force from its replica fades out (and never
  // comes in), while its hand goes 3 cm into the box.
  const auto ends = run({std::nullopt, kMinusZ});
  ASSERT_TRUE(ends[1]);
  const RigEnd& r2 = *ends[1];
  EXPECT_EQ(r2.states_obeyed, 0.0) << r2.log;
  EXPECT_GT(r2.contact_ticks, 1500u) << r2.log;
  EXPECT_LT(r2.max_force_N, 0.5) << r2.log;
}

}  // namespace mhd::dds::shared_box_process_test

#include "share_sim_command.h"

#include "command_exit.h"
#include "shared_object_sim.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace {

struct ShareSimOptions {
  std::string out = "share_sim_out";
  int sessions = 500;
  std::uint64_t first_seed = 3000000;
  double duration_s = 6.0;
};

int fail(const std::string& message) {
  fmt::print(stderr, "mhd share-sim: error: {}\n", message);
  return 1;
}

double max_of(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

int run(const ShareSimOptions& o) {
  if (o.sessions < 1 || o.sessions > 100000) return fail("--sessions must be 1..100000");
  if (!(o.duration_s >= 2.0) || !(o.duration_s <= 600.0)) return fail("--duration-s must be >= 2 and <= 600");
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  if (ec) return fail("cannot create '" + o.out + "': " + ec.message());
  const auto s = mhd::share_sim::simulate_sessions(o.first_seed, o.sessions, o.duration_s);

  // The push felt: against the same session over a link of no delay, and what is left
  // once the link's own delay is taken off.
  std::vector<double> added_s, beyond_link_s;
  for (std::size_t i = 0; i < s.felt_delay_s.size(); ++i) {
    added_s.push_back(s.felt_delay_s[i] - s.felt_delay_no_link_s[i]);
    beyond_link_s.push_back(added_s.back() - s.felt_link_delay_s[i]);
  }
  fmt::print("{} two-rig sessions of {:g} s from seed {}: link 1-20 ms one way, jitter <= 5 ms, loss <= 5 %\n",
             s.sessions, o.duration_s, o.first_seed);
  fmt::print("ticks (both rigs)        {}\n", s.ticks);
  fmt::print("contact ticks            {}\n", s.contact_ticks);
  fmt::print("pop-throughs             {}\n", s.pop_throughs);
  fmt::print("squeeze overlaps         {} (authority) {} (replica)\n", s.overlaps[0], s.overlaps[1]);
  fmt::print("box disagreement         p99 {:.2f} mm, max {:.2f} mm, max {:.3f} rad (link up); max {:.0f} mm "
             "(link cut)\n",
             1e3 * s.disagreement_p99_m, 1e3 * s.disagreement_max_m, s.disagreement_max_rad,
             1e3 * s.disagreement_stale_max_m);
  fmt::print("state age (rig 1)        max {:.1f} ms (link up)\n", 1e3 * s.max_state_age_s);
  fmt::print("old-term states ignored  {}\n", s.old_term_ignored);
  fmt::print("force on stale replica   max {:.2f} N (rig 1, its state stale for the whole fade)\n",
             s.max_force_on_stale_N);
  fmt::print("push felt ({} sessions)  max {:.1f} ms; no link max {:.1f} ms; added max {:.1f} ms; added beyond the "
             "link's delay max {:.1f} ms\n",
             s.felt_delay_s.size(), 1e3 * max_of(s.felt_delay_s), 1e3 * max_of(s.felt_delay_no_link_s),
             1e3 * max_of(added_s), 1e3 * max_of(beyond_link_s));

  const std::filesystem::path csv = std::filesystem::path(o.out) / "share_sim.csv";
  std::ofstream out(csv);
  out << mhd::share_sim::csv_header() << '\n';
  for (const std::string& row : s.csv_rows) out << row << '\n';
  if (!out) return fail("cannot write '" + csv.string() + "'");
  fmt::print("wrote {}\n", csv.string());
  return s.pop_throughs == 0 ? 0 : 3;
}

}  // namespace

void add_share_sim_command(CLI::App& app) {
  auto o = std::make_shared<ShareSimOptions>();
  CLI::App* cmd = app.add_subcommand(
      "share-sim", "Two rigs sharing one pushable box over a simulated link: pop-throughs, agreement, push felt");
  cmd->add_option("--sessions", o->sessions, "Sessions, each drawn from its seed")->capture_default_str();
  cmd->add_option("--first-seed", o->first_seed, "The first session's seed")->capture_default_str();
  cmd->add_option("--duration-s", o->duration_s, "Each session's length")->capture_default_str();
  cmd->add_option("--out", o->out, "Directory for share_sim.csv")->capture_default_str();
  cmd->callback([o] { mhd::cli::exit_with(run(*o)); });
}

#include "hardware_run.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>

namespace mhd::test::hardware {

namespace fs = std::filesystem;

fs::path write_scene_logging_the_base(const fs::path& dir, const std::string& name,
                                      std::vector<std::pair<std::string, std::string>> fills) {
  const std::string scenes = std::string(MHD_SOURCE_DIR) + "/scenes/";
  fills.insert(fills.begin(),
               {{R"(file="common/materials.xml")", R"(file=")" + scenes + R"(common/materials.xml")"},
                {R"(file="rigs/pomhi.xml")", R"(file=")" + scenes + R"(rigs/pomhi.xml")"},
                {R"(<plugin kind="base" name="sim_omni3">)",
                 R"(<plugin kind="base" name="sim_omni3"><param name="command_log" value="base.csv"/>)"}});
  const fs::path scene = dir / "scene.xml";
  std::ofstream(scene) << fill_scene_template(scenes + name, fills);
  return scene;
}

int exit_status(MhdRunProcess& process, std::chrono::seconds timeout) {
  const auto status = process.wait_for(timeout);
  if (!status) return -1;
  if (!WIFEXITED(*status)) return 1000 + WTERMSIG(*status);
  return WEXITSTATUS(*status);
}

std::vector<CommandLogRow> log_of(const fs::path& file) {
  return fs::exists(file) ? read_command_log(file) : std::vector<CommandLogRow>{};
}

std::vector<CommandLogRow> rows_of(const fs::path& file, const std::string& event) {
  std::vector<CommandLogRow> out;
  for (const CommandLogRow& r : log_of(file)) {
    if (r.event == event) out.push_back(r);
  }
  return out;
}

void expect_last_command_zero(const fs::path& file, const std::string& output) {
  const auto commands = rows_of(file, "command");
  ASSERT_FALSE(commands.empty()) << file << " has no command\n" << output;
  const CommandLogRow& last = commands.back();
  EXPECT_TRUE(last.is_zero()) << file << " last command " << last.values[0] << " " << last.values[1] << " "
                              << last.values[2] << "\n"
                              << output;
}

int stale_ticks(const std::string& output) {
  int stale = -1;
  const std::size_t at = output.find("start-up, ");
  if (at == std::string::npos || std::sscanf(output.c_str() + at, "start-up, %d stale", &stale) != 1) return -1;
  return stale;
}

}  // namespace mhd::test::hardware

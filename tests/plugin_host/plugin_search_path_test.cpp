// Where plugins are found: the folder order, find() on real files copied into scratch
// folders, and a listing that survives every broken test plugin.

#include "plugin_host/plugin_search_path.h"
#include "test_plugins.h"

#include <mhd/plugin_abi.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <iterator>
#include <fstream>
#include <string>
#include <vector>

namespace mhd {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> dirs_of(const std::vector<PluginFolder>& folders) {
  std::vector<fs::path> dirs;
  for (const PluginFolder& f : folders) dirs.push_back(f.dir);
  return dirs;
}

/// Scratch folders a/, b/, ... under a fresh temporary folder, removed afterwards.
class PluginSearchPathTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::temp_directory_path() /
            ("mhd_plugin_search_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }

  fs::path folder(const std::string& name) {
    const fs::path dir = root_ / name;
    fs::create_directories(dir);
    return dir;
  }

  /// Copies a built plugin into `dir` under its own file name.
  static fs::path copy_into(const fs::path& plugin, const fs::path& dir) {
    const fs::path target = dir / plugin.filename();
    fs::copy_file(plugin, target, fs::copy_options::overwrite_existing);
    return target;
  }

  fs::path root_;
};

TEST(PluginFolders, CommandLineThenEnvironmentThenInstalledThenBuildTree) {
  const auto folders = plugin_folders({"/cmd/a", "/cmd/b"}, "/env/c::/env/d", "/opt/mhd/bin/mhd");
  ASSERT_EQ(folders.size(), 6u);
  EXPECT_EQ(dirs_of(folders), (std::vector<fs::path>{"/cmd/a", "/cmd/b", "/env/c", "/env/d",
                                                     ("/opt/mhd/bin" / installed_plugin_dir_from_bindir()).lexically_normal(),
                                                     build_tree_plugin_dir()}));
  EXPECT_EQ(folders[0].source, PluginFolderSource::CommandLine);
  EXPECT_EQ(folders[2].source, PluginFolderSource::Environment);
  EXPECT_EQ(folders[4].source, PluginFolderSource::Executable);
  EXPECT_EQ(folders[5].source, PluginFolderSource::BuildTree);
}

TEST(PluginFolders, AFolderNamedTwiceKeepsItsFirstPlace) {
  const auto folders = plugin_folders({"/x/a", "/x/b/../a"}, "/x/a/:/x/c", "");
  EXPECT_EQ(dirs_of(folders), (std::vector<fs::path>{"/x/a", "/x/c", build_tree_plugin_dir()}));
}

TEST(PluginFolders, VersionedFolders) {
  EXPECT_EQ(versioned_plugin_subdir(), fs::path("mhd/plugins-abi" + std::to_string(MHD_PLUGIN_ABI_VERSION)));
  // bin/ and lib/ are siblings under the prefix (GNUInstallDirs), whatever the libdir.
  const fs::path installed = installed_plugin_dir_from_bindir();
  ASSERT_GE(std::distance(installed.begin(), installed.end()), 4) << installed;
  EXPECT_EQ(*installed.begin(), "..") << installed;
  EXPECT_EQ(*std::next(installed.begin()), "lib") << installed;
  EXPECT_EQ(installed.filename(), versioned_plugin_subdir().filename()) << installed;
  EXPECT_EQ(installed.parent_path().filename(), "mhd") << installed;
  EXPECT_EQ(build_tree_plugin_dir().filename(), "plugins-abi" + std::to_string(MHD_PLUGIN_ABI_VERSION));
  EXPECT_EQ(build_tree_plugin_dir().parent_path().filename(), "mhd");
}

TEST(PluginFolders, StandardReadsTheEnvironmentAndTheExecutable) {
  ASSERT_EQ(::setenv("MHD_PLUGIN_PATH", "/env/one:/env/two", 1), 0);
  const PluginSearchPath search = PluginSearchPath::standard({"/cmd"});
  ::unsetenv("MHD_PLUGIN_PATH");
  // This test runs from the build tree: no installed folder is searched (or listed).
  EXPECT_EQ(dirs_of(search.folders()),
            (std::vector<fs::path>{"/cmd", "/env/one", "/env/two", build_tree_plugin_dir()}));
}

TEST(PluginFolders, AnExecutableInTheBuildTreeSearchesTheBuildTreeOnly) {
  // "<build>/tools/lib/mhd/plugins-abi6" means nothing for a program built there.
  const fs::path in_tree = build_tree_root() / "tools" / "mhd" / "mhd";
  const auto folders = plugin_folders({}, "", in_tree);
  EXPECT_EQ(dirs_of(folders), (std::vector<fs::path>{build_tree_plugin_dir()}));
  ASSERT_EQ(folders.size(), 1u);
  EXPECT_EQ(folders[0].source, PluginFolderSource::BuildTree);
}

TEST_F(PluginSearchPathTest, AnInstalledExecutableNeverSearchesTheBuildTree) {
  const fs::path prefix = folder("prefix");
  const fs::path executable = prefix / "bin" / "mhd";
  const fs::path installed = (executable.parent_path() / installed_plugin_dir_from_bindir()).lexically_normal();
  EXPECT_EQ(dirs_of(plugin_folders({}, "", executable)), (std::vector<fs::path>{installed, build_tree_plugin_dir()}))
      << "no installed plugin folder yet: the executable runs from a tree";
  fs::create_directories(installed);
  const auto folders = plugin_folders({}, "", executable);
  EXPECT_EQ(dirs_of(folders), (std::vector<fs::path>{installed}));
  ASSERT_EQ(folders.size(), 1u);
  EXPECT_EQ(folders[0].source, PluginFolderSource::Executable);
}

TEST_F(PluginSearchPathTest, CommandLineBeforeEnvironmentBeforeBuildTree) {
  const fs::path cmd = folder("cmd");
  const fs::path env = folder("env");
  const PluginSearchPath search(plugin_folders({cmd}, env.string(), ""));

  const fs::path in_cmd = copy_into(test::test_plugin("good_device"), cmd);
  const fs::path in_env = copy_into(test::test_plugin("good_device"), env);
  EXPECT_EQ(search.find("good_device").value(), in_cmd);
  fs::remove(in_cmd);
  EXPECT_EQ(search.find("good_device").value(), in_env);

  // null_display is in the build tree (mhd_add_plugin's default folder).
  const fs::path display_in_env = copy_into(test::null_display_plugin(), env);
  EXPECT_EQ(search.find("null_display").value(), display_in_env);
  fs::remove(display_in_env);
  EXPECT_EQ(search.find("null_display").value(), build_tree_plugin_dir() / "libmhd_null_display.so");

  auto loaded = search.load("good_device");
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  EXPECT_EQ(loaded.value()->path(), in_env);
}

TEST_F(PluginSearchPathTest, NotFoundNamesEveryFolder) {
  const PluginSearchPath search({{"/no/a", PluginFolderSource::Given}, {"/no/b", PluginFolderSource::Given}});
  const auto found = search.find("nope");
  ASSERT_FALSE(found.ok());
  EXPECT_EQ(found.error().kind, PluginErrorKind::NotFound);
  EXPECT_EQ(found.error().to_string(), "plugin 'nope': not found (looked for libmhd_nope.so in /no/a, /no/b)");
  EXPECT_EQ(PluginSearchPath({}).find("nope").error().to_string(),
            "plugin 'nope': not found (no plugin folders to search)");
}

TEST_F(PluginSearchPathTest, NamesThatAreNotPluginNames) {
  const PluginSearchPath search({{test::test_plugin_dir(), PluginFolderSource::Given}});
  EXPECT_EQ(search.find("../plugins/libmhd_good_device").error().to_string(),
            "plugin '../plugins/libmhd_good_device': not a valid plugin name (letters, digits, '_' and '-' only)");
  EXPECT_EQ(search.load("").error().kind, PluginErrorKind::NotFound);
}

TEST_F(PluginSearchPathTest, ABrokenFileShadowsAGoodOneAndSaysSo) {
  const fs::path first = folder("first");
  const fs::path second = folder("second");
  std::ofstream(first / "libmhd_good_device.so") << "not a library, but long enough to have an ELF header's size......\n";
  copy_into(test::test_plugin("good_device"), second);
  const PluginSearchPath search(plugin_folders({first, second}, "", ""));
  auto loaded = search.load("good_device");
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().to_string(), "plugin 'good_device' (" + (first / "libmhd_good_device.so").string() +
                                            "): not a loadable library (invalid ELF header)");

  const auto listings = PluginSearchPath({{first, PluginFolderSource::Given}, {second, PluginFolderSource::Given}}).list();
  ASSERT_EQ(listings.size(), 2u);
  EXPECT_FALSE(listings[0].loaded.ok());
  EXPECT_FALSE(listings[0].shadowed);
  EXPECT_TRUE(listings[1].loaded.ok());
  EXPECT_TRUE(listings[1].shadowed);
}

TEST_F(PluginSearchPathTest, ListingSurvivesEveryBrokenPlugin) {
  const fs::path missing = root_ / "missing";
  const PluginSearchPath search({{missing, PluginFolderSource::Given}, {test::test_plugin_dir(), PluginFolderSource::Given}});
  const std::vector<PluginListing> listings = search.list();

  std::vector<std::string> good;
  std::vector<std::string> broken;
  for (const PluginListing& listing : listings) {
    EXPECT_EQ(listing.path.parent_path(), test::test_plugin_dir());
    EXPECT_FALSE(listing.shadowed);
    if (listing.loaded.ok()) {
      good.push_back(listing.loaded.value().name);
    } else {
      broken.push_back(listing.loaded.error().plugin);
    }
  }
  EXPECT_EQ(good, (std::vector<std::string>{"good_base", "good_device", "good_link", "good_tracker", "nan_device", "open_fails",
                                            "rejects_unknown_param"}));
  EXPECT_EQ(broken, (std::vector<std::string>{"abi2_device", "abi3_device", "abi4_device", "abi5_device", "bad_param_decl", "empty_name", "entry_returns_null",
                                              "garbage", "misnamed",
                                              "missing_device_read", "no_entry", "wrong_abi_version", "wrong_kind",
                                              "wrong_struct_size"}));
}

TEST_F(PluginSearchPathTest, ListingSkipsFilesThatAreNotNamedLikePlugins) {
  const fs::path dir = folder("mixed");
  std::ofstream(dir / "README.txt") << "hello\n";
  std::ofstream(dir / "libother.so") << "hello\n";
  fs::create_directories(dir / "libmhd_folder.so");
  copy_into(test::test_plugin("good_base"), dir);
  const auto listings = PluginSearchPath({{dir, PluginFolderSource::Given}}).list();
  ASSERT_EQ(listings.size(), 1u);
  EXPECT_EQ(listings[0].path, dir / "libmhd_good_base.so");
  EXPECT_EQ(listings[0].loaded.value().kind, PluginKind::Base);
}

}  // namespace
}  // namespace mhd

// Loading plugin files through the real dlopen path: one test plugin per way a plugin
// can be broken, each refused with its own error kind and exact message.

#include "plugin_host/plugin_library.h"
#include "plugin_host/plugin_name.h"
#include "test_plugins.h"

#include <mhd/plugin_abi.h>

#include <gtest/gtest.h>

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include <string>

namespace mhd {
namespace {

using test::test_plugin;

/// True while `path` is loaded in this process (dlopen with RTLD_NOLOAD loads nothing).
bool is_loaded(const std::filesystem::path& path) {
  void* handle = dlopen(std::filesystem::absolute(path).c_str(), RTLD_NOW | RTLD_NOLOAD);
  if (handle == nullptr) return false;
  dlclose(handle);
  return true;
}

/// Loads the test plugin `name`, expects failure and returns the error.
PluginError load_error(const std::string& name) {
  auto loaded = PluginLibrary::load(test_plugin(name));
  EXPECT_FALSE(loaded.ok()) << name << " should not load";
  if (loaded.ok()) return {};
  return loaded.error();
}

std::string where(const std::string& name) { return "plugin '" + name + "' (" + test_plugin(name).string() + "): "; }

TEST(PluginLibrary, LoadsAGoodPluginAndReadsItsTable) {
  auto loaded = PluginLibrary::load(test_plugin("good_device"));
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  const PluginLibrary& library = *loaded.value();
  EXPECT_EQ(library.name(), "good_device");
  EXPECT_EQ(library.kind(), PluginKind::Device);
  EXPECT_EQ(library.info().version, "1.2.3");
  EXPECT_EQ(library.info().description, "test device");
  EXPECT_EQ(library.path(), test_plugin("good_device"));
  EXPECT_EQ(library.api().abi_version, MHD_PLUGIN_ABI_VERSION);
  EXPECT_TRUE(is_loaded(test_plugin("good_device")));
}

TEST(PluginLibrary, UnloadsWhenTheLastReferenceGoes) {
  {
    auto loaded = PluginLibrary::load(test_plugin("good_tracker"));
    ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
    EXPECT_TRUE(is_loaded(test_plugin("good_tracker")));
  }
  EXPECT_FALSE(is_loaded(test_plugin("good_tracker")));
}

TEST(PluginLibrary, MissingFile) {
  const PluginError e = load_error("no_such_plugin");
  EXPECT_EQ(e.kind, PluginErrorKind::NotFound);
  EXPECT_EQ(e.plugin, "no_such_plugin");
  EXPECT_EQ(e.to_string(), where("no_such_plugin") + "no such file");
}

TEST(PluginLibrary, TextFileIsNotALibrary) {
  const PluginError e = load_error("garbage");
  EXPECT_EQ(e.kind, PluginErrorKind::NotALibrary);
  EXPECT_EQ(e.to_string(), where("garbage") + "not a loadable library (invalid ELF header)");
}

TEST(PluginLibrary, LibraryWithoutEntryPoint) {
  const PluginError e = load_error("no_entry");
  EXPECT_EQ(e.kind, PluginErrorKind::NoEntryPoint);
  EXPECT_EQ(e.to_string(), where("no_entry") + "exports no mhd_plugin_entry");
  EXPECT_FALSE(is_loaded(test_plugin("no_entry")));
}

TEST(PluginLibrary, EntryThatRefusesTheHost) {
  const PluginError e = load_error("entry_returns_null");
  EXPECT_EQ(e.kind, PluginErrorKind::EntryReturnedNull);
  EXPECT_EQ(e.to_string(), where("entry_returns_null") + "refused this host (mhd_plugin_entry(" +
                               std::to_string(MHD_PLUGIN_ABI_VERSION) + ") returned NULL)");
  EXPECT_FALSE(is_loaded(test_plugin("entry_returns_null")));
}

TEST(PluginLibrary, WrongAbiVersion) {
  const PluginError e = load_error("wrong_abi_version");
  EXPECT_EQ(e.kind, PluginErrorKind::AbiVersionMismatch);
  EXPECT_EQ(e.to_string(), where("wrong_abi_version") + "ABI version " + std::to_string(MHD_PLUGIN_ABI_VERSION + 1) +
                               ", this host speaks " + std::to_string(MHD_PLUGIN_ABI_VERSION));
  EXPECT_FALSE(is_loaded(test_plugin("wrong_abi_version")));
}

/// `name`, a plugin of an older ABI `version`, is refused with the message that says so.
void expect_refused_as_older(const char* name, int version) {
  static_assert(MHD_PLUGIN_ABI_VERSION == 6u, "the refusal below names this host's version");
  const PluginError e = load_error(name);
  EXPECT_EQ(e.kind, PluginErrorKind::AbiVersionMismatch);
  EXPECT_EQ(e.to_string(), where(name) + "built for plugin ABI " + std::to_string(version) +
                               ", this host speaks ABI 6: rebuild it against this MHD's "
                               "mhd/plugin_abi.h (docs/plugins.md, \"Porting a plugin to ABI 6\")");
  EXPECT_FALSE(is_loaded(test_plugin(name)));
}

TEST(PluginLibrary, AnAbi2PluginIsRefusedNamingItsVersion) {
  // abi2_device is built against the frozen ABI 2 header and, as every v2 plugin does,
  // returns NULL to a host that asks for a newer version.
  expect_refused_as_older("abi2_device", 2);
}

TEST(PluginLibrary, AnAbi3PluginIsRefusedNamingItsVersion) {
  // A v3 plugin expects the simulated world in mhd_host, which ABI 4 took out: the host
  // never opens it.
  expect_refused_as_older("abi3_device", 3);
}

TEST(PluginLibrary, AnAbi4PluginIsRefusedNamingItsVersion) {
  // A v4 base would leave the lift fields of ABI 5's base state and command unread: the
  // host never opens a v4 plugin.
  expect_refused_as_older("abi4_device", 4);
}

TEST(PluginLibrary, AnAbi5PluginIsRefusedNamingItsVersion) {
  // A v5 table ends before link_send and link_read: reading them would read past it.
  expect_refused_as_older("abi5_device", 5);
}

TEST(PluginLibrary, ADeclarationWhoseDefaultBreaksItsRangeIsABadTable) {
  const PluginError e = load_error("bad_param_decl");
  EXPECT_EQ(e.kind, PluginErrorKind::BadTable);
  EXPECT_EQ(e.to_string(), where("bad_param_decl") +
                               "parameter declaration 0: its default is invalid: parameter 'rate_hz' must be a "
                               "number > 0 (Hz), got '0'");
  // The dual: good_device's declarations pass, and it loads.
  EXPECT_TRUE(PluginLibrary::load(test_plugin("good_device")).ok());
}

TEST(PluginLibrary, WrongStructSize) {
  const PluginError e = load_error("wrong_struct_size");
  EXPECT_EQ(e.kind, PluginErrorKind::StructSizeMismatch);
  EXPECT_EQ(e.to_string(), where("wrong_struct_size") + "plugin table is " +
                               std::to_string(sizeof(mhd_plugin_api) + sizeof(void*)) + " bytes, this host's is " +
                               std::to_string(sizeof(mhd_plugin_api)) + " (built against another plugin_abi.h)");
  EXPECT_FALSE(is_loaded(test_plugin("wrong_struct_size")));
}

TEST(PluginLibrary, UnknownKind) {
  const PluginError e = load_error("wrong_kind");
  EXPECT_EQ(e.kind, PluginErrorKind::WrongKind);
  EXPECT_EQ(e.to_string(), where("wrong_kind") + "unknown kind 99");
}

TEST(PluginLibrary, MissingMandatoryCall) {
  const PluginError e = load_error("missing_device_read");
  EXPECT_EQ(e.kind, PluginErrorKind::BadTable);
  EXPECT_EQ(e.to_string(), where("missing_device_read") + "the table lacks device_read (mandatory for a device plugin)");
  EXPECT_FALSE(is_loaded(test_plugin("missing_device_read")));
}

TEST(PluginLibrary, EmptyName) {
  const PluginError e = load_error("empty_name");
  EXPECT_EQ(e.kind, PluginErrorKind::BadTable);
  EXPECT_EQ(e.to_string(), where("empty_name") + "the table gives no name");
}

TEST(PluginLibrary, NameThatDisagreesWithTheFile) {
  const PluginError e = load_error("misnamed");
  EXPECT_EQ(e.kind, PluginErrorKind::BadTable);
  EXPECT_EQ(e.to_string(), where("misnamed") + "the table names the plugin 'someone_else', the file is named for 'misnamed'");
}

TEST(PluginLibrary, PluginsThatFailLaterStillLoad) {
  for (const char* name : {"open_fails", "rejects_unknown_param", "nan_device", "good_base"}) {
    auto loaded = PluginLibrary::load(test_plugin(name));
    EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
  }
}

TEST(PluginLibrary, LoadsTheExampleDisplay) {
  auto loaded = PluginLibrary::load(test::null_display_plugin());
  ASSERT_TRUE(loaded.ok()) << loaded.error().to_string();
  EXPECT_EQ(loaded.value()->name(), "null_display");
  EXPECT_EQ(loaded.value()->kind(), PluginKind::Display);
  EXPECT_EQ(loaded.value()->info().version, "1.0.0");
}

TEST(PluginName, FileNames) {
  EXPECT_EQ(plugin_file_name("sim_phantom"), "libmhd_sim_phantom.so");
  EXPECT_EQ(plugin_name_from_file("/a/b/libmhd_sim_phantom.so"), "sim_phantom");
  EXPECT_EQ(plugin_name_from_file("libmhd_.so"), "");
  EXPECT_EQ(plugin_name_from_file("libfoo.so"), "");
  EXPECT_EQ(plugin_name_from_file("libmhd_x.so.1"), "");
  EXPECT_TRUE(is_valid_plugin_name("sim_phantom-2"));
  EXPECT_FALSE(is_valid_plugin_name(""));
  EXPECT_FALSE(is_valid_plugin_name("../x"));
  EXPECT_FALSE(is_valid_plugin_name("a b"));
}

TEST(PluginError, MessageWithAndWithoutPath) {
  PluginError e{PluginErrorKind::AbiVersionMismatch, "sim_phantom", "/p/libmhd_sim_phantom.so",
                "ABI version 2, this host speaks 1"};
  EXPECT_EQ(e.to_string(), "plugin 'sim_phantom' (/p/libmhd_sim_phantom.so): ABI version 2, this host speaks 1");
  e.path.clear();
  EXPECT_EQ(e.to_string(), "plugin 'sim_phantom': ABI version 2, this host speaks 1");
  EXPECT_EQ(to_string(PluginErrorKind::StructSizeMismatch), "struct-size-mismatch");
}

// A plugin runs with the user's rights, so a file or folder others may write is a way for
// them to run code as this user: refused before dlopen, unless the user opts in.
class WritablePluginTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ::unsetenv("MHD_ALLOW_WRITABLE_PLUGINS");
    dir_ = std::filesystem::temp_directory_path() / ("mhd_writable_plugin_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "folder");
    std::filesystem::permissions(dir_ / "folder", std::filesystem::perms(0755));
    file_ = dir_ / "folder" / "libmhd_good_device.so";
    std::filesystem::copy_file(test_plugin("good_device"), file_);
    std::filesystem::permissions(file_, std::filesystem::perms(0755));
  }
  void TearDown() override {
    ::unsetenv("MHD_ALLOW_WRITABLE_PLUGINS");
    std::filesystem::remove_all(dir_);
  }
  std::filesystem::path dir_;
  std::filesystem::path file_;
};

TEST_F(WritablePluginTest, AFileOthersMayWriteIsRefusedBeforeItIsLoaded) {
  ASSERT_TRUE(PluginLibrary::load(file_).ok()) << "the same file, 0755, loads";
  std::filesystem::permissions(file_, std::filesystem::perms(0757));
  auto loaded = PluginLibrary::load(file_);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().kind, PluginErrorKind::Untrusted);
  EXPECT_EQ(loaded.error().to_string(),
            "plugin 'good_device' (" + file_.string() + "): the file " + file_.string() +
                " is writable by other users (mode 0757), so they could run code as you: remove their write "
                "permission (chmod o-w), or set MHD_ALLOW_WRITABLE_PLUGINS=1 to load it anyway");
  EXPECT_FALSE(is_loaded(file_)) << "refused before dlopen";
}

TEST_F(WritablePluginTest, AFolderOthersMayWriteIsRefusedEvenWithTheStickyBit) {
  for (const unsigned mode : {0777U, 01777U, 0703U}) {
    std::filesystem::permissions(dir_ / "folder", std::filesystem::perms(mode));
    auto loaded = PluginLibrary::load(file_);
    ASSERT_FALSE(loaded.ok()) << std::oct << mode;
    EXPECT_EQ(loaded.error().kind, PluginErrorKind::Untrusted);
    EXPECT_NE(loaded.error().message.find("the folder " + (dir_ / "folder").string() + " is writable by other users"),
              std::string::npos)
        << loaded.error().message;
  }
  std::filesystem::permissions(dir_ / "folder", std::filesystem::perms(0775));
  EXPECT_TRUE(PluginLibrary::load(file_).ok()) << "a group-writable folder is the user's own choice";
}

TEST_F(WritablePluginTest, ALinkToAFileOthersMayWriteIsRefused) {
  const std::filesystem::path outside = dir_ / "outside";
  std::filesystem::create_directories(outside);
  std::filesystem::permissions(outside, std::filesystem::perms(0777));
  std::filesystem::rename(file_, outside / "libmhd_good_device.so");
  std::filesystem::create_symlink(outside / "libmhd_good_device.so", file_);
  auto loaded = PluginLibrary::load(file_);
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().kind, PluginErrorKind::Untrusted);
  EXPECT_NE(loaded.error().message.find("the folder " + outside.string()), std::string::npos) << loaded.error().message;
}

TEST_F(WritablePluginTest, TheUserMayOptIn) {
  std::filesystem::permissions(file_, std::filesystem::perms(0777));
  std::filesystem::permissions(dir_ / "folder", std::filesystem::perms(0777));
  ::setenv("MHD_ALLOW_WRITABLE_PLUGINS", "1", 1);
  auto loaded = PluginLibrary::load(file_);
  EXPECT_TRUE(loaded.ok()) << loaded.error().to_string();
  ::setenv("MHD_ALLOW_WRITABLE_PLUGINS", "0", 1);
  EXPECT_FALSE(PluginLibrary::load(file_).ok()) << "only 1 opts in";
}

}  // namespace
}  // namespace mhd

#include "plugin_file.h"

#include <dlfcn.h>

#include <stdexcept>
#include <vector>

namespace mhd::test {

PluginFile::PluginFile(const char* path) : handle_(dlopen(path, RTLD_NOW | RTLD_LOCAL)) {
  if (handle_ == nullptr) throw std::runtime_error(std::string("dlopen: ") + dlerror());
  void* symbol = dlsym(handle_, MHD_PLUGIN_ENTRY_SYMBOL);
  if (symbol == nullptr) {
    dlclose(handle_);
    throw std::runtime_error(std::string(path) + " exports no " MHD_PLUGIN_ENTRY_SYMBOL);
  }
  entry_ = reinterpret_cast<mhd_plugin_entry_fn>(symbol);
}

PluginFile::~PluginFile() { dlclose(handle_); }

const mhd_plugin_api& PluginFile::api() const {
  const mhd_plugin_api* api = entry(MHD_PLUGIN_ABI_VERSION);
  if (api == nullptr) throw std::runtime_error("the plugin refuses ABI version 1");
  return *api;
}

FakeHost::FakeHost() : session(sim_world::SimSession::acquire("", 0.0)), world(session->world()) {
  host.abi_version = MHD_PLUGIN_ABI_VERSION;
  host.struct_size = sizeof(mhd_host);
  host.now_s = [](void* context) { return *static_cast<double*>(context); };
  host.clock_context = &now_s;
}

Opened open_plugin(const mhd_plugin_api& api, const mhd_host& host,
                   std::initializer_list<std::pair<const char*, const char*>> params) {
  std::vector<mhd_param> list;
  for (const auto& [name, value] : params) list.push_back({name, value});
  mhd_error err{};
  Opened out;
  out.instance = api.open(&host, list.data(), list.size(), &err);
  if (out.instance == nullptr) out.error = err.message;
  return out;
}

StartedPlugin::StartedPlugin(const mhd_plugin_api& api, const mhd_host& host,
                             std::initializer_list<std::pair<const char*, const char*>> params)
    : api_(api) {
  const Opened opened = open_plugin(api, host, params);
  if (opened.instance == nullptr) throw std::runtime_error(opened.error);
  instance_ = opened.instance;
  mhd_error err{};
  if (api.start(instance_, &err) != MHD_OK) {
    api.close(instance_);
    throw std::runtime_error(err.message);
  }
}

StartedPlugin::~StartedPlugin() {
  mhd_error err{};
  api_.stop(instance_, &err);
  api_.close(instance_);
}

}  // namespace mhd::test

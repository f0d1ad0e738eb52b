// A probe for tests/layering: the plugin ABI header, which only plugin_host among the
// engine's layers may see (it links the ABI privately and converts at every call).
#include <mhd/plugin_abi.h>

namespace mhd::layering_probe {

unsigned abi_version() { return MHD_PLUGIN_ABI_VERSION; }

}  // namespace mhd::layering_probe

#include "realtime/thread_name.h"

#include <pthread.h>

#include <cstring>

namespace mhd::realtime {

void name_current_thread(const char* name) noexcept {
  char cut[16] = {};
  std::strncpy(cut, name, sizeof cut - 1);
  (void)pthread_setname_np(pthread_self(), cut);  // a name is a convenience: failure is harmless
}

}  // namespace mhd::realtime

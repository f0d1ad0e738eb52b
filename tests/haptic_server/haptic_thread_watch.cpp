// The interposers of haptic_thread_hygiene_test.cpp (see there): each counts the calls
// made on the watched thread while counting is on, then does what it replaces. In a file
// of its own, apart from the code it watches.
#include "haptic_thread_watch.h"

#include "haptic_server/opened_plugin.h"

#include <dlfcn.h>
#include <pthread.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>

namespace {

std::atomic<bool> g_counting{false};
std::atomic<const char*> g_thread_name{""};
std::atomic<int> g_watch{0};  // which watch this is: a thread asks its name again for each
std::atomic<long> g_locks{0}, g_allocations{0}, g_writes{0}, g_locks_in_plugins{0}, g_allocations_in_plugins{0};
std::atomic<void*> g_first_caller{nullptr};  // of the first lock or allocation counted
thread_local int t_watch = 0;          // the watch t_is_watched answers for
thread_local bool t_is_watched = false;

bool on_watched_thread() noexcept {
  if (!g_counting.load(std::memory_order_relaxed)) return false;
  if (const int watch = g_watch.load(std::memory_order_relaxed); t_watch != watch) {
    char name[16] = {};
    (void)prctl(PR_GET_NAME, name, 0, 0, 0);  // a system call: no lock, no allocation
    t_is_watched = std::strcmp(name, g_thread_name.load(std::memory_order_relaxed)) == 0;
    t_watch = watch;
  }
  return t_is_watched;
}

// Reads thread-locals only: no lock, no allocation.
bool in_plugin_call() noexcept { return mhd::plugin_call_on_this_thread().first != nullptr; }

using MutexLockFn = int (*)(pthread_mutex_t*);
using WriteFn = ssize_t (*)(int, const void*, size_t);
using FwriteFn = size_t (*)(const void*, size_t, size_t, FILE*);
MutexLockFn g_real_lock = nullptr;
WriteFn g_real_write = nullptr;
FwriteFn g_real_fwrite = nullptr;

// Resolved before main, before any thread: dlsym may lock and allocate itself.
[[gnu::constructor]] void resolve_real_functions() {
  g_real_lock = reinterpret_cast<MutexLockFn>(dlsym(RTLD_NEXT, "pthread_mutex_lock"));
  g_real_write = reinterpret_cast<WriteFn>(dlsym(RTLD_NEXT, "write"));
  g_real_fwrite = reinterpret_cast<FwriteFn>(dlsym(RTLD_NEXT, "fwrite"));
}

}  // namespace

extern "C" int pthread_mutex_lock(pthread_mutex_t* m) {
  if (on_watched_thread()) {
    if (g_locks.fetch_add(1, std::memory_order_relaxed) == 0) {
      g_first_caller.store(__builtin_return_address(0), std::memory_order_relaxed);
    }
    if (in_plugin_call()) g_locks_in_plugins.fetch_add(1, std::memory_order_relaxed);
  }
  return g_real_lock(m);
}

extern "C" ssize_t write(int fd, const void* data, size_t n) {
  if (on_watched_thread()) g_writes.fetch_add(1, std::memory_order_relaxed);
  return g_real_write(fd, data, n);
}

extern "C" size_t fwrite(const void* data, size_t size, size_t count, FILE* f) {
  if (on_watched_thread()) g_writes.fetch_add(1, std::memory_order_relaxed);
  return g_real_fwrite(data, size, count, f);
}

void* operator new(std::size_t size) {
  if (on_watched_thread()) {
    if (g_allocations.fetch_add(1, std::memory_order_relaxed) == 0) {
      g_first_caller.store(__builtin_return_address(0), std::memory_order_relaxed);
    }
    if (in_plugin_call()) g_allocations_in_plugins.fetch_add(1, std::memory_order_relaxed);
  }
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace mhd::test {

void start_thread_watch(const char* thread_name) noexcept {
  g_thread_name = thread_name;
  g_watch.fetch_add(1);
  g_locks = 0;
  g_allocations = 0;
  g_locks_in_plugins = 0;
  g_allocations_in_plugins = 0;
  g_writes = 0;
  g_first_caller = nullptr;
  g_counting = true;
}

ThreadCalls stop_thread_watch() {
  g_counting = false;
  ThreadCalls calls{g_locks.load(), g_allocations.load(), g_writes.load(), g_locks_in_plugins.load(),
                    g_allocations_in_plugins.load(), "-"};
  Dl_info info{};
  if (void* caller = g_first_caller.load(); caller != nullptr && dladdr(caller, &info) != 0) {
    calls.first_caller = std::string(info.dli_fname != nullptr ? info.dli_fname : "?") + " " +
                         (info.dli_sname != nullptr ? info.dli_sname : "?");
  }
  return calls;
}

}  // namespace mhd::test

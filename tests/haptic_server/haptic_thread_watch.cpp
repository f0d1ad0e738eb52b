// The interposers of haptic_thread_hygiene_test.cpp (see there): each counts the calls
// made on the thread named realtime::kHapticThreadName while counting is on, then does
// what it replaces. In a file of its own, apart from the code it watches.
#include "haptic_thread_watch.h"

#include "realtime/thread_name.h"

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
std::atomic<long> g_locks{0}, g_allocations{0}, g_writes{0};
std::atomic<void*> g_first_caller{nullptr};  // of the first lock or allocation counted
thread_local int t_is_haptic = -1;  // unknown until asked while counting

bool on_haptic_thread() noexcept {
  if (!g_counting.load(std::memory_order_relaxed)) return false;
  if (t_is_haptic < 0) {
    char name[16] = {};
    (void)prctl(PR_GET_NAME, name, 0, 0, 0);  // a system call: no lock, no allocation
    t_is_haptic = std::strcmp(name, mhd::realtime::kHapticThreadName) == 0 ? 1 : 0;
  }
  return t_is_haptic == 1;
}

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
  if (on_haptic_thread() && g_locks.fetch_add(1, std::memory_order_relaxed) == 0) {
    g_first_caller.store(__builtin_return_address(0), std::memory_order_relaxed);
  }
  return g_real_lock(m);
}

extern "C" ssize_t write(int fd, const void* data, size_t n) {
  if (on_haptic_thread()) g_writes.fetch_add(1, std::memory_order_relaxed);
  return g_real_write(fd, data, n);
}

extern "C" size_t fwrite(const void* data, size_t size, size_t count, FILE* f) {
  if (on_haptic_thread()) g_writes.fetch_add(1, std::memory_order_relaxed);
  return g_real_fwrite(data, size, count, f);
}

void* operator new(std::size_t size) {
  if (on_haptic_thread() && g_allocations.fetch_add(1, std::memory_order_relaxed) == 0) {
    g_first_caller.store(__builtin_return_address(0), std::memory_order_relaxed);
  }
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace mhd::test {

void start_haptic_thread_watch() noexcept {
  g_locks = 0;
  g_allocations = 0;
  g_writes = 0;
  g_first_caller = nullptr;
  g_counting = true;
}

HapticThreadCalls stop_haptic_thread_watch() {
  g_counting = false;
  HapticThreadCalls calls{g_locks.load(), g_allocations.load(), g_writes.load(), "-"};
  Dl_info info{};
  if (void* caller = g_first_caller.load(); caller != nullptr && dladdr(caller, &info) != 0) {
    calls.first_caller = std::string(info.dli_fname != nullptr ? info.dli_fname : "?") + " " +
                         (info.dli_sname != nullptr ? info.dli_sname : "?");
  }
  return calls;
}

}  // namespace mhd::test

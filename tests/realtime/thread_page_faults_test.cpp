// A thread's page faults, as the haptic thread counts those of its loop.

#include "realtime/thread_page_faults.h"

#include <gtest/gtest.h>

#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstddef>
#include <thread>

namespace mhd::realtime {
namespace page_faults_test {

constexpr long kPages = 256;

// Writes a byte to each of kPages fresh anonymous pages: a minor fault each.
void touch_fresh_pages() {
  const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const std::size_t bytes = static_cast<std::size_t>(kPages) * page;
  void* region = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(region, MAP_FAILED);
  auto* p = static_cast<volatile unsigned char*>(region);
  for (std::size_t i = 0; i < bytes; i += page) p[i] = 1;
  ::munmap(region, bytes);
}

TEST(ThreadPageFaults, AThreadCountsThePagesItFaultsIn) {
  const PageFaults before = current_thread_page_faults();
  touch_fresh_pages();
  const PageFaults taken = current_thread_page_faults() - before;
  EXPECT_GE(taken.minor, kPages);
  EXPECT_EQ(taken.major, 0);  // nothing came from the disk
}

TEST(ThreadPageFaults, AnotherThreadsFaultsAreNotCounted) {
  // The other thread is started first (starting one takes faults of its own, hundreds
  // under a sanitizer), then touches its pages while this one waits.
  std::atomic<bool> go{false};
  PageFaults taken_there;
  std::thread other([&] {
    while (!go.load()) std::this_thread::yield();
    const PageFaults before = current_thread_page_faults();
    touch_fresh_pages();
    taken_there = current_thread_page_faults() - before;
  });
  const PageFaults before = current_thread_page_faults();
  go.store(true);
  other.join();
  const PageFaults taken_here = current_thread_page_faults() - before;
  EXPECT_GE(taken_there.minor, kPages);
  EXPECT_LT(taken_here.minor, kPages);
}

}  // namespace page_faults_test
}  // namespace mhd::realtime

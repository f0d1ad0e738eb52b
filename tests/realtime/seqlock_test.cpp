// The seqlock the simulated world is shared through: its readers run inside plugin calls
// on the haptic thread, so a read must never wait for a writer the scheduler has stopped
// part-way through a write (CI once saw a device call stuck over 100 ms that way, and the
// plugin watchdog ended the run), and must still return whole writes, never older ones.
#include "realtime/seqlock.h"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <thread>
#include <vector>

namespace {

using mhd::realtime::Seqlock;

TEST(Seqlock, AReadReturnsTheInitialValuesThenTheLastCompleteWrite) {
  Seqlock<3> lock({1.0, 2.0, 3.0});
  EXPECT_EQ(lock.read(), (std::array<double, 3>{1.0, 2.0, 3.0}));
  lock.write({4.0, 5.0, 6.0});
  EXPECT_EQ(lock.read(), (std::array<double, 3>{4.0, 5.0, 6.0}));
  lock.write({7.0, 8.0, 9.0});
  lock.write({10.0, 11.0, 12.0});
  EXPECT_EQ(lock.read(), (std::array<double, 3>{10.0, 11.0, 12.0}));
}

TEST(Seqlock, AReaderNeverWaitsForAWriterStoppedHalfWayThroughAWrite) {
  Seqlock<3> lock({1.0, 2.0, 3.0});
  lock.write({4.0, 5.0, 6.0});
  std::atomic<bool> writer_stopped{false}, read_done{false}, read_done_while_stopped{false};
  std::thread writer([&] {
    // Stands for the scheduler stopping the writer with half the values written: it
    // resumes once the read is done, or after a long while if the read waits for it.
    lock.write({7.0, 8.0, 9.0}, [&] {
      writer_stopped.store(true);
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(5);
      while (!read_done.load() && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
      read_done_while_stopped.store(read_done.load());
    });
  });
  while (!writer_stopped.load()) std::this_thread::yield();
  const std::array<double, 3> seen = lock.read();
  read_done.store(true);
  writer.join();
  EXPECT_TRUE(read_done_while_stopped.load()) << "the read waited for the stopped writer";
  EXPECT_EQ(seen, (std::array<double, 3>{4.0, 5.0, 6.0})) << "the last complete write, whole";
  EXPECT_EQ(lock.read(), (std::array<double, 3>{7.0, 8.0, 9.0})) << "and the write once it completes";
}

TEST(Seqlock, ConcurrentReadersNeverSeeATornOrOlderWrite) {
  Seqlock<3> lock;
  constexpr std::uint64_t kWrites = 200000;
  std::atomic<bool> done{false};
  std::atomic<int> readers_reading{0};
  std::thread writer([&] {
    while (readers_reading.load() < 2) std::this_thread::yield();  // writes while they read
    for (std::uint64_t n = 1; n <= kWrites; ++n) {
      const auto v = static_cast<double>(n);
      lock.write({v, 2.0 * v, 3.0 * v});
    }
    done.store(true);
  });
  struct Seen {
    std::uint64_t torn = 0, backwards = 0;
    double last = 0.0;
  };
  std::vector<Seen> seen(2);
  std::vector<std::thread> readers;
  for (Seen& s : seen) {
    readers.emplace_back([&lock, &done, &readers_reading, &s] {
      readers_reading.fetch_add(1);
      for (;;) {
        const bool finished = done.load();
        const std::array<double, 3> v = lock.read();
        if (v[1] != 2.0 * v[0] || v[2] != 3.0 * v[0]) ++s.torn;
        if (v[0] < s.last) ++s.backwards;
        s.last = v[0];
        if (finished) break;
      }
    });
  }
  writer.join();
  for (std::thread& r : readers) r.join();
  for (const Seen& s : seen) {
    EXPECT_EQ(s.torn, 0u);
    EXPECT_EQ(s.backwards, 0u);
    EXPECT_EQ(s.last, static_cast<double>(kWrites)) << "the last read after the last write returns it";
  }
}

}  // namespace

#include "realtime/triple_buffer.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <thread>

namespace {

using mhd::realtime::TripleBuffer;

struct Sample {
  std::uint64_t a = 0, b = 0, c = 0;  // written as (n, 2n, 3n): a torn read breaks it
};

TEST(TripleBuffer, ReadReturnsTheNewestWriteOnceThenReportsNothingNew) {
  TripleBuffer<int> buffer(-1);
  int value = 0;
  EXPECT_FALSE(buffer.read(value));
  EXPECT_EQ(value, -1);
  buffer.write(1);
  buffer.write(2);
  buffer.write(3);
  EXPECT_TRUE(buffer.read(value));
  EXPECT_EQ(value, 3);  // the older writes are dropped
  EXPECT_FALSE(buffer.read(value));
  EXPECT_EQ(value, 3);  // and the last value stays
  buffer.write(4);
  EXPECT_EQ(buffer.latest(), 4);
}

TEST(TripleBuffer, ConcurrentReaderNeverSeesATornOrOlderValue) {
  TripleBuffer<Sample> buffer;
  constexpr std::uint64_t kWrites = 200000;
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (std::uint64_t n = 1; n <= kWrites; ++n) buffer.write({n, 2 * n, 3 * n});
    done.store(true);
  });
  std::uint64_t last = 0, torn = 0, backwards = 0, fresh = 0;
  Sample s;
  for (;;) {
    const bool finished = done.load();
    if (!buffer.read(s)) {
      if (finished) break;  // nothing new after the last write
      continue;
    }
    ++fresh;
    if (s.b != 2 * s.a || s.c != 3 * s.a) ++torn;
    if (s.a < last) ++backwards;
    last = s.a;
  }
  writer.join();
  EXPECT_EQ(torn, 0u);
  EXPECT_EQ(backwards, 0u);
  EXPECT_GT(fresh, 0u);
  EXPECT_EQ(buffer.latest().a, kWrites);
}

}  // namespace

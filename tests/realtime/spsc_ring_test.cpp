#include "realtime/spsc_ring.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <thread>

namespace {

using mhd::realtime::SpscRing;

TEST(SpscRing, KeepsOrderAndRefusesWhenFull) {
  SpscRing<int> ring(3);
  EXPECT_EQ(ring.capacity(), 3u);
  EXPECT_TRUE(ring.empty());
  EXPECT_TRUE(ring.push(1));
  EXPECT_TRUE(ring.push(2));
  EXPECT_TRUE(ring.push(3));
  EXPECT_FALSE(ring.push(4));  // full: nothing stored, the producer counts a drop
  int v = 0;
  ASSERT_TRUE(ring.pop(v));
  EXPECT_EQ(v, 1);
  EXPECT_TRUE(ring.push(5));  // wraps around
  for (const int expected : {2, 3, 5}) {
    ASSERT_TRUE(ring.pop(v));
    EXPECT_EQ(v, expected);
  }
  EXPECT_FALSE(ring.pop(v));
  EXPECT_TRUE(ring.empty());
}

TEST(SpscRing, EveryPushedElementArrivesOnceInOrderAcrossThreads) {
  SpscRing<std::uint64_t> ring(64);
  constexpr std::uint64_t kCount = 300000;
  std::thread producer([&] {
    for (std::uint64_t n = 0; n < kCount;) {
      if (ring.push(n)) ++n;
    }
  });
  std::uint64_t expected = 0, out_of_order = 0, v = 0;
  while (expected < kCount) {
    if (!ring.pop(v)) continue;
    if (v != expected) ++out_of_order;
    expected = v + 1;
  }
  producer.join();
  EXPECT_EQ(out_of_order, 0u);
  EXPECT_TRUE(ring.empty());
}

}  // namespace

// ContentHash against libxxhash's one-shot XXH3_128bits: every width, every length across
// XXH3's stripe (64), block (1024) and buffer (256) sizes and the powers of two round
// them, fed whole and in pieces of every awkward size. The dual: one changed byte changes
// the digest.
#include "mesh_io/content_hash.h"

#include <gtest/gtest.h>
#include <xxhash.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace mhd {
namespace {

std::vector<std::byte> random_bytes(std::size_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<std::byte> out(n);
  for (auto& b : out) b = static_cast<std::byte>(rng() & 0xffU);
  return out;
}

ContentHash::Digest hashed_in_pieces(ContentHash::Width width, const std::vector<std::byte>& bytes,
                                     std::size_t piece) {
  ContentHash h(width);
  EXPECT_TRUE(h.ok());
  for (std::size_t at = 0; at < bytes.size(); at += piece) {
    h.update(bytes.data() + at, std::min(piece, bytes.size() - at));
  }
  return h.digest();
}

constexpr ContentHash::Width kWidths[] = {ContentHash::Width::Widest, ContentHash::Width::Baseline};

TEST(ContentHash, EveryWidthGivesTheLibrarysDigestAtEveryLengthAndSplit) {
  const std::vector<std::size_t> lengths = {0,    1,    2,    3,    4,     8,     9,     16,    17,   128,
                                            129,  240,  241,  255,  256,   257,   1023,  1024,  1025, 4095,
                                            4096, 4097, 65535, 65536, 65537, (std::size_t{1} << 20) + 13};
  const std::vector<std::size_t> pieces = {1, 7, 63, 64, 65, 255, 256, 1000, 1024, 4099, std::size_t{1} << 30};
  for (const std::size_t n : lengths) {
    const std::vector<std::byte> bytes = random_bytes(n, static_cast<std::uint32_t>(n) + 1U);
    const XXH128_hash_t want = XXH3_128bits(bytes.data(), bytes.size());
    for (const auto width : kWidths) {
      for (const std::size_t piece : pieces) {
        if (n > 70000 && piece < 64) continue;  // a byte at a time over a megabyte adds nothing
        const ContentHash::Digest got = hashed_in_pieces(width, bytes, piece);
        ASSERT_EQ(got.low64, want.low64) << n << " bytes in pieces of " << piece;
        ASSERT_EQ(got.high64, want.high64) << n << " bytes in pieces of " << piece;
      }
    }
  }
}

// A digest taken part-way leaves the state as it was: feeding on gives the whole's.
TEST(ContentHash, ADigestPartWayDoesNotDisturbTheRest) {
  const std::vector<std::byte> bytes = random_bytes(5000, 7);
  for (const auto width : kWidths) {
    ContentHash h(width);
    h.update(bytes.data(), 3000);
    const XXH128_hash_t part = XXH3_128bits(bytes.data(), 3000);
    EXPECT_EQ(h.digest().low64, part.low64);
    h.update(bytes.data() + 3000, 2000);
    EXPECT_EQ(h.digest().low64, XXH3_128bits(bytes.data(), bytes.size()).low64);
  }
}

TEST(ContentHash, OneChangedByteChangesTheDigest) {
  std::vector<std::byte> bytes = random_bytes(3 * 1024 + 5, 11);
  for (const auto width : kWidths) {
    const ContentHash::Digest before = hashed_in_pieces(width, bytes, 100);
    for (const std::size_t at : {std::size_t{0}, std::size_t{1024}, bytes.size() - 1}) {
      bytes[at] ^= std::byte{0x01};
      const ContentHash::Digest after = hashed_in_pieces(width, bytes, 100);
      bytes[at] ^= std::byte{0x01};
      EXPECT_FALSE(after.low64 == before.low64 && after.high64 == before.high64) << at;
    }
  }
}

// The widest hash is the AVX2 one wherever the CPU has AVX2, and never elsewhere.
TEST(ContentHash, TheWidestRunsOnAvx2ExactlyWhereTheCpuHasIt) {
  EXPECT_FALSE(ContentHash(ContentHash::Width::Baseline).wide());
#if defined(__x86_64__)
  EXPECT_EQ(ContentHash(ContentHash::Width::Widest).wide(), __builtin_cpu_supports("avx2") != 0);
#else
  EXPECT_FALSE(ContentHash(ContentHash::Width::Widest).wide());
#endif
}

}  // namespace
}  // namespace mhd

#pragma once
// libxxhash's XXH3-128, compiled for AVX2 from its own header (content_hash_avx2.cpp).
// Only ContentHash calls these, and only on a CPU that has AVX2.

#include <cstddef>
#include <cstdint>

namespace mhd::content_hash_avx2 {

[[nodiscard]] void* create();
void destroy(void* state);
void update(void* state, const void* data, std::size_t bytes);
void digest(const void* state, std::uint64_t* low64, std::uint64_t* high64);

}  // namespace mhd::content_hash_avx2

// The whole of XXH3 inlined here and compiled with -mavx2, so that xxhash.h picks its
// AVX2 kernel. This file includes nothing with inline C++ (only C headers, whose
// functions XXH_INLINE_ALL makes static): no AVX2 copy of a shared inline function can
// reach the rest of the program, which runs where AVX2 may be missing.
#include "mesh_io/content_hash_avx2.h"

#define XXH_INLINE_ALL
#include <xxhash.h>

#ifndef __AVX2__
#error "content_hash_avx2.cpp must be compiled with -mavx2"
#endif

namespace mhd::content_hash_avx2 {

void* create() {
  XXH3_state_t* state = XXH3_createState();
  if (state != nullptr && XXH3_128bits_reset(state) != XXH_OK) {
    XXH3_freeState(state);
    return nullptr;
  }
  return state;
}

void destroy(void* state) { XXH3_freeState(static_cast<XXH3_state_t*>(state)); }

void update(void* state, const void* data, std::size_t bytes) {
  XXH3_128bits_update(static_cast<XXH3_state_t*>(state), data, bytes);
}

void digest(const void* state, std::uint64_t* low64, std::uint64_t* high64) {
  const XXH128_hash_t h = XXH3_128bits_digest(static_cast<const XXH3_state_t*>(state));
  *low64 = h.low64;
  *high64 = h.high64;
}

}  // namespace mhd::content_hash_avx2

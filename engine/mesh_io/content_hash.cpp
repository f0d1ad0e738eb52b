#include "mesh_io/content_hash.h"

#if defined(MHD_CONTENT_HASH_AVX2)
#include "mesh_io/content_hash_avx2.h"
#endif

#include <xxhash.h>

namespace mhd {
namespace {

bool cpu_has_avx2() {
#if defined(MHD_CONTENT_HASH_AVX2)
  static const bool has = __builtin_cpu_supports("avx2") != 0;
  return has;
#else
  return false;
#endif
}

}  // namespace

ContentHash::ContentHash(Width width) : wide_(width == Width::Widest && cpu_has_avx2()) {
#if defined(MHD_CONTENT_HASH_AVX2)
  if (wide_) {
    state_ = content_hash_avx2::create();
    return;
  }
#endif
  XXH3_state_t* state = XXH3_createState();
  if (state != nullptr && XXH3_128bits_reset(state) != XXH_OK) {
    XXH3_freeState(state);
    state = nullptr;
  }
  state_ = state;
}

ContentHash::~ContentHash() {
  if (state_ == nullptr) return;
#if defined(MHD_CONTENT_HASH_AVX2)
  if (wide_) {
    content_hash_avx2::destroy(state_);
    return;
  }
#endif
  XXH3_freeState(static_cast<XXH3_state_t*>(state_));
}

void ContentHash::update(const void* data, std::size_t bytes) {
  if (state_ == nullptr) return;
#if defined(MHD_CONTENT_HASH_AVX2)
  if (wide_) {
    content_hash_avx2::update(state_, data, bytes);
    return;
  }
#endif
  XXH3_128bits_update(static_cast<XXH3_state_t*>(state_), data, bytes);
}

ContentHash::Digest ContentHash::digest() const {
  Digest d;
  if (state_ == nullptr) return d;
#if defined(MHD_CONTENT_HASH_AVX2)
  if (wide_) {
    content_hash_avx2::digest(state_, &d.low64, &d.high64);
    return d;
  }
#endif
  const XXH128_hash_t h = XXH3_128bits_digest(static_cast<const XXH3_state_t*>(state_));
  d.low64 = h.low64;
  d.high64 = h.high64;
  return d;
}

}  // namespace mhd

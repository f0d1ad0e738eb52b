#pragma once
// The arrays of a mesh: std::vector, whose storage is either its own (the heap) or a block
// that already holds the elements, such as a section of a mapped cache file, adopted
// without a copy and kept alive by a shared owner. A cached mesh of 100 M triangles is
// then not copied out of its file, and its pages are read as they are used.

#include <cstddef>
#include <memory>
#include <new>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace mhd {

template <class T>
class MeshArrayAllocator {
 public:
  using value_type = T;
  // A vector's copy takes storage of its own; a move or swap takes the block with it.
  using propagate_on_container_copy_assignment = std::false_type;
  using propagate_on_container_move_assignment = std::true_type;
  using propagate_on_container_swap = std::true_type;
  using is_always_equal = std::false_type;

  MeshArrayAllocator() noexcept = default;
  template <class U>
  MeshArrayAllocator(const MeshArrayAllocator<U>& /*other*/) noexcept {}  // NOLINT: rebinding takes no block

  /// Hands out `block` (n elements, alive while `owner` is) for the first allocation of
  /// exactly n elements; every other allocation is the heap's.
  MeshArrayAllocator(T* block, std::size_t n, std::shared_ptr<const void> owner) noexcept
      : block_(std::make_shared<Block>(Block{block, n, std::move(owner), false})) {}

  [[nodiscard]] T* allocate(std::size_t n) {
    if (block_ && !block_->given && n == block_->n) {
      block_->given = true;
      return block_->data;
    }
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (block_ && p == block_->data) {
      block_->owner.reset();  // the vector has let go of the block
      return;
    }
    std::allocator<T>().deallocate(p, n);
  }

  /// Elements made in the adopted block keep the bytes they have; elsewhere they are
  /// value-initialised, as in any std::vector.
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    if (in_block(p)) {
      ::new (static_cast<void*>(p)) U;
    } else {
      ::new (static_cast<void*>(p)) U();
    }
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  [[nodiscard]] MeshArrayAllocator select_on_container_copy_construction() const noexcept { return {}; }

  /// True while the vector's storage is an adopted block.
  [[nodiscard]] bool adopted() const noexcept { return block_ && block_->given && block_->owner != nullptr; }

  template <class U>
  friend class MeshArrayAllocator;
  friend bool operator==(const MeshArrayAllocator& a, const MeshArrayAllocator& b) noexcept {
    return a.block_ == b.block_;
  }

 private:
  struct Block {
    T* data;
    std::size_t n;
    std::shared_ptr<const void> owner;
    bool given;
  };
  template <class U>
  [[nodiscard]] bool in_block(const U* p) const noexcept {
    if (!block_) return false;
    const auto* b = reinterpret_cast<const std::byte*>(block_->data);
    const auto* q = reinterpret_cast<const std::byte*>(p);
    return q >= b && q < b + block_->n * sizeof(T);
  }
  // Shared, so that the copy of the allocator a vector keeps sees the block as given.
  std::shared_ptr<Block> block_;
};

/// One array of a mesh (vertices, triangles, normals).
template <class T>
using MeshArray = std::vector<T, MeshArrayAllocator<T>>;

/// A mesh array over `elements` where they lie, not copied: they must stay valid and
/// unchanged while `owner` lives, and the array keeps `owner` alive. The array may be
/// written (a private mapping then copies the page) and may grow (it then moves to the
/// heap and lets the block go).
template <class T>
[[nodiscard]] MeshArray<T> adopt_mesh_array(std::span<T> elements, std::shared_ptr<const void> owner) {
  // Plain data laid out as stored (Eigen's vectors declare copies, so are not "trivially
  // copyable", but hold only their scalars).
  static_assert(std::is_trivially_destructible_v<T> && std::is_standard_layout_v<T>);
  if (elements.empty()) return {};
  MeshArray<T> v(MeshArrayAllocator<T>(elements.data(), elements.size(), std::move(owner)));
  v.reserve(elements.size());
  v.resize(elements.size());
  return v;
}

}  // namespace mhd

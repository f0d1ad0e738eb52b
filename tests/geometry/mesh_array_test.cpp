#include "geometry/mesh_array.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace mhd {
namespace {

using Triple = std::array<std::uint32_t, 3>;

// A block of triples 0..n-1, and an owner whose end the test can see.
struct Block {
  explicit Block(std::size_t n) : elements(n) {
    for (std::size_t i = 0; i < n; ++i) elements[i] = {std::uint32_t(i), std::uint32_t(i + 1), std::uint32_t(i + 2)};
    owner = std::make_shared<int>(0);
    watch = owner;
  }
  std::vector<Triple> elements;
  std::shared_ptr<const void> owner;
  std::weak_ptr<const void> watch;
};

TEST(MeshArray, AnAdoptedArrayIsTheBlockItselfWithItsElementsUntouched) {
  Block b(1000);
  const Triple* const where = b.elements.data();
  MeshArray<Triple> v = adopt_mesh_array(std::span<Triple>(b.elements), std::move(b.owner));
  EXPECT_EQ(v.data(), where);
  ASSERT_EQ(v.size(), 1000u);
  EXPECT_TRUE(v.get_allocator().adopted());
  for (std::size_t i = 0; i < v.size(); ++i) ASSERT_EQ(v[i][2], i + 2) << i;
  EXPECT_FALSE(b.watch.expired()) << "the array keeps its block's owner";
  v = MeshArray<Triple>();
  EXPECT_TRUE(b.watch.expired()) << "and lets it go with its storage";
}

TEST(MeshArray, ACopyAndAGrownArrayLeaveTheBlock) {
  Block b(64);
  MeshArray<Triple> v = adopt_mesh_array(std::span<Triple>(b.elements), std::move(b.owner));
  const MeshArray<Triple> copy = v;
  EXPECT_NE(copy.data(), v.data());
  EXPECT_FALSE(copy.get_allocator().adopted());
  EXPECT_EQ(copy, v);
  // Moving keeps the block; growing copies the elements to the heap and lets it go.
  MeshArray<Triple> moved = std::move(v);
  EXPECT_EQ(moved.data(), b.elements.data());
  EXPECT_TRUE(moved.get_allocator().adopted());
  moved.push_back({7, 8, 9});
  EXPECT_NE(moved.data(), b.elements.data());
  EXPECT_FALSE(moved.get_allocator().adopted());
  EXPECT_TRUE(b.watch.expired());
  EXPECT_EQ(moved[63], (Triple{63, 64, 65}));
  EXPECT_EQ(moved.back(), (Triple{7, 8, 9}));
}

TEST(MeshArray, AnArrayOfItsOwnIsValueInitialisedAsAnyVector) {
  MeshArray<Triple> v;
  v.resize(100);
  for (const Triple& t : v) ASSERT_EQ(t, (Triple{0, 0, 0}));
  EXPECT_FALSE(v.get_allocator().adopted());
  // A block is handed out for its own size only: another size comes from the heap, and
  // the block's elements stay as they were.
  Block b(10);
  MeshArray<Triple> other{MeshArrayAllocator<Triple>(b.elements.data(), b.elements.size(), b.owner)};
  other.resize(5);
  EXPECT_NE(other.data(), b.elements.data());
  EXPECT_EQ(other[4], (Triple{0, 0, 0}));
  EXPECT_EQ(b.elements[4], (Triple{4, 5, 6}));
}

TEST(MeshArray, AnEmptyBlockIsAnEmptyArray) {
  Block b(0);
  const MeshArray<Triple> v = adopt_mesh_array(std::span<Triple>(b.elements), std::move(b.owner));
  EXPECT_TRUE(v.empty());
  EXPECT_TRUE(b.watch.expired());
}

}  // namespace
}  // namespace mhd

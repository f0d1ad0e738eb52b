#pragma once
// A triangle mesh with its Bullet BVH (btBvhTriangleMeshShape, quantized AABBs).
// The BVH is built once per mesh in the mesh's own frame; moving the object moves
// only its pose, never the tree. btScalar is double (Debian's -float64 Bullet).

#include "geometry/triangle_mesh.h"

#include <btBulletCollisionCommon.h>

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace mhd {

class MeshBvh {
 public:
  /// Builds the BVH. Precondition: mesh has at least one triangle, all indices valid.
  explicit MeshBvh(std::shared_ptr<const TriangleMesh> mesh);

  /// Adopts a BVH produced by serialize_bvh() for the same mesh (the BVH cache).
  /// Returns nullptr if the buffer is not a valid serialized BVH for this mesh.
  static std::unique_ptr<MeshBvh> from_serialized(std::shared_ptr<const TriangleMesh> mesh,
                                                  std::span<const std::byte> serialized);

  ~MeshBvh();
  MeshBvh(const MeshBvh&) = delete;
  MeshBvh& operator=(const MeshBvh&) = delete;

  /// The BVH in Bullet's own in-place format (the cache stores it verbatim).
  [[nodiscard]] std::vector<std::byte> serialize_bvh() const;

  [[nodiscard]] const TriangleMesh& mesh() const { return *mesh_; }
  [[nodiscard]] const std::shared_ptr<const TriangleMesh>& mesh_ptr() const { return mesh_; }
  [[nodiscard]] const Eigen::AlignedBox3d& bounds() const { return bounds_; }
  [[nodiscard]] const btBvhTriangleMeshShape& shape() const { return *shape_; }

  /// Calls f(triangle_index) for every triangle whose (conservative) BVH box
  /// overlaps box_O. Never misses a triangle that overlaps the box; may report extra.
  template <class F>
  void for_each_triangle_overlapping(const Eigen::AlignedBox3d& box_O, F&& f) const {
    struct Callback final : btNodeOverlapCallback {
      F& fn;
      explicit Callback(F& g) : fn(g) {}
      void processNode(int /*subPart*/, int triangle_index) override {
        fn(static_cast<std::uint32_t>(triangle_index));
      }
    } callback(f);
    query(box_O, callback);
  }

 private:
  MeshBvh() = default;
  void make_interface();
  void query(const Eigen::AlignedBox3d& box_O, btNodeOverlapCallback& callback) const;

  std::shared_ptr<const TriangleMesh> mesh_;
  Eigen::AlignedBox3d bounds_;
  // Bullet sees the mesh scaled by this (see make_interface); queries are scaled alike.
  double bvh_scale_ = 1.0;
  std::unique_ptr<btTriangleIndexVertexArray> interface_;
  std::unique_ptr<btBvhTriangleMeshShape> shape_;
  // Backing store of a deserialized BVH (Bullet's in-place format points into it).
  std::unique_ptr<std::byte[], void (*)(std::byte*)> serialized_storage_{nullptr, nullptr};
  // The tree our own code queries. A deserialized tree is a plain btQuantizedBvh
  // (Bullet's deSerializeInPlace builds that), so it is never used as btOptimizedBvh here.
  const btQuantizedBvh* tree_ = nullptr;
  btQuantizedBvh* adopted_tree_ = nullptr;
};

}  // namespace mhd

#pragma once
// Internal to mhd_viewer: Eigen <-> OSG. OSG's matrices are row-major with row vectors
// (p' = p * M), so an Eigen column-vector matrix goes in transposed.

#include "geometry/pose.h"

#include <Eigen/Core>
#include <osg/Matrixd>
#include <osg/Vec3>
#include <osg/ref_ptr>

#include <utility>

namespace mhd::viewer {

template <class T, class... Args>
osg::ref_ptr<T> make_ref(Args&&... args) {
  return osg::ref_ptr<T>(new T(std::forward<Args>(args)...));
}

inline osg::Vec3 to_osg(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

inline osg::Vec3 to_osg(const Eigen::Vector3f& v) { return {v.x(), v.y(), v.z()}; }

inline osg::Matrixd to_osg(const Eigen::Matrix4d& m) {
  osg::Matrixd out;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) out(c, r) = m(r, c);
  }
  return out;
}

inline osg::Matrixd to_osg(const Pose& X) { return to_osg(X.matrix()); }

}  // namespace mhd::viewer

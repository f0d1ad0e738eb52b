#pragma once
// Haptic textures: a height field carved into a surface, and a friction map, in the
// surface's texture coordinates (docs/textures.md). A texture is immutable once built and
// sampled at the haptic rate: sample() allocates nothing and takes no lock.

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace mhd {

enum class TextureKind {
  Grating,    ///< sinusoidal grating: one spatial period along one direction
  Noise,      ///< band-limited noise: a sum of sinusoids with seeded directions and phases
  HeightMap,  ///< a greyscale image, white high, tiled over the surface
};

/// Planar projection of the object's frame onto texture coordinates (u, v) in metres:
/// Xy takes u = x_O, v = y_O (projection along z_O); Yz u = y_O, v = z_O; Zx u = z_O, v = x_O.
enum class TextureProjection { Xy, Yz, Zx };

/// What a scene file says about a texture, SI units.
struct HapticTextureSpec {
  TextureKind kind = TextureKind::Grating;
  /// The textured surface lies between the real surface and depth_m below it: peaks touch
  /// the real surface, valleys are depth_m deep (exactly so for gratings and full-range images).
  double depth_m = 0.0;
  /// Grating: the spatial period. Noise: the shortest wavelength.
  double period_m = 1e-3;
  /// Noise: the longest wavelength (>= period_m).
  double max_period_m = 4e-3;
  /// Grating: the direction across the ridges in (u, v); need not be unit, must not be zero.
  Eigen::Vector2d direction_uv = Eigen::Vector2d::UnitX();
  /// Noise: seeds its sinusoids; one seed always gives the same surface.
  std::uint64_t seed = 1;
  /// Height map: the greyscale PNG (absolute path) and the size one copy of it covers in (u, v).
  std::filesystem::path image_file;
  Eigen::Vector2d image_size_m = Eigen::Vector2d::Constant(0.01);
  TextureProjection projection = TextureProjection::Xy;
  /// Friction map: friction coefficients are scaled by 1 + c (2 r - 1), where r in [0, 1] is
  /// the relief (1 on peaks, 0 in valleys); c in [0, 1], 0 for no friction map.
  double friction_contrast = 0.0;
};

/// A greyscale image, row 0 at v = 0 (the image's top row), values in [0, 1].
struct GreyImage {
  int width = 0;
  int height = 0;
  std::vector<double> grey;  ///< width * height, row by row
};

/// The texture at one point of the surface.
struct TextureSample {
  /// Height of the textured surface over the real one: in [-depth_m, 0].
  double height_m = 0.0;
  /// d height / d(u, v): the textured surface's slope, dimensionless.
  Eigen::Vector2d gradient_uv = Eigen::Vector2d::Zero();
  /// Factor on the material's friction coefficients, in [1 - c, 1 + c].
  double friction_scale = 1.0;
};

/// Most sinusoids in a noise texture.
inline constexpr int kNoiseComponents = 24;

class HapticTexture {
 public:
  /// A grating or noise texture. Precondition: spec.kind is not HeightMap and its values are
  /// those the scene reader accepts (positive periods, non-zero direction).
  [[nodiscard]] static HapticTexture procedural(const HapticTextureSpec& spec);
  /// A height-map texture over `image`. Precondition: the image is at least 1x1 with
  /// width * height values, and spec.image_size_m is positive.
  [[nodiscard]] static HapticTexture height_map(const HapticTextureSpec& spec, GreyImage image);

  /// The texture at (u, v) in metres. Defined everywhere (height maps tile, procedural
  /// textures are periodic or unbounded); allocation-free.
  [[nodiscard]] TextureSample sample(const Eigen::Vector2d& uv_m) const;

  /// (u, v) of a point in the object's frame under this texture's projection.
  [[nodiscard]] Eigen::Vector2d uv_of(const Eigen::Vector3d& p_O) const;
  /// The object-frame directions of u and v.
  [[nodiscard]] Eigen::Vector3d u_axis_O() const;
  [[nodiscard]] Eigen::Vector3d v_axis_O() const;

  [[nodiscard]] const HapticTextureSpec& spec() const { return spec_; }

 private:
  explicit HapticTexture(const HapticTextureSpec& spec) : spec_(spec) {}

  /// Relief r in [0, 1] (1 on peaks) and its gradient in (u, v), per metre.
  void relief(const Eigen::Vector2d& uv_m, double& r, Eigen::Vector2d& dr_duv) const;

  struct Wave {
    Eigen::Vector2d wavenumber_rad_per_m = Eigen::Vector2d::Zero();
    double phase_rad = 0.0;
  };
  HapticTextureSpec spec_;
  std::array<Wave, kNoiseComponents> waves_{};
  int wave_count_ = 0;
  GreyImage image_;
  std::vector<Eigen::Vector2d> image_slope_per_m_;  ///< d grey / d(u, v) at each texel centre
};

}  // namespace mhd

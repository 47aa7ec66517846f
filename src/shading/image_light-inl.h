// An image light's two queries over lanes (image_light.h): the irradiance E/π about a normal from
// the nine harmonics, and the prefiltered radiance towards a direction, read from the octahedral
// levels by per-lane roughness, with the split sum's (A, B). IEEE-exact operations only
// (lane_math-inl.h), so that one lane gives the bits of any width on any target.
// Included once per target (Highway's -inl.h convention).

#if defined(ILLUM_SHADING_IMAGE_LIGHT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ILLUM_SHADING_IMAGE_LIGHT_INL_H_
#undef ILLUM_SHADING_IMAGE_LIGHT_INL_H_
#else
#define ILLUM_SHADING_IMAGE_LIGHT_INL_H_
#endif

#include "math/gather_pairs-inl.h"
#include "shading/image_light.h"
#include "shading/lane_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {

template <class D, class V = hn::VFromD<D>>
HWY_INLINE Vec3L<V> Rotated(D d, const Mat3& m, const Vec3L<V>& v) {
  return {hn::Set(d, m[0][0]) * v.x + hn::Set(d, m[1][0]) * v.y + hn::Set(d, m[2][0]) * v.z,
          hn::Set(d, m[0][1]) * v.x + hn::Set(d, m[1][1]) * v.y + hn::Set(d, m[2][1]) * v.z,
          hn::Set(d, m[0][2]) * v.x + hn::Set(d, m[1][2]) * v.y + hn::Set(d, m[2][2]) * v.z};
}

// E/π about unit n (in the map's space): Σ c_lm·Y_lm(n), below zero taken as zero (nine terms can
// ring there opposite a bright sun).
template <class D, class V = hn::VFromD<D>>
HWY_INLINE Vec3L<V> IrradianceOverPi(D d, const ImageLight& light, const Vec3L<V>& n) {
  const std::array<Vec3, 9>& c = light.irradianceSh();
  const V x = n.x, y = n.y, z = n.z;
  const V basis[9] = {hn::Set(d, Real(0.282095)),
                      hn::Set(d, Real(0.488603)) * y,
                      hn::Set(d, Real(0.488603)) * z,
                      hn::Set(d, Real(0.488603)) * x,
                      hn::Set(d, Real(1.092548)) * (x * y),
                      hn::Set(d, Real(1.092548)) * (y * z),
                      hn::Set(d, Real(0.315392)) * (hn::Set(d, Real(3)) * (z * z) - hn::Set(d, Real(1))),
                      hn::Set(d, Real(1.092548)) * (x * z),
                      hn::Set(d, Real(0.546274)) * (x * x - y * y)};
  Vec3L<V> e = Broadcast(d, Vec3(0));
  for (std::size_t k = 0; k < 9; ++k) e = e + basis[k] * Broadcast(d, c[k]);
  return {hn::ZeroIfNegative(e.x), hn::ZeroIfNegative(e.y), hn::ZeroIfNegative(e.z)};
}

// Where direction d (any length but 0) lies on the octahedral square, u and v in [0, 1]: the
// octahedron |x| + |y| + |z| = 1 with +Y at the centre, the lower half folded over the corners.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE void OctahedralUv(D d, const Vec3L<V>& dir, V& u, V& v) {
  const V one = hn::Set(d, Real(1)), half = hn::Set(d, Real(0.5));
  const V s = hn::Abs(dir.x) + hn::Abs(dir.y) + hn::Abs(dir.z);
  const V safe = hn::IfThenElse(s > hn::Zero(d), s, one);
  const V px = dir.x / safe, pz = dir.z / safe;
  const V sx = hn::IfThenElse(px < hn::Zero(d), hn::Neg(one), one), sz = hn::IfThenElse(pz < hn::Zero(d), hn::Neg(one), one);
  const auto below = dir.y < hn::Zero(d);
  const V fx = hn::IfThenElse(below, (one - hn::Abs(pz)) * sx, px);
  const V fz = hn::IfThenElse(below, (one - hn::Abs(px)) * sz, pz);
  u = fx * half + half;
  v = fz * half + half;
}

// One level's bilinear texel at (u, v), each lane at its own level (size and offset in the atlas),
// edges clamped. Most surfaces have one roughness, so one level: its size and offset are then
// read once, not gathered; and away from the level's edges (most lanes, most often) a row's two
// texels are neighbours in memory, read as pairs (gather_pairs-inl.h).
template <class D, class V = hn::VFromD<D>>
HWY_INLINE Vec3L<V> OctahedralTexel(D d, const ImageLight& light, hn::VFromD<hn::RebindToSigned<D>> level, V u, V v) {
  const hn::RebindToSigned<D> di;
  using VI = hn::VFromD<decltype(di)>;
  const int first = int(hn::GetLane(level));
  const bool oneLevel = hn::AllTrue(di, level == hn::Set(di, first));
  const VI size = oneLevel ? hn::Set(di, light.levelSizes()[first]) : hn::GatherIndex(di, light.levelSizes(), level);
  const VI offset =
      oneLevel ? hn::Set(di, light.levelOffsets()[first]) : hn::GatherIndex(di, light.levelOffsets(), level);
  const V sizeF = hn::ConvertTo(d, size), half = hn::Set(d, Real(0.5));
  // Clamped in floats first, so that no lane's index can leave its level (a NaN direction too).
  const V x = hn::Min(hn::Max(u * sizeF - half, hn::Set(d, Real(-1))), sizeF);
  const V y = hn::Min(hn::Max(v * sizeF - half, hn::Set(d, Real(-1))), sizeF);
  const V x0f = hn::Floor(x), y0f = hn::Floor(y);
  const V fx = x - x0f, fy = y - y0f;
  const VI last = size - hn::Set(di, 1), zero = hn::Zero(di), oneI = hn::Set(di, 1);
  const VI x0i = hn::ConvertTo(di, x0f), y0i = hn::ConvertTo(di, y0f);
  const VI xa = hn::Min(hn::Max(x0i, zero), last), xb = hn::Min(hn::Max(x0i + oneI, zero), last);
  const VI ya = hn::Min(hn::Max(y0i, zero), last), yb = hn::Min(hn::Max(y0i + oneI, zero), last);
  const VI rowA = offset + ya * size, rowB = offset + yb * size;
  const VI i00 = rowA + xa, i10 = rowA + xb, i01 = rowB + xa, i11 = rowB + xb;
  const bool pairs = hn::AllTrue(di, xb == xa + oneI);
  const V one = hn::Set(d, Real(1));
  const V w00 = (one - fx) * (one - fy), w10 = fx * (one - fy), w01 = (one - fx) * fy, w11 = fx * fy;
  Vec3L<V> out;
  V* channels[3] = {&out.x, &out.y, &out.z};
  for (int c = 0; c < 3; ++c) {
    const Real* plane = light.atlas(c);
    V t00, t10, t01, t11;
    if (pairs) {
      GatherPairs(d, plane, i00, t00, t10);
      GatherPairs(d, plane, i01, t01, t11);
    } else {
      t00 = hn::GatherIndex(d, plane, i00), t10 = hn::GatherIndex(d, plane, i10);
      t01 = hn::GatherIndex(d, plane, i01), t11 = hn::GatherIndex(d, plane, i11);
    }
    *channels[c] = w00 * t00 + w10 * t10 + w01 * t01 + w11 * t11;
  }
  return out;
}

// The map prefiltered by the GGX lobe of each lane's perceptual roughness (in [0, 1]), towards dir:
// the two levels about the roughness, blended.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE Vec3L<V> Prefiltered(D d, const ImageLight& light, const Vec3L<V>& dir, V roughness) {
  const hn::RebindToSigned<D> di;
  V u, v;
  OctahedralUv(d, dir, u, v);
  const V top = hn::Set(d, Real(ImageLight::kLevels - 1));
  const V level = hn::Min(hn::Max(roughness, hn::Zero(d)), hn::Set(d, Real(1))) * top;
  const V l0f = hn::Min(hn::Floor(level), top);
  const V f = level - l0f;
  const auto l0 = hn::Min(hn::Max(hn::ConvertTo(di, l0f), hn::Zero(di)), hn::Set(di, ImageLight::kLevels - 1));
  const auto l1 = hn::Min(l0 + hn::Set(di, 1), hn::Set(di, ImageLight::kLevels - 1));
  const Vec3L<V> a = OctahedralTexel(d, light, l0, u, v);
  if (hn::AllTrue(d, f == hn::Zero(d))) return a;
  const Vec3L<V> b = OctahedralTexel(d, light, l1, u, v);
  return (hn::Set(d, Real(1)) - f) * a + f * b;
}

// The split sum's (A, B) at each lane's N·V and perceptual roughness, bilinear in the table.
template <class D, class V = hn::VFromD<D>>
HWY_INLINE void SplitSum(D d, V NoV, V roughness, V& A, V& B) {
  const hn::RebindToSigned<D> di;
  constexpr int n = kSplitSumTableSize;
  const V zero = hn::Zero(d), one = hn::Set(d, Real(1)), top = hn::Set(d, Real(n - 1));
  const V x = hn::Min(hn::Max(NoV, zero), one) * top, y = hn::Min(hn::Max(roughness, zero), one) * top;
  const V x0f = hn::Min(hn::Floor(x), hn::Set(d, Real(n - 2))), y0f = hn::Min(hn::Floor(y), hn::Set(d, Real(n - 2)));
  const V fx = x - x0f, fy = y - y0f;
  // Clamped as integers too, so that no lane reads outside the table whatever it holds (a NaN).
  const auto last = hn::Set(di, n - 2), none = hn::Zero(di);
  const auto x0i = hn::Min(hn::Max(hn::ConvertTo(di, x0f), none), last), y0i = hn::Min(hn::Max(hn::ConvertTo(di, y0f), none), last);
  const auto i00 = y0i * hn::Set(di, n) + x0i;
  const auto i01 = i00 + hn::Set(di, n);
  const V w00 = (one - fx) * (one - fy), w10 = fx * (one - fy), w01 = (one - fx) * fy, w11 = fx * fy;
  // Entries x0 and x0 + 1 of rows y0 and y0 + 1 (x0 stops a column short of the last). With one
  // roughness in every lane (a surface without a roughness map) the two rows are the same for
  // every lane, read from registers.
  static_assert(n == kShortRow);
  const int row = int(hn::GetLane(y0i));
  const bool oneRow = hn::AllTrue(di, y0i == hn::Set(di, row));
  const auto read = [&](const Real* table) {
    V t00, t10, t01, t11;
    if (oneRow) {
      ShortRowPairs(d, table + row * n, x0i, t00, t10);
      ShortRowPairs(d, table + (row + 1) * n, x0i, t01, t11);
    } else {
      GatherPairs(d, table, i00, t00, t10);
      GatherPairs(d, table, i01, t01, t11);
    }
    return w00 * t00 + w10 * t10 + w01 * t01 + w11 * t11;
  };
  A = read(splitSumTable(0));
  B = read(splitSumTable(1));
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // ILLUM_SHADING_IMAGE_LIGHT_INL_H_

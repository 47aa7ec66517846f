// shadePoints, compiled once per SIMD target (Highway's foreach_target) and dispatched at run time,
// and the one-point entry points of the equation (lighting.h, brdf.h), which run the same lines
// on one lane.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shading/shade_points.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include "math/unorm8-inl.h"
#include "math/iota-inl.h"
#include "shading/gl_lighting-inl.h"
#include "shading/shade_points.h"
#include "shading/prepared_light.h"

#include <span>
#include <vector>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {

// The clamped colour at each lane of `s` (its toViewer filled in here), with each lane's own
// colour for GL_COLOR_MATERIAL when `color` is given (four arrays read at the lanes), and the
// ambient term scaled by each lane's open share when `open` is given (ambient occlusion).
// glTF's maps' values read at the lanes (SurfacePoints' metallic, roughness and emission), from `i` on.
template <class V>
struct MapLanes {
  V metallic, roughness;
  Vec3L<V> emission;
  MappedL<V> mapped;
};
template <class D, class V = hn::VFromD<D>>
HWY_INLINE void LoadMaps(D d, const SurfacePoints& p, std::size_t i, MapLanes<V>& m) {
  if (p.metallic) {
    m.metallic = hn::LoadU(d, p.metallic + i), m.roughness = hn::LoadU(d, p.roughness + i);
    m.mapped.metallic = &m.metallic, m.mapped.roughness = &m.roughness;
  }
  if (p.emission[0]) {
    m.emission = {hn::LoadU(d, p.emission[0] + i), hn::LoadU(d, p.emission[1] + i), hn::LoadU(d, p.emission[2] + i)};
    m.mapped.emission = &m.emission;
  }
}

// (`physical` is physicalFor(setup.material, setup.model): asked for once per batch or owner, not
// once a vector, where deriving it from a GL material had cost a twelfth of a frame.)
// The lights are setup.lights, or the same prepared (PreparedLight).
template <class D, class L, class V = hn::VFromD<D>>
HWY_INLINE void LitColor(D d, const ShadeSetup& setup, std::span<const L> lights, const PhysicalMaterial& physical,
                         SurfaceL<V>& s, const Real* const* color, const Real* open, V& r, V& g, V& b, V& a,
                         const MappedL<V>& mapped = {}) {
  s.toViewer = ToViewer(d, s.P, viewerIsLocal(setup.lightModel));
  MaterialColorsL<V> colors = UniformColors(d, setup.material, physical, setup.model);
  if (color) {
    const Vec3L<V> c{hn::LoadU(d, color[0]), hn::LoadU(d, color[1]), hn::LoadU(d, color[2])};
    colors = {c, c, hn::LoadU(d, color[3])};
  }
  TermsL<V> terms =
      ShadeEquation(d, lights, setup.lightModel, setup.material, physical, colors, setup.model, s, mapped);
  if (open) terms.ambient = hn::LoadU(d, open) * terms.ambient;
  ClampedColor(d, terms, colors.alpha, setup.lightModel.toneMap, r, g, b, a);
}

// Points [first, first + lanes) of `p`, read from and written to arrays offset by `first`.
template <class D>
HWY_INLINE void ShadeLanes(D d, const ShadeSetup& setup, std::span<const PreparedLight> lights,
                           const PhysicalMaterial& physical, const Real* const position[3],
                           const Real* const normal[3], const Real* const color[4], const Real* open,
                           Real* const out[4], const MappedL<hn::VFromD<D>>& mapped = {}) {
  using V = hn::VFromD<D>;
  SurfaceL<V> s;
  s.P = {hn::LoadU(d, position[0]), hn::LoadU(d, position[1]), hn::LoadU(d, position[2])};
  s.N = {hn::LoadU(d, normal[0]), hn::LoadU(d, normal[1]), hn::LoadU(d, normal[2])};
  V r, g, b, a;
  LitColor(d, setup, lights, physical, s, color[0] ? color : nullptr, open, r, g, b, a, mapped);
  hn::StoreU(r, d, out[0]);
  hn::StoreU(g, d, out[1]);
  hn::StoreU(b, d, out[2]);
  hn::StoreU(a, d, out[3]);
}

void ShadePoints(const ShadeSetup& setup, const SurfacePoints& p, Real* const out[4]) {
  const hn::ScalableTag<Real> d;
  const std::size_t lanes = hn::Lanes(d);
  const bool colored = p.color[0] != nullptr;
  const PhysicalMaterial physical = physicalFor(setup.material, setup.model);
  const std::vector<PreparedLight> prepared(setup.lights.begin(), setup.lights.end());
  const std::span<const PreparedLight> lights(prepared);
  std::size_t i = 0;
  for (; i + lanes <= p.count; i += lanes) {
    const Real* position[3] = {p.position[0] + i, p.position[1] + i, p.position[2] + i};
    const Real* normal[3] = {p.normal[0] + i, p.normal[1] + i, p.normal[2] + i};
    const Real* color[4] = {};
    if (colored) color[0] = p.color[0] + i, color[1] = p.color[1] + i, color[2] = p.color[2] + i, color[3] = p.color[3] + i;
    Real* const dst[4] = {out[0] + i, out[1] + i, out[2] + i, out[3] + i};
    MapLanes<hn::VFromD<decltype(d)>> maps;
    LoadMaps(d, p, i, maps);
    ShadeLanes(d, setup, lights, physical, position, normal, color, p.ambientOpen ? p.ambientOpen + i : nullptr, dst,
               maps.mapped);
  }
  if (i == p.count) return;
  // The last few points: copied into full vectors, the spare lanes repeating the last point.
  constexpr std::size_t kMax = hn::MaxLanes(d);
  HWY_ALIGN Real in[16][kMax], result[4][kMax];
  const Real* const* sources[3] = {p.position, p.normal, p.color};
  const Real* extra[6] = {p.ambientOpen, p.metallic, p.roughness, p.emission[0], p.emission[1], p.emission[2]};
  for (std::size_t k = 0; k < lanes; ++k) {
    const std::size_t from = std::min(i + k, p.count - 1);
    for (int a = 0; a < 10; ++a) {
      const Real* src = sources[a < 3 ? 0 : a < 6 ? 1 : 2][a < 3 ? a : a < 6 ? a - 3 : a - 6];
      in[a][k] = src ? src[from] : Real(0);
    }
    for (int a = 0; a < 6; ++a) in[10 + a][k] = extra[a] ? extra[a][from] : Real(1);
  }
  SurfacePoints tail;  // the maps' values of the spare lanes, as LoadMaps reads them
  if (p.metallic) tail.metallic = in[11], tail.roughness = in[12];
  if (p.emission[0]) tail.emission[0] = in[13], tail.emission[1] = in[14], tail.emission[2] = in[15];
  MapLanes<hn::VFromD<decltype(d)>> maps;
  LoadMaps(d, tail, 0, maps);
  const Real* position[3] = {in[0], in[1], in[2]};
  const Real* normal[3] = {in[3], in[4], in[5]};
  const Real* color[4] = {};
  if (colored) color[0] = in[6], color[1] = in[7], color[2] = in[8], color[3] = in[9];
  Real* const dst[4] = {result[0], result[1], result[2], result[3]};
  ShadeLanes(d, setup, lights, physical, position, normal, color, p.ambientOpen ? in[10] : nullptr, dst, maps.mapped);
  for (std::size_t k = 0; i + k < p.count; ++k)
    for (int c = 0; c < 4; ++c) out[c][i + k] = result[c][k];
}

#if !ILLUM_USE_DOUBLE
// Each owner's physicalFor, asked for when the owner differs from the last one asked about (a
// tile's pixels come owner after owner).
class OwnerPhysical {
 public:
  explicit OwnerPhysical(std::span<const ShadeSetup> setups) : setups_(setups) {}
  const PhysicalMaterial& operator()(std::uint32_t owner) {
    if (owner != owner_) owner_ = owner, physical_ = physicalFor(setups_[owner].material, setups_[owner].model);
    return physical_;
  }

 private:
  std::span<const ShadeSetup> setups_;
  std::uint32_t owner_ = kNoOwner;
  PhysicalMaterial physical_;
};

// The lanes of vectors that an object's edge splits (some lanes empty or another owner's), gathered
// owner by owner into dense vectors before they are lit: lighting each such vector once per owner
// it holds would light the other lanes for nothing (a tenth of the work on small objects). The
// planes hold two vectors: a compressing store may write a whole vector past the lanes it keeps.
class EdgeLanes {
 public:
  using D = hn::ScalableTag<float>;
  using DU = hn::RebindToUnsigned<D>;
  static constexpr std::size_t kRoom = 2 * hn::MaxLanes(D());

  EdgeLanes(std::span<const ShadeSetup> setups, std::span<const std::uint8_t> colored, std::uint32_t* rgba,
            OwnerPhysical& physical)
      : setups_(setups), colored_(colored), rgba_(rgba), physical_(physical) {}

  // The lanes `mine` of pixels [i, i + lanes), all owner `o`'s. A whole vector of one owner's
  // lanes is lit as soon as it is gathered; the lanes past it wait for the next.
  void add(std::uint32_t o, hn::Mask<D> mine, std::size_t i, const Vec3L<hn::Vec<D>>& P, const Vec3L<hn::Vec<D>>& N,
           const SurfacePoints& p) {
    const D d;
    const DU du;
    if (count_ > 0 && owner_ != o) flush();
    owner_ = o;
    // (Compressed in a register and stored whole, which the planes have room for: a compressing
    // store to memory is slow on some CPUs.)
    const hn::Vec<D> planes[6] = {P.x, P.y, P.z, N.x, N.y, N.z};
    for (int c = 0; c < 6; ++c) hn::StoreU(hn::Compress(planes[c], mine), d, plane_[c] + count_);
    if (colored_[o])
      for (int c = 0; c < 4; ++c) hn::StoreU(hn::Compress(hn::LoadU(d, p.color[c] + i), mine), d, plane_[6 + c] + count_);
    hn::StoreU(hn::Compress(IotaFrom(du, std::uint32_t(i)), hn::RebindMask(du, mine)), du, pixel_ + count_);
    count_ += hn::CountTrue(d, mine);
    const std::size_t lanes = hn::Lanes(d);
    if (count_ < lanes) return;
    light(lanes);
    // The rest down to the planes' start.
    for (int c = 0; c < (colored_[o] ? 10 : 6); ++c) hn::Store(hn::Load(d, plane_[c] + lanes), d, plane_[c]);
    hn::Store(hn::Load(du, pixel_ + lanes), du, pixel_);
    count_ -= lanes;
  }

  void flush() {
    if (count_ == 0) return;
    light(count_);
    count_ = 0;
  }

 private:
  // Lights the first `n` lanes of the planes and writes them to their pixels.
  void light(std::size_t n) {
    const D d;
    const DU du;
    using V = hn::Vec<D>;
    SurfaceL<V> s;
    s.P = {hn::Load(d, plane_[0]), hn::Load(d, plane_[1]), hn::Load(d, plane_[2])};
    s.N = {hn::Load(d, plane_[3]), hn::Load(d, plane_[4]), hn::Load(d, plane_[5])};
    const Real* color[4] = {plane_[6], plane_[7], plane_[8], plane_[9]};
    V r, g, b, a;
    LitColor(d, setups_[owner_], setups_[owner_].lights, physical_(owner_), s, colored_[owner_] ? color : nullptr,
             nullptr, r, g, b, a);
    HWY_ALIGN std::uint32_t packed[hn::MaxLanes(du)];
    hn::Store(PackUnorm8(d, r, g, b, a), du, packed);
    for (std::size_t k = 0; k < n; ++k) rgba_[pixel_[k]] = packed[k];
  }

  std::span<const ShadeSetup> setups_;
  std::span<const std::uint8_t> colored_;
  std::uint32_t* rgba_;
  OwnerPhysical& physical_;
  // Position, normal, colour; lanes past count_ keep earlier points (finite values, never stored).
  HWY_ALIGN float plane_[10][kRoom] = {};
  HWY_ALIGN std::uint32_t pixel_[kRoom] = {};
  std::size_t count_ = 0;
  std::uint32_t owner_ = kNoOwner;
};
#endif

void ShadeOwnedPoints(std::span<const ShadeSetup> setups, std::span<const std::uint8_t> colored,
                      const SurfacePoints& p, const std::uint32_t* owner, std::uint32_t* rgba) {
#if !ILLUM_USE_DOUBLE  // float channels only
  const hn::ScalableTag<float> d;
  const hn::RebindToUnsigned<decltype(d)> du;
  using V = hn::VFromD<decltype(d)>;
  const std::size_t lanes = hn::Lanes(d);
  const auto none = hn::Set(du, kNoOwner);
  OwnerPhysical physical(setups);
  EdgeLanes edges(setups, colored, rgba, physical);
  for (std::size_t i = 0; i < p.count; i += lanes) {
    const auto owners = hn::LoadU(du, owner + i);
    auto todo = owners != none;
    if (hn::AllFalse(du, todo)) continue;
    SurfaceL<V> s;
    s.P = {hn::LoadU(d, p.position[0] + i), hn::LoadU(d, p.position[1] + i), hn::LoadU(d, p.position[2] + i)};
    s.N = {hn::LoadU(d, p.normal[0] + i), hn::LoadU(d, p.normal[1] + i), hn::LoadU(d, p.normal[2] + i)};
    const std::uint32_t first = owner[i + std::size_t(hn::FindFirstTrue(du, todo))];
    if (hn::AllTrue(du, owners == hn::Set(du, first))) {  // a whole vector of one owner: lit as it is
      const Real* color[4] = {p.color[0] + i, p.color[1] + i, p.color[2] + i, p.color[3] + i};
      V r, g, b, a;
      LitColor(d, setups[first], setups[first].lights, physical(first), s, colored[first] ? color : nullptr, nullptr, r,
               g, b, a);
      hn::StoreU(PackUnorm8(d, r, g, b, a), du, rgba + i);
      continue;
    }
    while (!hn::AllFalse(du, todo)) {
      const std::uint32_t o = owner[i + std::size_t(hn::FindFirstTrue(du, todo))];
      const auto mine = hn::And(todo, owners == hn::Set(du, o));
      edges.add(o, hn::RebindMask(d, mine), i, s.P, s.N, p);
      todo = hn::AndNot(mine, todo);
    }
  }
  edges.flush();
#else
  (void)setups, (void)colored, (void)p, (void)owner, (void)rgba;
#endif
}

const char* TargetName() { return hwy::TargetName(HWY_TARGET); }

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "shading/brdf.h"

namespace illum {

HWY_EXPORT(ShadePoints);
HWY_EXPORT(TargetName);
HWY_EXPORT(ShadeOwnedPoints);

void shadeOwnedPoints(std::span<const ShadeSetup> setups, std::span<const std::uint8_t> colored,
                      const SurfacePoints& points, const std::uint32_t* owner, std::uint32_t* rgba) {
  HWY_DYNAMIC_DISPATCH(ShadeOwnedPoints)(setups, colored, points, owner, rgba);
}

void shadePoints(const ShadeSetup& setup, const SurfacePoints& points, Real* const out[4]) {
  HWY_DYNAMIC_DISPATCH(ShadePoints)(setup, points, out);
}

const char* simdTargetName() { return HWY_DYNAMIC_DISPATCH(TargetName)(); }

// One point: the same templates on a single lane of the static target (which gives the same bits
// as every other target, see lane_math-inl.h).
namespace hn = hwy::HWY_NAMESPACE;
namespace one {
using D = hn::CappedTag<Real, 1>;
using V = hn::VFromD<D>;
constexpr D d;

V lane(Real x) { return hn::Set(d, x); }
HWY_NAMESPACE::Vec3L<V> lanes(const Vec3& v) { return HWY_NAMESPACE::Broadcast(d, v); }
HWY_NAMESPACE::SurfaceL<V> surface(const SurfaceGeometry& s) {
  return {lanes(s.position), lanes(s.normal), lanes(s.toViewer)};
}
HWY_NAMESPACE::MaterialColorsL<V> colors(const Material& m, LightingModel model) {
  return HWY_NAMESPACE::UniformColors(d, m, physicalFor(m, model), model);
}

}  // namespace one

void accumulateLight(LightingTerms& terms, const EyeLight& light, const Material& material, LightingModel model,
                     const SurfaceGeometry& surface, LightDetail* detail, Convention convention) {
  auto t = HWY_NAMESPACE::NoTerms(one::d);
  auto sums = HWY_NAMESPACE::NoLight(one::d);
  const auto physical = HWY_NAMESPACE::UniformPhysical(one::d, physicalFor(material, model));
  const auto colors = one::colors(material, model);
  if (detail) {
    *detail = LightDetail{};
    HWY_NAMESPACE::AccumulateLight<true>(one::d, t, sums, light, material, physical, colors, model, convention,
                                         one::surface(surface), detail);
  } else {
    HWY_NAMESPACE::AccumulateLight<false>(one::d, t, sums, light, material, physical, colors, model, convention,
                                          one::surface(surface), nullptr);
  }
  HWY_NAMESPACE::AddLightSums(one::d, t, sums, material, colors, model);
  terms.ambient += HWY_NAMESPACE::Lane0(t.ambient);
  terms.diffuse += HWY_NAMESPACE::Lane0(t.diffuse);
  terms.specular += HWY_NAMESPACE::Lane0(t.specular);
}

LightingTerms evaluateTerms(std::span<const EyeLight> lights, const LightModel& lightModel, const Material& material,
                            LightingModel model, const SurfaceGeometry& surface) {
  const auto t = HWY_NAMESPACE::ShadeEquation(one::d, lights, lightModel, material, physicalFor(material, model),
                                              one::colors(material, model),
                                              model, one::surface(surface));
  return {HWY_NAMESPACE::Lane0(t.emission), HWY_NAMESPACE::Lane0(t.ambient), HWY_NAMESPACE::Lane0(t.diffuse),
          HWY_NAMESPACE::Lane0(t.specular)};
}

Color4 clampedColor(const LightingTerms& terms, const Material& material, ToneMap toneMap) {
  const HWY_NAMESPACE::TermsL<one::V> t{one::lanes(terms.emission), one::lanes(terms.ambient),
                                        one::lanes(terms.diffuse), one::lanes(terms.specular)};
  one::V r, g, b, a;
  HWY_NAMESPACE::ClampedColor(one::d, t, one::lane(material.diffuse.a), toneMap, r, g, b, a);
  return {hn::GetLane(r), hn::GetLane(g), hn::GetLane(b), hn::GetLane(a)};
}

Vec3 viewerDirection(const Vec3& eyePosition, const LightModel& lightModel) {
  return HWY_NAMESPACE::Lane0(HWY_NAMESPACE::ToViewer(one::d, one::lanes(eyePosition), viewerIsLocal(lightModel)));
}

Real Fd_LambertCosine(Real NoL) { return hn::GetLane(HWY_NAMESPACE::Fd_LambertCosine(one::lane(NoL))); }
Real Fs_Phong(Real RoV, Real shininess) { return hn::GetLane(HWY_NAMESPACE::Fs_Phong(one::d, one::lane(RoV), shininess)); }
Real Fs_BlinnPhong(Real NoH, Real shininess) {
  return hn::GetLane(HWY_NAMESPACE::Fs_BlinnPhong(one::d, one::lane(NoH), shininess));
}
Real distanceAttenuation(const Vec3& k, Real d) {
  return hn::GetLane(HWY_NAMESPACE::DistanceAttenuation(one::d, k, one::lane(d)));
}
Real spotFactor(Real minusLoS, Real cosCutoff, Real exponent) {
  return hn::GetLane(HWY_NAMESPACE::SpotFactor(one::d, one::lane(minusLoS), cosCutoff, exponent));
}
LightSampleAt sampleLight(const EyeLight& light, const Vec3& P, const Vec3& N) {
  const auto s = HWY_NAMESPACE::SampleLight(one::d, light, one::lanes(P), one::lanes(N));
  return {HWY_NAMESPACE::Lane0(s.L), hn::GetLane(s.distance), hn::GetLane(s.attenuation), hn::GetLane(s.spot)};
}
Real Fd_Lambert() { return HWY_NAMESPACE::Fd_Lambert(); }
Real D_GGX(Real NoH, Real alpha) {
  return hn::GetLane(HWY_NAMESPACE::D_GGX(one::d, one::lane(NoH), one::lane(alpha)));
}
Real D_Beckmann(Real NoH, Real alpha) {
  return hn::GetLane(HWY_NAMESPACE::D_Beckmann(one::d, one::lane(NoH), one::lane(alpha)));
}
Real V_SmithGGXCorrelated(Real NoV, Real NoL, Real alpha) {
  return hn::GetLane(HWY_NAMESPACE::V_SmithGGXCorrelated(one::d, one::lane(NoV), one::lane(NoL), one::lane(alpha)));
}
Color3 F_Schlick(Real VoH, const Color3& f0) {
  return HWY_NAMESPACE::Lane0(HWY_NAMESPACE::F_Schlick(one::d, one::lane(VoH), one::lanes(f0)));
}
Real microfacetAlpha(Real roughness) { return HWY_NAMESPACE::MicrofacetAlpha(roughness); }

}  // namespace illum
#endif  // HWY_ONCE

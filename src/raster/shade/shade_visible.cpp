// shade_visible.h: the lanes' part compiled once per SIMD target (Highway's foreach_target) and
// dispatched at run time; the records gathered, lit and written back (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/shade/shade_visible.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "raster/coverage/interpolate-inl.h"
#include "shading/lane_math-inl.h"
#include "raster/shade/shade_visible.h"
#include "raster/shade/visible_lanes.h"

#include <algorithm>
#include <cstring>
#include <type_traits>

HWY_BEFORE_NAMESPACE();
namespace illum::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The values of the records whose pixels fill a vector, as each lane sees them: one record's,
// broadcast (OneRecord: a record with a vector or more of pixels), or, where small records share
// a vector, each lane its own record's, looked up by its index in the group (RecordGroup). Both
// give a lane the same bits from the same record.
template <class D, bool kSplit>
struct OneRecord {
  using V = hn::VFromD<D>;
  using DI = hn::Rebind<std::int32_t, D>;
  using VI = hn::VFromD<DI>;
  using T = std::conditional_t<kSplit, float, double>;
  D d;
  const ShownRecord& rec;
  // The first pixel's edge values (split: its multiple of 256, and the rest), and the steps.
  T high[3], low[3], A[3], B[3];
  int column0, row0;  // the first pixel in the tile

  OneRecord(D dr, const ShownRecord& r, const PixelRect& rect, std::uint32_t firstPixel) : d(dr), rec(r) {
    const TriangleSetup& t = *rec.setup;
    column0 = int(firstPixel % kTileSize), row0 = int(firstPixel / kTileSize);
    const int x0 = rect.minX + column0, y0 = rect.minY + row0;
    const std::int64_t half = kSubpixelOne / 2;
    for (int i = 0; i < 3; ++i) {
      const std::int64_t e = t.edge[i].at(std::int64_t(x0) * kSubpixelOne + half, std::int64_t(y0) * kSubpixelOne + half);
      const std::int64_t rest = kSplit ? (e & (kSubpixelOne - 1)) : 0;
      high[i] = T(e - rest), low[i] = T(rest);
      A[i] = T(std::int64_t(t.edge[i].a) * kSubpixelOne), B[i] = T(std::int64_t(t.edge[i].b) * kSubpixelOne);
    }
  }
  void next(VI) {}
  VI column() const { return hn::Set(DI(), column0); }
  VI row() const { return hn::Set(DI(), row0); }
  // Edge value i at the lanes' pixels dx, dy from the first one, as Real: with kSplit in float
  // lanes, a multiple of 256 plus the rest, else in double lanes, half a vector at a time.
  V edgeAt(int i, VI dx, VI dy) const {
#if !ILLUM_USE_DOUBLE
    if constexpr (kSplit) {
      const V offset = hn::ConvertTo(d, dx) * hn::Set(d, A[i]) + hn::ConvertTo(d, dy) * hn::Set(d, B[i]);
      return (hn::Set(d, high[i]) + offset) + hn::Set(d, low[i]);
    } else
#endif
    {
      const auto exact = [&](auto dd, auto x, auto y) {  // in double lanes
        return hn::Set(dd, high[i]) + (hn::PromoteTo(dd, x) * hn::Set(dd, A[i]) + hn::PromoteTo(dd, y) * hn::Set(dd, B[i]));
      };
#if HWY_TARGET == HWY_SCALAR || ILLUM_USE_DOUBLE
      const hn::Rebind<double, D> dd;
      if constexpr (sizeof(Real) == 8) return exact(dd, dx, dy);
      else return hn::DemoteTo(d, exact(dd, dx, dy));
#else
      const hn::Half<D> dh;
      const hn::Half<DI> dih;
      const hn::Rebind<double, decltype(dh)> dd;
      const auto lower = hn::DemoteTo(dh, exact(dd, hn::LowerHalf(dih, dx), hn::LowerHalf(dih, dy)));
      const auto upper = hn::DemoteTo(dh, exact(dd, hn::UpperHalf(dih, dx), hn::UpperHalf(dih, dy)));
      return hn::Combine(d, upper, lower);
#endif
    }
  }
  V invArea() const { return hn::Set(d, rec.setup->invArea); }
  V invW(int k) const { return hn::Set(d, rec.setup->invW[k]); }
  V vertex(int k, int value) const { return hn::Set(d, rec.vertex[k][value]); }
  V flat(int c) const { return hn::Set(d, rec.flat[c]); }
  V step(int axis, int i) const { return hn::Set(d, axis == 0 ? rec.stepX[i] : rec.stepY[i]); }
  Vec3L<V> dPdu() const { return Broadcast(d, rec.dPdu); }
  Vec3L<V> dPdv() const { return Broadcast(d, rec.dPdv); }
  auto negate() const { return hn::FirstN(d, rec.negate ? hn::Lanes(d) : 0); }
  void slots(std::uint32_t* out, hn::Mask<D>, std::size_t n) const { std::fill_n(out, n, rec.slot); }
};

#if HWY_TARGET != HWY_SCALAR && !ILLUM_USE_DOUBLE
// How many of a ShownRecord's values per vertex the layout names.
inline int ValuesUsed(const VisibleLayout& layout) {
  int n = 0;
  for (const auto [at, size] : {std::pair{layout.lit, 4}, {layout.position, 3}, {layout.normal, 3}, {layout.color, 4},
                                {layout.uv, 2}})
    if (at >= 0) n = std::max(n, at + size);
  return n;
}

// Up to a vector's lane count of small records, each value a row of the table, record by record.
template <class D>
struct RecordTable {
  static constexpr std::size_t kRecords = hn::MaxLanes(D());
  HWY_ALIGN float high[3][kRecords], low[3][kRecords], A[3][kRecords], B[3][kRecords];
  HWY_ALIGN float invArea[kRecords], invW[3][kRecords];
  HWY_ALIGN float vertex[3][ShownRecord::kValues][kRecords];
  HWY_ALIGN float flat[4][kRecords], step[2][3][kRecords], dPdu[3][kRecords], dPdv[3][kRecords];
  HWY_ALIGN std::int32_t column0[kRecords], row0[kRecords], negate[kRecords];
  HWY_ALIGN std::uint32_t slot[kRecords];

  // Record j's row entries, from the values OneRecord computes for it (kSplit).
  void set(std::size_t j, const VisibleLayout& layout, const OneRecord<D, true>& one) {
    const ShownRecord& r = one.rec;
    for (int i = 0; i < 3; ++i) {
      high[i][j] = one.high[i], low[i][j] = one.low[i], A[i][j] = one.A[i], B[i][j] = one.B[i];
      invW[i][j] = r.setup->invW[i];
      step[0][i][j] = r.stepX[i], step[1][i][j] = r.stepY[i];
      dPdu[i][j] = r.dPdu[i], dPdv[i][j] = r.dPdv[i];
    }
    invArea[j] = r.setup->invArea;
    const int values = ValuesUsed(layout);
    for (int k = 0; k < 3; ++k)
      for (int v = 0; v < values; ++v) vertex[k][v][j] = r.vertex[k][v];
    for (int c = 0; c < 4; ++c) flat[c][j] = r.flat[c];
    column0[j] = one.column0, row0[j] = one.row0, negate[j] = r.negate ? -1 : 0;
    slot[j] = r.slot;
  }
};

template <class D>
struct RecordGroup {
  using V = hn::VFromD<D>;
  using DI = hn::Rebind<std::int32_t, D>;
  using DU = hn::Rebind<std::uint32_t, D>;
  using VI = hn::VFromD<DI>;
  D d;
  const RecordTable<D>& table;
  // Each lane's record in the table, for float, signed and unsigned rows.
  decltype(hn::IndicesFromVec(D(), hn::Zero(DI()))) of;
  decltype(hn::IndicesFromVec(DI(), hn::Zero(DI()))) ofI;
  decltype(hn::IndicesFromVec(DU(), hn::Zero(DU()))) ofU;

  RecordGroup(D dr, const RecordTable<D>& t)
      : d(dr), table(t), of(hn::IndicesFromVec(d, hn::Zero(DI()))), ofI(hn::IndicesFromVec(DI(), hn::Zero(DI()))),
        ofU(hn::IndicesFromVec(DU(), hn::Zero(DU()))) {}

  // The lanes' records for the next vector: `which` holds each lane's index in the table.
  void next(VI which) {
    of = hn::IndicesFromVec(d, which), ofI = hn::IndicesFromVec(DI(), which);
    ofU = hn::IndicesFromVec(DU(), hn::BitCast(DU(), which));
  }
  V at(const float* row) const { return hn::TableLookupLanes(hn::Load(d, row), of); }
  VI column() const { return hn::TableLookupLanes(hn::Load(DI(), table.column0), ofI); }
  VI row() const { return hn::TableLookupLanes(hn::Load(DI(), table.row0), ofI); }
  V edgeAt(int i, VI dx, VI dy) const {
    const V offset = hn::ConvertTo(d, dx) * at(table.A[i]) + hn::ConvertTo(d, dy) * at(table.B[i]);
    return (at(table.high[i]) + offset) + at(table.low[i]);
  }
  V invArea() const { return at(table.invArea); }
  V invW(int k) const { return at(table.invW[k]); }
  V vertex(int k, int value) const { return at(table.vertex[k][value]); }
  V flat(int c) const { return at(table.flat[c]); }
  V step(int axis, int i) const { return at(table.step[axis][i]); }
  Vec3L<V> dPdu() const { return {at(table.dPdu[0]), at(table.dPdu[1]), at(table.dPdu[2])}; }
  Vec3L<V> dPdv() const { return {at(table.dPdv[0]), at(table.dPdv[1]), at(table.dPdv[2])}; }
  auto negate() const {
    const auto n = hn::TableLookupLanes(hn::Load(DI(), table.negate), ofI);
    return hn::RebindMask(d, hn::Ne(n, hn::Zero(DI())));
  }
  void slots(std::uint32_t* out, hn::Mask<D> shown, std::size_t) const {
    const auto s = hn::TableLookupLanes(hn::Load(DU(), table.slot), ofU);
    hn::StoreU(hn::Compress(s, hn::RebindMask(DU(), shown)), DU(), out);
  }
};
#endif

// Where each lane's pixel falls on the textures (UvLanes, visible_lanes.h): its uv at the pixel, and
// at the pixel moved one right and one up by the record's steps.
template <class R, class V>
HWY_INLINE UvLanes<V> UvAt(const VisibleLayout& layout, const R& rec, const V (&l)[3], const V (&invW)[3],
                           const V (&p)[3]) {
  const auto uvAt = [&](const V (&w)[3], V (&out)[2]) {
    for (int c = 0; c < 2; ++c)
      out[c] = Blend(w, rec.vertex(0, layout.uv + c), rec.vertex(1, layout.uv + c), rec.vertex(2, layout.uv + c));
  };
  UvLanes<V> u;
  uvAt(p, u.uv);
  for (int axis = 0; axis < 2; ++axis) {
    V w[3], moved[2];
    PerspectiveWeights(l[0] + rec.step(axis, 0), l[1] + rec.step(axis, 1), l[2] + rec.step(axis, 2), invW[0],
                       invW[1], invW[2], w);
    uvAt(w, moved);
    V(&delta)[2] = axis == 0 ? u.dx : u.dy;
    for (int c = 0; c < 2; ++c) delta[c] = moved[c] - u.uv[c];
  }
  return u;
}

// gatherShown's lanes, `count` pixels (tile indices) in the widest Real lanes, appended to the
// batch: each lane's record as `rec` gives it (OneRecord, RecordGroup), its record's index in
// the group from `which` (none for one record). The edge values are exact integers, the record's
// first pixel's plus dx·256a + dy·256b.
template <class R>
HWY_INLINE void GatherLanes(const VisibleLayout& layout, R& rec, const std::uint32_t* pixels, const std::int32_t* which,
                            std::size_t count, VisibleBatch& b) {
  const hn::ScalableTag<Real> dr;
  const hn::Rebind<std::uint32_t, decltype(dr)> du;
  const hn::Rebind<std::int32_t, decltype(dr)> di;
  using VR = hn::VFromD<decltype(dr)>;
  using VI = hn::VFromD<decltype(di)>;
  const VR one = hn::Set(dr, Real(1));
  const auto blend = [&](const VR (&p)[3], int value) {
    return Blend(p, rec.vertex(0, value), rec.vertex(1, value), rec.vertex(2, value));
  };
  const std::size_t lanes = hn::Lanes(dr);
  for (std::size_t i = 0; i < count; i += lanes) {
    if (which) rec.next(hn::LoadU(di, which + i));
    const auto shown = hn::FirstN(dr, count - i);
    const auto index = hn::LoadU(du, pixels + i);  // (the list has room for a vector past its end)
    const auto indexI = hn::BitCast(di, index);
    static_assert(kTileSize == 64);
    const VI dx = hn::And(indexI, hn::Set(di, kTileSize - 1)) - rec.column(), dy = hn::ShiftRight<6>(indexI) - rec.row();
    // The centres' barycentrics, as the rasterizer computes them.
    const VR invArea = rec.invArea(), invW[3] = {rec.invW(0), rec.invW(1), rec.invW(2)};
    VR l[3];
    for (int e = 0; e < 3; ++e) l[e] = rec.edgeAt(e, dx, dy) * invArea;
    VR p[3];
    PerspectiveWeights(l[0], l[1], l[2], invW[0], invW[1], invW[2], p);
    VR color[4];
    const std::size_t at = b.count;
    // (Compressed in a register and stored whole: the batch has room for a vector past its end,
    // and a compressing store to memory is slow on some CPUs. A whole vector needs no compressing.)
    const bool whole = count - i >= lanes;
    const auto keep = [&](VR v, Real* plane) { hn::StoreU(whole ? v : hn::Compress(v, shown), dr, plane + at); };
    if (layout.shading == Shading::Flat) {
      for (int c = 0; c < 4; ++c) color[c] = rec.flat(c);
    } else if (layout.shading == Shading::Gouraud) {
      for (int c = 0; c < 4; ++c) color[c] = blend(p, layout.lit + c);
    } else {
      VR n[3], front[3];
      for (int c = 0; c < 3; ++c) {
        keep(blend(p, layout.position + c), b.position[c]);
        n[c] = blend(p, layout.normal + c);
      }
      UnitNormal(n, hn::FirstN(dr, 0), front);
      // Two-sided lighting's back faces take the normal's opposite: now, or once a normal map has
      // bent it (SampleBatchTexels), which then needs the triangle's tangent frame.
      const auto negate = rec.negate();
      const bool bent = layout.maps && layout.maps->normal;
      for (int c = 0; c < 3; ++c) keep(bent ? front[c] : hn::IfThenElse(negate, hn::Neg(front[c]), front[c]), b.normal[c]);
      if (bent) {
        keep(hn::IfThenElseZero(negate, one), b.flip);
        const Vec3L<VR> dPdu = rec.dPdu(), dPdv = rec.dPdv();
        const VR u[3] = {dPdu.x, dPdu.y, dPdu.z}, v[3] = {dPdv.x, dPdv.y, dPdv.z};
        for (int c = 0; c < 3; ++c) keep(u[c], b.dPdu[c]), keep(v[c], b.dPdv[c]);
      }
      for (int c = 0; c < 4; ++c) color[c] = layout.color >= 0 ? blend(p, layout.color + c) : one;
    }
    // Where the textures are read, sampled for the whole batch afterwards (SampleBatchTexels).
    if (layout.uv >= 0) {
      const UvLanes<VR> uv = UvAt(layout, rec, l, invW, p);
      for (int c = 0; c < 2; ++c) keep(uv.uv[c], b.uv[c]), keep(uv.dx[c], b.uvDx[c]), keep(uv.dy[c], b.uvDy[c]);
    }
    // A base colour texture tints the material's (or the vertex's) colour: that colour now.
    if (layout.texture && layout.baseTexel && layout.color < 0)
      for (int c = 0; c < 4; ++c) color[c] = hn::Set(dr, layout.baseColor[c]);
    for (int c = 0; c < 4; ++c) keep(color[c], b.color[c]);
    hn::StoreU(index, du, b.pixel + at);
    const std::size_t n = std::min(lanes, count - i);
    rec.slots(b.slot + at, shown, n);
    b.count += n;
  }
}

// Whether every edge value over the record's pixels in the tile, and the parts it is summed from,
// stay below 2^31 (GatherLanes may then take them in float lanes).
bool SplitFits(const ShownRecord& rec, const PixelRect& rect) {
#if HWY_TARGET != HWY_SCALAR && !ILLUM_USE_DOUBLE
  const TriangleSetup& t = *rec.setup;
  // A float-exact triangle's (most of a dense mesh's) every edge value and step across its
  // bounds is at most 2^24 (setup.h), far inside.
  if (t.floatExact) return true;
  const int minX = std::max(t.minX, rect.minX), maxX = std::min(t.maxX, rect.maxX);
  const int minY = std::max(t.minY, rect.minY), maxY = std::min(t.maxY, rect.maxY);
  const std::int64_t half = kSubpixelOne / 2, limit = (std::int64_t(1) << 31) - 4 * kSubpixelOne;
  for (const EdgeFunction& e : t.edge) {
    const std::int64_t a = std::abs(std::int64_t(e.a)), bb = std::abs(std::int64_t(e.b));
    const std::int64_t first = e.at(std::int64_t(minX) * kSubpixelOne + half, std::int64_t(minY) * kSubpixelOne + half);
    if (std::abs(first) + 2 * (a * (maxX - minX) + bb * (maxY - minY)) * kSubpixelOne > limit) return false;
  }
  return true;
#else
  (void)rec, (void)rect;
  return false;
#endif
}

void GatherShown(const VisibleLayout& layout, const ShownRecord& rec, const PixelRect& rect, const std::uint32_t* pixels,
                 std::size_t count, VisibleBatch& b) {
  if (count == 0) return;
  const hn::ScalableTag<Real> dr;
#if HWY_TARGET != HWY_SCALAR && !ILLUM_USE_DOUBLE
  if (SplitFits(rec, rect)) {
    OneRecord<decltype(dr), true> one(dr, rec, rect, pixels[0]);
    return GatherLanes(layout, one, pixels, nullptr, count, b);
  }
#endif
  OneRecord<decltype(dr), false> one(dr, rec, rect, pixels[0]);
  GatherLanes(layout, one, pixels, nullptr, count, b);
}

// The small records' pixels, up to a vector's lane count of records sharing the vectors (those
// whose edge values fit float lanes; any other one by one).
void GatherShownGroup(const VisibleLayout& layout, const PendingRecords& group, const PixelRect& rect,
                      VisibleBatch& b) {
#if HWY_TARGET != HWY_SCALAR && !ILLUM_USE_DOUBLE
  const hn::ScalableTag<Real> dr;
  RecordTable<decltype(dr)> table;
  constexpr std::size_t kRoom = RecordTable<decltype(dr)>::kRecords * PendingRecords::kFewestAlone + 16;
  HWY_ALIGN std::uint32_t pixels[kRoom];
  HWY_ALIGN std::int32_t which[kRoom];
  const std::size_t lanes = hn::Lanes(dr);
  std::size_t records = 0, count = 0;
  const auto gather = [&] {
    // The lanes past the last pixel read a copy of it (and leave nothing in the batch).
    std::fill_n(pixels + count, lanes, pixels[count - 1]);
    std::fill_n(which + count, lanes, which[count - 1]);
    RecordGroup<decltype(dr)> lanesOf(dr, table);
    GatherLanes(layout, lanesOf, pixels, which, count, b);
    records = 0, count = 0;
  };
  for (std::size_t r = 0; r < group.size; ++r) {
    const ShownRecord& rec = group.record[r];
    const std::uint32_t* p = group.pixels[r];
    const std::size_t n = group.count[r];
    if (!SplitFits(rec, rect)) {
      GatherShown(layout, rec, rect, p, n, b);
      continue;
    }
    table.set(records, layout, OneRecord<decltype(dr), true>(dr, rec, rect, p[0]));
    std::copy_n(p, n, pixels + count);
    std::fill_n(which + count, n, std::int32_t(records));
    count += n, ++records;
    if (records == lanes) gather();
  }
  if (records > 0) gather();
#else
  for (std::size_t r = 0; r < group.size; ++r)
    GatherShown(layout, group.record[r], rect, group.pixels[r], group.count[r], b);
#endif
}

}  // namespace illum::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "raster/shade/fragment.h"
#include "shading/shade_points.h"

namespace illum {

HWY_EXPORT(GatherShown);
HWY_EXPORT(GatherShownGroup);

void gatherShown(const VisibleLayout& layout, const ShownRecord& record, const PixelRect& rect,
                 const std::uint32_t* pixels, std::size_t count, VisibleBatch& batch) {
  HWY_DYNAMIC_DISPATCH(GatherShown)(layout, record, rect, pixels, count, batch);
}

void gatherShownGroup(const VisibleLayout& layout, const PendingRecords& group, const PixelRect& rect,
                      VisibleBatch& batch) {
  HWY_DYNAMIC_DISPATCH(GatherShownGroup)(layout, group, rect, batch);
}

namespace {

// Where an object's per-vertex values go in a ShownRecord, for the frame's shading.
VisibleLayout layoutOf(const FrameContext& frame, const Object& object) {
  VisibleLayout v;
  v.shading = frame.shading;
  int next = 0;
  const auto take = [&](int n) {
    const int at = next;
    next += n;
    return at;
  };
  if (frame.shading == Shading::Gouraud) v.lit = take(4);
  if (frame.shading == Shading::Phong) {
    v.position = take(3), v.normal = take(3);
    if (!object.mesh->colors.empty()) v.color = take(4);
  }
  v.texture = drawnTexture(object);
  if (mapsDrawn(object, frame.litPerPixel())) {
    const Material& m = object.material;
    v.maps = &object.maps;
    v.physical = m.physicallyBased;
    v.metallic = m.physical.metallic, v.roughness = m.physical.roughness;
    v.emission = Color3(m.emission);
  }
  if (v.texture || v.maps) v.uv = take(2);
  v.baseTexel = texelIsBaseColor(object, frame.model, frame.litPerPixel());
  const Material& m = object.material;
  v.baseColor = Color4(physicalOf(m).baseColor, m.diffuse.a);
  return v;
}

}  // namespace

void VisibleShader::shadeAll(ShownLists& lists) {
  // The pairs, then each record's pixels laid out record by record (groupByRecord).
  const std::size_t n = records_.size(), room = kTileBlock * std::size_t(out_.count) + 16;
  if (lists.pairPixel.size() < room) lists.pairPixel.resize(room), lists.pairSlot.resize(room);
  const std::size_t pairs = shownPairs(out_.winners, out_.count, lists.pairPixel.data(), lists.pairSlot.data());
  if (pairs == 0) return;
  lists.start.resize(n + 1);
  lists.pixels.resize(pairs + 16);  // room for a vector written or read past the last
  groupByRecord(lists.pairPixel.data(), lists.pairSlot.data(), pairs, n, lists.start.data(), lists.pixels.data());
  for (std::size_t r = 0; r < n; ++r)
    if (lists.start[r + 1] > lists.start[r])
      shade(std::uint32_t(r), lists.pixels.data() + lists.start[r], lists.start[r + 1] - lists.start[r]);
  flush();
}

void VisibleShader::shadeListed(ShownLists& lists) {
  const std::size_t n = lists.start.size() - 1;
  lists.kept.resize(n);
  keepShown(out_.winners, out_.count, lists.start.data(), n, lists.pixels.data(), lists.kept.data());
  for (std::size_t r = 0; r < n; ++r)
    if (lists.kept[r] > 0) shade(std::uint32_t(r), lists.pixels.data() + lists.start[r], lists.kept[r]);
  flush();
}

void VisibleShader::shade(std::uint32_t slot, const std::uint32_t* pixels, std::size_t count) {
  const DrawRecord& r = *records_[slot];
  const Object& object = target_.scene.objects[r.object];
  const TriangleSetup& t = r.setup;
  if ((b_.count > 0 || pending_.size > 0) && r.object != object_) flush();
  if (b_.count == 0 && pending_.size == 0) {
    object_ = r.object;
    layout_ = layoutOf(target_.frame, object);
  }
  ShownRecord rec;
  rec.setup = &t;
  rec.slot = slot;
  const AttributeLayout& a = target_.layout(r);
  for (int k = 0; k < 3; ++k) {
    const VertexValues v{r.vertex(k, a), a};
    const auto put = [&](int at, const auto& value, int n) {
      for (int c = 0; c < n; ++c) rec.vertex[k][at + c] = value[c];
    };
    if (layout_.lit >= 0) put(layout_.lit, v.lit(), 4);
    if (layout_.position >= 0) put(layout_.position, v.position(), 3), put(layout_.normal, v.normal(), 3);
    if (layout_.color >= 0) put(layout_.color, v.color(), 4);
    if (layout_.uv >= 0) put(layout_.uv, v.uv(), 2);
  }
  rec.flat = r.flat;
  rec.negate = target_.frame.lightModel.twoSided && !t.frontFacing;
  if (layout_.maps && layout_.maps->normal) {
    const VertexValues v[3] = {{r.vertex(0, a), a}, {r.vertex(1, a), a}, {r.vertex(2, a), a}};
    const TangentFrame f =
        triangleTangents({v[0].position(), v[1].position(), v[2].position()}, {v[0].uv(), v[1].uv(), v[2].uv()});
    rec.dPdu = f.dPdu, rec.dPdv = f.dPdv;
  }
  if (layout_.uv >= 0) {
    // Screen-space barycentrics are linear: one pixel right adds a·256/area, one up adds b·256/area.
    const Real step = Real(kSubpixelOne) / Real(t.area2);
    for (int i = 0; i < 3; ++i)
      rec.stepX[i] = Real(t.edge[std::size_t(i)].a) * step, rec.stepY[i] = Real(t.edge[std::size_t(i)].b) * step;
  }
  if (count < PendingRecords::kFewestAlone) {
    if (pending_.size == PendingRecords::kRecords) gatherPending();
    if (b_.count + pending_.pixelCount + count > VisibleBatch::kSize) flush();
    const std::size_t k = pending_.size++;
    pending_.record[k] = rec, pending_.pixels[k] = pixels, pending_.count[k] = std::uint32_t(count);
    pending_.pixelCount += count;
    return;
  }
  gatherPending();
  // In pieces that fit in the batch.
  for (std::size_t done = 0; done < count;) {
    if (b_.count == VisibleBatch::kSize) flush();
    const std::size_t piece = std::min(count - done, VisibleBatch::kSize - b_.count);
    gatherShown(layout_, rec, rect_, pixels + done, piece, b_);
    done += piece;
  }
}

void VisibleShader::gatherPending() {
  if (pending_.size == 0) return;
  gatherShownGroup(layout_, pending_, rect_, b_);
  pending_.size = 0, pending_.pixelCount = 0;
}

void VisibleShader::flush() {
  gatherPending();
  if (b_.count == 0) return;
  if (layout_.texture || layout_.maps) sampleBatchTexels(layout_, b_);
  const Object& object = target_.scene.objects[object_];
  if (layout_.shading == Shading::Phong) {
    const ShadeSetup setup{target_.frame.lights, target_.frame.lightModel, modelOf(object.material, target_.frame.model),
                           object.material};
    SurfacePoints points;
    points.count = b_.count;
    for (int c = 0; c < 3; ++c) points.position[c] = b_.position[c], points.normal[c] = b_.normal[c];
    if (layout_.color >= 0 || layout_.baseTexel)
      for (int c = 0; c < 4; ++c) points.color[c] = b_.color[c];
    if (layout_.maps && layout_.maps->metallicRoughness && layout_.physical)
      points.metallic = b_.metallic, points.roughness = b_.roughness;
    if (layout_.maps && layout_.maps->emissive)
      for (int c = 0; c < 3; ++c) points.emission[c] = b_.emission[c];
    if (const OcclusionQuery* occlusion = target_.frame.occlusion) {
      // The ambient's open share at each pixel's point, seeded by the pixel.
      for (std::size_t k = 0; k < b_.count; ++k)
        b_.seed[k] = OcclusionQuery::pixelSeed(rect_.minX + int(b_.pixel[k] % kTileSize),
                                               rect_.minY + int(b_.pixel[k] / kTileSize), target_.frame.width);
      const Real* position[3] = {b_.position[0], b_.position[1], b_.position[2]};
      const Real* normal[3] = {b_.normal[0], b_.normal[1], b_.normal[2]};
      occlusion->open(b_.count, position, normal, b_.seed, b_.open);
      points.ambientOpen = b_.open;
    }
    Real* const lit[4] = {b_.lit[0], b_.lit[1], b_.lit[2], b_.lit[3]};
    shadePoints(setup, points, lit);
  } else {
    for (int c = 0; c < 4; ++c) std::copy_n(b_.color[c], b_.count, b_.lit[c]);
  }
  if (blending_) {
    // Each pixel's colour (GL_MODULATE's product too) blended over its samples, in float.
    const bool modulate = layout_.texture && !layout_.baseTexel;
    for (std::size_t k = 0; k < b_.count; ++k) {
      const Color4 lit(b_.lit[0][k], b_.lit[1][k], b_.lit[2][k], b_.lit[3][k]);
      out_.blend(int(b_.pixel[k]), b_.blendMask[k],
                 modulate ? lit * Vec4(b_.texel[0][k], b_.texel[1][k], b_.texel[2][k], b_.texel[3][k]) : lit);
    }
  } else {
    finishVisible(layout_, b_);
    writeShown(b_, out_.color, out_.winners, out_.count);
  }
  b_.count = 0;
}

void VisibleShader::blendRecord(std::uint32_t slot, ShownLists& lists) {
  const TriangleSetup& t = records_[slot]->setup;
  const int minX = std::max(t.minX, rect_.minX), maxX = std::min(t.maxX, rect_.maxX);
  const int minY = std::max(t.minY, rect_.minY), maxY = std::min(t.maxY, rect_.maxY);
  if (minX > maxX || minY > maxY) return;
  // Its pixels: those of its bounds some sample of which shows it.
  lists.pixels.clear();
  for (int y = minY; y <= maxY; ++y)
    for (int x = minX; x <= maxX; ++x) {
      const int index = (y - rect_.minY) * kTileSize + (x - rect_.minX);
      if (out_.shows(index, slot)) lists.pixels.push_back(std::uint32_t(index));
    }
  const std::size_t count = lists.pixels.size();
  lists.pixels.resize(count + 16);  // room for a vector read past the last
  blendPixels(slot, lists.pixels.data(), count);
}

void VisibleShader::blendPixels(std::uint32_t slot, const std::uint32_t* pixels, std::size_t count) {
  if (count == 0) return;
  blending_ = true;
  // In pieces that fit in the batch, each gathered at once (`pixels` is the caller's, reused for
  // the next record), its samples beside its pixels.
  for (std::size_t done = 0; done < count;) {
    if (b_.count == VisibleBatch::kSize) flush();
    const std::size_t piece = std::min(count - done, VisibleBatch::kSize - b_.count);
    shade(slot, pixels + done, piece);
    gatherPending();
    std::uint32_t* mask = b_.blendMask + (b_.count - piece);
    for (std::size_t k = 0; k < piece; ++k) mask[k] = out_.takeShown(int(pixels[done + k]), slot);
    done += piece;
  }
}

void VisibleShader::finishBlending() {
  flush();
  blending_ = false;
}

}  // namespace illum
#endif  // HWY_ONCE

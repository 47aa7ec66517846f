// Setup's output: self-contained triangle records. Each holds the triangle's geometry (edge
// functions, depths, 1/w, bounds) and, by value, only the per-vertex values its draw reads (an
// attribute layout chosen once per object: Gouraud's lit colours, Phong's eye positions and
// normals, vertex colours, texture coordinates), so that a dense mesh's records stay small and a
// record needs nothing but the frame and its object when a tile is drawn later.
#pragma once

#include <illum/render.h>
#include <illum/texture.h>

#include "raster/setup/bin.h"
#include "raster/frame_context.h"
#include "raster/setup/setup.h"
#include "raster/setup/vertex.h"
#include "shading/shade_points.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace illum {

// Where each per-vertex value sits among a vertex's `stride` Reals; −1: not carried.
struct AttributeLayout {
  int stride = 0;
  int lit = -1;       // 4: the colour lit at the vertex for the side the triangle shows (Gouraud)
  int position = -1;  // 3: eye-space position (Phong)
  int normal = -1;    // 3: eye-space unit normal, as lit (Phong)
  int color = -1;     // 4: the vertex colour (GL_COLOR_MATERIAL, Phong)
  int uv = -1;        // 2: texture coordinates
  // With a watched pixel everything is carried, and after the three vertices the provoking
  // vertex's eye position and normal (6 Reals), which flat shading lit.
  bool probe = false;

  static AttributeLayout forObject(const FrameContext& frame, const Object& object, bool probe);
  std::size_t reals() const { return std::size_t(3 * stride + (probe ? 6 : 0)); }
};

struct DrawRecord {
  TriangleSetup setup;
  Color4 flat;                 // flat shading: the provoking (last) vertex's colour for the side shown
  std::uint32_t object;        // index into Scene::objects
  std::uint32_t triangle;      // of that object's mesh
  std::uint32_t piece;         // which of the clipped triangle's fan (0 when unclipped)

  // The per-vertex values follow the record in memory.
  const Real* vertex(int i, const AttributeLayout& l) const {
    return reinterpret_cast<const Real*>(this + 1) + i * l.stride;
  }
  Real* vertex(int i, const AttributeLayout& l) { return reinterpret_cast<Real*>(this + 1) + i * l.stride; }
  const Real* provoking(const AttributeLayout& l) const { return vertex(3, l); }
};

// Vertex i's values, read through the layout.
struct VertexValues {
  const Real* v;
  const AttributeLayout& l;
  Color4 lit() const { return {v[l.lit], v[l.lit + 1], v[l.lit + 2], v[l.lit + 3]}; }
  Vec3 position() const { return {v[l.position], v[l.position + 1], v[l.position + 2]}; }
  Vec3 normal() const { return {v[l.normal], v[l.normal + 1], v[l.normal + 2]}; }
  Color4 color() const { return l.color < 0 ? Color4(1) : Color4(v[l.color], v[l.color + 1], v[l.color + 2], v[l.color + 3]); }
  Vec2 uv() const { return {v[l.uv], v[l.uv + 1]}; }
};

// One chunk's records, each followed by its values, in one block reused from batch to batch.
// Records do not move once the chunk is set up (it is binned only then).
class RecordArena {
 public:
  // Empties the arena for records of `layout`, with room for `expected` of them at once (a chunk's
  // triangle count: growing by doubling would copy the records and touch the memory twice).
  void reset(const AttributeLayout& layout, std::size_t expected = 0);
  // A record to fill; drop() takes back the last one.
  DrawRecord& append();
  void drop() { --count_; }
  std::size_t size() const { return count_; }
  const DrawRecord& operator[](std::size_t i) const {
    return *reinterpret_cast<const DrawRecord*>(blocks_.get() + i * blocksPerRecord_);
  }
  const AttributeLayout& layout() const { return layout_; }

 private:
  void grow(std::size_t capacity);
  struct alignas(16) Block {
    std::byte bytes[16];
  };
  std::unique_ptr<Block[]> blocks_;
  std::size_t capacity_ = 0, count_ = 0, blocksPerRecord_ = 0;
  AttributeLayout layout_;
};

// How the binned pipeline takes a chunk's output: each record binned to the tiles it touches as
// soon as it is set up and, with `tiny` (DrawTarget::tiny), each tiny triangle (isTiny) worked out
// at once into pixels of its tile (coloured, or for Phong shading the visible surface) instead
// of becoming a record.
struct SetupBinning {
  TileBins& bins;
  bool tiny = false;
  std::uint32_t shadeOwner = 0;  // the owner that Phong's tiny pixels name (DrawTarget::shadeOwner)
  // Multisampled Phong: the object's lighting, which colours its tiny triangles' samples at setup.
  const ShadeSetup* lighting = nullptr;
};

// Clips and sets up triangles [first, last) of `object` (its vertices already through the vertex
// stage), appending a record for each drawn (clipped) piece to `out` in submission order, binned
// as it goes when `binning` is given. Returns how many pieces were drawn (records and tiny ones).
std::size_t setupTriangles(const FrameContext& frame, const Object& object, std::uint32_t objectIndex,
                           std::span<const ShadedVertex> vertices, std::size_t first, std::size_t last,
                           RecordArena& out, const SetupBinning* binning = nullptr);

}  // namespace illum

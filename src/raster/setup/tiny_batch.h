// Tiny triangles covered a batch at a time: flat and Gouraud shading's fragments, Phong's visible
// surface. One tiny triangle alone (tile_raster.h: coverTinyGouraud) is one long chain of
// dependent steps, edges to coverage to colour (or surface), that leaves most of a vector and of
// the core idle; a batch lays the pixels of up to 16 triangles side by side in the lanes, one
// pixel per lane, each lane with its own triangle's values, and works them out together: the
// same formulas (interpolate-inl.h), so the same depths and colours (or surfaces), written in the
// same order, triangle after triangle.
#pragma once

#include <illum/real.h>

#if !ILLUM_USE_DOUBLE
#include "raster/setup/bin.h"
#include "raster/setup/setup.h"
#include "raster/coverage/tile_raster.h"
#include "raster/coverage/tiny_fragment.h"
#include "raster/setup/vertex.h"

#include <illum/lighting.h>

#include "shading/shade_points.h"

#include <cstddef>
#include <cstdint>

namespace illum {

// Up to kCapacity tiny triangles, each field a row of lanes (one per triangle).
struct TinyBatchLanes {
  static constexpr int kCapacity = 16;
  // Edge values at the bounds' first pixel centre, their steps per column and per row, and the
  // top-left rule's bias, as VisitTiny (tile_raster.cpp) has them.
  alignas(64) float edge[3][kCapacity], stepX[3][kCapacity], stepY[3][kCapacity], bias[3][kCapacity];
  alignas(64) float invArea[kCapacity], z[3][kCapacity], invW[3][kCapacity];
  alignas(64) float lit[3][3][kCapacity];  // Gouraud: channel, vertex (counter-clockwise), triangle
  // Phong: eye-space position and normal (component, vertex, triangle), and 1 where the normal is
  // negated (the back of a triangle under two-sided lighting).
  alignas(64) float position[3][3][kCapacity], normal[3][3][kCapacity], negate[kCapacity];
  alignas(64) std::uint32_t packed[kCapacity];  // flat: the RGBA8 colour
  alignas(64) std::uint32_t firstTag[kCapacity];  // the bounds' first pixel, tagged (TinyTag)
  std::uint8_t width[kCapacity], count[kCapacity];  // the bounds' width and pixel count
  // Bit 0: the bounds run on into the next tile to the right; bit 1: into the tile above. Such a
  // triangle's firstTag is only its first pixel in its (bottom-left) tile: TinyBatch::flush sorts
  // its covered pixels into their tiles and tags them there.
  std::uint8_t crosses[kCapacity];
  // Multisampling in one pass: the samples per pixel (4, 8 or 16). A pixel's samples are covered
  // and their depths found each as a pass at that sample would (rasterizeSamples), its colour once
  // at the centre; each covered sample is one TinyFragment, tagged with its sample's place
  // (TinyTag), and firstTag holds the bounds' first pixel times the samples. The bounds take in
  // every pixel with a sample in the triangle's box; sample s of triangle j is looked for only in
  // the pixels whose sample s lies in that box, as a pass at that sample bounds them: a box
  // `sampleWidth` pixels wide of `sampleCount` pixels (0: none), whose first slot is sampleBase
  // (TinySampleSlot: its place in the bounds and the sample's offset).
  int samples = 1;
  alignas(64) std::uint32_t sampleBase[kSamplesMax][kCapacity];
  alignas(64) std::int32_t sampleWidth[kSamplesMax][kCapacity], sampleCount[kSamplesMax][kCapacity];
};

// A multisampled tiny triangle's slot (tiny_batch.cpp): sample s of pixel (c, r) of its bounds,
// the sample (x', y') sixteenths of a pixel from the centre (x' in [−8, 7], y' in [−7, 8]: the
// standard patterns, y flipped): 16c + x' + kColumnBias in bits 0–8, 16r + y' + kRowBias in bits
// 9–17 (each field's value >> kSubShift the pixel's), s in bits 18–21.
struct TinySampleSlot {
  static constexpr int kRowShift = 9, kSampleShift = 18, kBits = 22, kSubShift = 4;
  static constexpr std::uint32_t kFieldMask = (1u << kRowShift) - 1;
  static constexpr int kColumnBias = 8, kRowBias = 7;
  static std::uint32_t of(int column, int row, SubpixelOffset sample, int s) {
    return std::uint32_t(16 * column + int(sample.x / 16) + kColumnBias) |
           std::uint32_t(16 * row + int(sample.y / 16) + kRowBias) << kRowShift | std::uint32_t(s) << kSampleShift;
  }
};

// Lane j of `lanes` for the tiny triangle `t`, as the batch needs it: its three vertex colours
// (`lit`, counter-clockwise) or, flat, its colour `packed`; it comes after `recordsBefore` of its
// tile's records.
void setTinyLanes(TinyBatchLanes& lanes, int j, const TriangleSetup& t, const Color4* lit, std::uint32_t packed,
                  std::uint32_t recordsBefore);

// Lane j's surface, for Phong's tiny triangle `v` (its vertices counter-clockwise, no colours).
void setTinySurfaceLanes(TinyBatchLanes& lanes, int j, const SurfaceVertices& v);

// Covers the batch's triangles named by the bits of `members` (bit j: triangle j): their covered
// pixels go to `out` (room for kTinyBatchRoom times the samples), triangle after triangle, each
// triangle's in rows from the bottom, as coverTinyFlat (`flat`) or coverTinyGouraud writes them
// (multisampled: each covered sample, as rasterizeSamplesColored writes it); covered[j] is how
// many triangle j has. Returns how many were written.
constexpr std::size_t kTinyBatchRoom = TinyBatchLanes::kCapacity * (kTinyPixels + 1);
std::size_t coverTinyBatch(const TinyBatchLanes& batch, std::uint32_t members, bool flat, TinyFragment* out,
                           std::uint16_t* covered);
// Multisampled Phong: the same covered samples, each coloured by `lighting` at its pixel's centre
// as the Deferred route colours it (each pixel of a triangle lit once).
std::size_t coverTinyBatch(const TinyBatchLanes& batch, std::uint32_t members, const ShadeSetup& lighting,
                           TinyFragment* out, std::uint16_t* covered);
// The same for Phong: the visible surface there, as coverTinySurface writes it, named `owner`.
std::size_t coverTinyBatch(const TinyBatchLanes& batch, std::uint32_t members, std::uint32_t owner, TinySurface* out,
                           std::uint16_t* covered);

// A run of triangles of one object, for setting a group of them up at once.
struct TinyGroupSource {
  const ShadedVertex* vertices;
  const std::uint32_t* indices;  // three per triangle, from the group's first
  int width, height, tilesX;
  bool twoSided, flat;
  bool surface = false;  // Phong: positions and normals instead of colours
  // How many vertices `vertices` holds (0: not known). Up to 2^26 of them, each field of the
  // group's vertices is gathered into lanes at once; beyond, or not known, they are read one by one.
  std::size_t vertexCount = 0;
  // Multisampling in one pass: the bounds take in every pixel whose samples, this far from its
  // centre, the triangle may cover (setupTriangle's reach), and the first pixel's tag is times
  // `samples`.
  FrameContext::SampleReach reach;
  int samples = 1;
  const SubpixelOffset* sampleOffsets = nullptr;  // the frame's `samples` offsets
  bool frontOnly = false;  // only front faces (window area > 0) are fast
};

// How many triangles setupTinyGroup takes at a time on this CPU (at most kCapacity).
int tinyGroupCapacity();

// Sets `count` triangles up in lanes, as setupTriangle and setTinyLanes would, without a branch
// per triangle: bit j of `fast` says that triangle j is inside the clip volume, tiny and
// float-exact with opaque colours (a surface's need none), and its lanes (all but the records before it in firstTag's
// upper bits) and tile (of its bounds' first pixel) are filled in, `crosses` saying which tiles
// its bounds run on into; bit j of `empty` that it is inside the clip volume but covers no pixel
// centre (setupTriangle would drop it). The others are left to the one-by-one path.
void setupTinyGroup(const TinyGroupSource& source, int count, TinyBatchLanes& lanes, int* tile, std::uint32_t& fast,
                    std::uint32_t& empty);

// Gathers the tiny triangles of one setup run and hands their pixels (TinyFragment, or Phong's
// TinySurface) to the bins, in the order they came. Only float-exact triangles
// (TriangleSetup::floatExact) of opaque colours join: one at a time (add, in one tile) or a group
// set up at once (setGroupUp, then take each fast one in order, in one tile or across up to four).
// The bins have `tilesX` tiles to a row; a surface's pixels name `owner`.
template <class Pixel>
class TinyBatch {
 public:
  // Multisampled in one pass, `samples` is the frame's sample count (4, 8 or 16: the standard
  // pattern, multisamplePattern).
  // With `lighting` (multisampled Phong), fragments are lit at setup (coverTinyBatch).
  TinyBatch(TinyRuns<Pixel>& out, bool flat, int tilesX, std::uint32_t owner = 0, int samples = 1,
            const ShadeSetup* lighting = nullptr);
  TinyBatch(const TinyBatch&) = delete;
  TinyBatch& operator=(const TinyBatch&) = delete;

  static bool joins(const TriangleSetup& t, const Color4* lit) {
    return t.floatExact && (!lit || (lit[0].a == 1 && lit[1].a == 1 && lit[2].a == 1));
  }
  // Adds a triangle whose bounds lie in `tile` (setTinyLanes).
  void add(const TriangleSetup& t, const Color4* lit, std::uint32_t packed, std::uint32_t recordsBefore, int tile);
  // The same for Phong's surface (a batch of TinySurface; its pixels name the batch's owner, which
  // must be v.owner).
  void add(const TriangleSetup& t, const SurfaceVertices& v, std::uint32_t recordsBefore, int tile) {
    setTinySurfaceLanes(lanes_, size_, v);
    add(t, nullptr, 0, recordsBefore, tile);
  }

  // Sets the next `count` (≤ tinyGroupCapacity()) triangles up at once (setupTinyGroup); the batch
  // must be empty.
  void setGroupUp(const TinyGroupSource& source, int count, std::uint32_t& fast, std::uint32_t& empty) {
    setupTinyGroup(source, count, lanes_, tile_, fast, empty);
  }
  // Takes fast triangle j of the group, after recordsIn(tile) of each of its tiles' records.
  template <class RecordsIn>
  void take(int j, const RecordsIn& recordsIn) {
    const unsigned crosses = lanes_.crosses[j];
    if (crosses == 0) {
      lanes_.firstTag[j] |= TinyTag::of(recordsIn(tile_[j]), 0);
    } else {
      for (unsigned piece = 0; piece < 4; ++piece)
        if ((piece & ~crosses) == 0) recordsBefore_[j][piece] = recordsIn(pieceTile(j, piece));
    }
    members_ |= 1u << j;
  }

  // Covers what was added or taken and appends it to the bins' runs (before anything else is
  // appended there, and once the run is over).
  void flush();

 private:
  // The tile of piece p of triangle j's bounds: bit 0 of p, the next tile right; bit 1, above.
  int pieceTile(int j, unsigned p) const { return tile_[j] + int(p & 1) + int(p >> 1) * tilesX_; }
  // Sorts the `count` covered pixels of triangle j (crossing tiles) into its tiles and commits them.
  void commitAcrossTiles(int j, Pixel* pixels, std::size_t count);

  TinyRuns<Pixel>& out_;
  bool flat_;
  int tilesX_;
  std::uint32_t owner_;
  const ShadeSetup* lighting_;
  int size_ = 0;               // add: the lanes used
  std::uint32_t members_ = 0;  // the lanes to cover
  int tile_[TinyBatchLanes::kCapacity];
  std::uint32_t recordsBefore_[TinyBatchLanes::kCapacity][4];  // a crossing triangle's, per piece
  TinyBatchLanes lanes_;
};

}  // namespace illum
#endif  // !ILLUM_USE_DOUBLE

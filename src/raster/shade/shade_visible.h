// The deferred draws' one shade hand-off: record by record, the pixels of the tile that show it
// (whichever of their samples do), in SIMD lanes with the record's values broadcast (or, for
// records of few pixels, several records' pixels in one vector, each lane its own record's): the pixel
// centres' barycentrics → perspective-correct weights → the draw's colour (flat, Gouraud's
// interpolated one, or Phong's surface, lit by shadePoints a batch of the object's pixels at a
// time) → the texel (texture_lanes-inl.h) → GL_MODULATE → RGBA8, written to every sample that
// shows the record. glTF's maps are read in the lanes too (metallic, roughness, emission, the
// normal map's bent normal), each pixel's material given to the lighting lane by lane. The same
// bits as the one-pixel formulas of fragment.h.
#pragma once

#include "raster/shade/draw.h"
#include "raster/coverage/tile_raster.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace illum {

// Where a tile's deferred colours go: its RGBA8 words and the record each sample shows, each
// pixel's `count` samples side by side (framebuffer.h).
struct VisibleSamples {
  int count = 1;
  std::uint32_t* color;
  std::uint32_t* winners;

  // f(index, slot) once for each record that some sample of pixel `index` shows, in sample order.
  template <class F>
  void forEachShown(int index, F&& f) const {
    const std::uint32_t* shown = winners + std::size_t(index) * std::size_t(count);
    // Most pixels show one record in every sample.
    int same = 1;
    while (same < count && shown[same] == shown[0]) ++same;
    if (same == count) {
      if (shown[0] != kNoWinner) f(index, shown[0]);
      return;
    }
    for (int s = 0; s < count; ++s) {
      const std::uint32_t slot = shown[s];
      if (slot == kNoWinner) continue;
      bool earlier = false;
      for (int e = 0; e < s && !earlier; ++e) earlier = shown[e] == slot;
      if (!earlier) f(index, slot);
    }
  }
  void write(int index, std::uint32_t slot, std::uint32_t rgba) const {
    const std::size_t at = std::size_t(index) * std::size_t(count);
    for (int s = 0; s < count; ++s)
      if (winners[at + std::size_t(s)] == slot) color[at + std::size_t(s)] = rgba;
  }
  // The samples of pixel `index` that show `slot` (bit s: sample s), which then show no record.
  std::uint32_t takeShown(int index, std::uint32_t slot) const {
    const std::size_t at = std::size_t(index) * std::size_t(count);
    std::uint32_t mask = 0;
    for (int s = 0; s < count; ++s)
      if (winners[at + std::size_t(s)] == slot) mask |= 1u << s, winners[at + std::size_t(s)] = kNoWinner;
    return mask;
  }
  // A translucent record's colour over what each sample of `mask` holds (blendOver).
  // (Samples that held the same word get the same one: it is blended once.)
  void blend(int index, std::uint32_t mask, const Color4& c) const {
    const std::size_t at = std::size_t(index) * std::size_t(count);
    bool blended = false;
    std::uint32_t under = 0, over = 0;
    for (int s = 0; s < count; ++s)
      if (mask & (1u << s)) {
        std::uint32_t& word = color[at + std::size_t(s)];
        if (!blended || word != under) {
          under = word;
          blendOver(reinterpret_cast<std::uint8_t*>(&word), c);
          over = word, blended = true;
        } else {
          word = over;
        }
      }
  }
  bool shows(int index, std::uint32_t slot) const {
    const std::size_t at = std::size_t(index) * std::size_t(count);
    for (int s = 0; s < count; ++s)
      if (winners[at + std::size_t(s)] == slot) return true;
    return false;
  }
};

// What the lanes of one record see, the same in every lane: where its per-vertex values sit
// (VisibleLayout), its geometry, and the values.
struct VisibleLayout {
  Shading shading = Shading::Phong;
  int lit = -1, position = -1, normal = -1, color = -1, uv = -1;  // in ShownRecord::vertex, −1: none
  const Texture* texture = nullptr;  // the object's drawn texture
  bool baseTexel = false;            // the texel tints the base colour before lighting
  Color4 baseColor{1};               // the material's base colour and alpha, for baseTexel without vertex colours
  // glTF's maps, when drawn (mapsDrawn), and the material values they scale: a physically based
  // material's metallic and roughness (`physical`), and the emission.
  const MaterialMaps* maps = nullptr;
  bool physical = false;
  Real metallic = 0, roughness = 1;
  Color3 emission{0};
};

struct ShownRecord {
  static constexpr int kValues = 12;  // per vertex, at most: position 3, normal 3, colour 4, uv 2
  const TriangleSetup* setup = nullptr;
  std::uint32_t slot = 0;
  Real vertex[3][kValues];  // the values the layout names, vertex by vertex (counter-clockwise)
  Color4 flat{0};           // flat shading: the provoking vertex's lit colour
  bool negate = false;      // a back face under two-sided lighting: lit with −N
  Real stepX[3], stepY[3];  // textured: how the barycentrics move one pixel right (a·256/area) and up (b·…)
  Vec3 dPdu{0}, dPdv{0};    // a normal map's tangent frame (triangleTangents)
};

// Records of one object with few pixels each, waiting to be gathered together: their pixels share
// vectors, each lane looking up its own record's values (a record of ClearCoatTest's normal-mapped
// spheres shows 3 pixels on average at 1000×600: one record a vector left most lanes empty).
struct PendingRecords {
  static constexpr std::size_t kRecords = 16;       // at most, waiting
  static constexpr std::size_t kFewestAlone = 16;   // a record of this many pixels or more goes alone
  std::size_t size = 0, pixelCount = 0;
  ShownRecord record[kRecords];
  const std::uint32_t* pixels[kRecords];  // each record's (tile indices, with room for a vector past the last)
  std::uint32_t count[kRecords];
};

// The shown pixels of some records of one object, structure of arrays: their surface (Phong), the
// colour (flat: the record's; Gouraud: interpolated; Phong: the vertex colour, or the base colour
// tinted by the texel), the texel, then the lit colour and the RGBA8 word.
struct VisibleBatch {
  static constexpr std::size_t kSize = 1024;
  static constexpr std::size_t kRoom = kSize + 16;  // a vector stored whole past the last pixel
  std::size_t count = 0;
  alignas(64) Real position[3][kRoom];
  alignas(64) Real normal[3][kRoom];
  alignas(64) Real color[4][kRoom];
  alignas(64) Real texel[4][kRoom];
  // Textured or mapped: where the textures are read, and how uv changes one pixel right and up.
  alignas(64) Real uv[2][kRoom];
  alignas(64) Real uvDx[2][kRoom];
  alignas(64) Real uvDy[2][kRoom];
  // A normal map's: the triangle's tangent frame, and whether the bent normal is negated (1).
  alignas(64) Real dPdu[3][kRoom];
  alignas(64) Real dPdv[3][kRoom];
  alignas(64) Real flip[kRoom];
  alignas(64) Real lit[4][kRoom];
  // glTF's maps' values (the layout's): metallic, roughness and the emission.
  alignas(64) Real metallic[kRoom];
  alignas(64) Real roughness[kRoom];
  alignas(64) Real emission[3][kRoom];
  alignas(64) std::uint32_t rgba[kRoom];
  alignas(64) std::uint32_t pixel[kRoom];  // index in the tile
  std::uint32_t slot[kRoom];
  std::uint32_t blendMask[kRoom];  // blending: the samples the pixel's colour is blended over
  // Ambient occlusion: each pixel's seed and its ambient's open share.
  std::uint64_t seed[kRoom];
  Real open[kRoom];
};

// The lanes' part (SIMD, dispatched). gatherShown appends the record's pixels `pixels` (tile
// indices, `count` of them) of the tile `rect`: their centres' barycentrics exactly as the
// rasterizer's, the perspective-correct weights, the layout's colour or surface, and where its
// textures are read. sampleBatchTexels, before lighting: the texels there, a texture at a time,
// and what they do (the base colour's tint, glTF's maps). finishVisible: after lighting,
// GL_MODULATE and RGBA8.
void gatherShown(const VisibleLayout& layout, const ShownRecord& record, const PixelRect& rect,
                 const std::uint32_t* pixels, std::size_t count, VisibleBatch& batch);
// The same for each of `group`'s records, the batch having room for all their pixels.
void gatherShownGroup(const VisibleLayout& layout, const PendingRecords& group, const PixelRect& rect,
                      VisibleBatch& batch);
void sampleBatchTexels(const VisibleLayout& layout, VisibleBatch& batch);
void finishVisible(const VisibleLayout& layout, VisibleBatch& batch);

// The (pixel, record) pairs of a tile's winners (`samples` a pixel, kTileSize² pixels), pixel by
// pixel, each record a pixel's samples show once, in sample order (VisibleSamples::forEachShown,
// a vector at a time): pixel[k] and slot[k], k < the count returned. Both hold at least
// kTileBlock·samples + 16 words.
std::size_t shownPairs(const std::uint32_t* winners, int samples, std::uint32_t* pixel, std::uint32_t* slot);

// The `pairs` pairs' pixels laid out record by record into `out` (room for pairs + 16), each
// record's in the pairs' order; start[r] .. start[r + 1] are record r's (start: records + 1
// words). A counting sort; with few records, each record's pixels picked out of the pairs a
// vector at a time (the sort's scattered stores, one after another through the same counters,
// took a tenth of a textured box's frame).
void groupByRecord(const std::uint32_t* pixel, const std::uint32_t* slot, std::size_t pairs, std::size_t records,
                   std::uint32_t* start, std::uint32_t* out);

// For each record slot r < `records`, of its pixels pixels[start[r]] .. [start[r + 1]] (tile
// indices), those some sample of which (`samples` a pixel in `winners`) shows r, kept in order in
// place: kept[r] of them.
void keepShown(const std::uint32_t* winners, int samples, const std::uint32_t* start, std::size_t records,
               std::uint32_t* pixels, std::uint32_t* kept);
// Each pair's RGBA8 word of `batch` to the samples of its pixel that show its record
// (VisibleSamples::write; `samples` a pixel in `color` and `winners`).
void writeShown(const VisibleBatch& batch, std::uint32_t* color, const std::uint32_t* winners, int samples);
// The pixels each record shows in a tile, record by record (a counting sort of the pixels by the
// records their samples show, or, multisampled, the pixels each record's coverage listed),
// reused from tile to tile.
struct ShownLists {
  std::vector<std::uint32_t> pairPixel, pairSlot;  // the pairs, pixel by pixel
  std::vector<std::uint32_t> start;   // per record slot, its first pixel in `pixels`; then the end
  std::vector<std::uint32_t> pixels;  // tile indices
  std::vector<std::uint32_t> kept;    // listed: per record slot, how many of its pixels it shows
};

// Colours the pixels the tile's Deferred records show (`out`), object by object in batches.
class VisibleShader {
 public:
  VisibleShader(const DrawTarget& target, std::span<const DrawRecord* const> records, const PixelRect& rect,
                VisibleBatch& batch, const VisibleSamples& out)
      : target_(target), records_(records), rect_(rect), b_(batch), out_(out) {}
  // Every record of the tile that some pixel shows, in submission order.
  void shadeAll(ShownLists& lists);
  // The same from the pixels each record's coverage listed (rasterizeSamples): record r's from
  // lists.pixels[lists.start[r]] to [lists.start[r + 1]], of which those it still shows are kept.
  void shadeListed(ShownLists& lists);
  // A translucent record's pixels just found (its slot in their samples' winners), to be blended
  // over what they hold. The samples are taken now (they then show no record), the colours
  // blended in order when the batch is lit (when full, at another object, or at finishBlending):
  // later records' coverage may draw over the winners meanwhile, not over the colours.
  void blendRecord(std::uint32_t slot, ShownLists& lists);
  // The same for the record's `count` pixels `pixels` (as rasterizeSamples lists them, with room
  // for a vector past the last).
  void blendPixels(std::uint32_t slot, const std::uint32_t* pixels, std::size_t count);
  // The blends still in the batch, done.
  void finishBlending();

 private:
  void shade(std::uint32_t slot, const std::uint32_t* pixels, std::size_t count);
  // The pending records' pixels into the batch.
  void gatherPending();
  // The batch's pixels lit and written (or blended).
  void flush();
  const DrawTarget& target_;
  std::span<const DrawRecord* const> records_;
  const PixelRect& rect_;
  VisibleBatch& b_;
  const VisibleSamples& out_;
  std::uint32_t object_ = 0;
  VisibleLayout layout_;
  PendingRecords pending_;
  bool blending_ = false;
};

}  // namespace illum

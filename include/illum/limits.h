// How much work an input may ask for before illum refuses it. Every limit can be raised from the
// command line; the error that a limit causes says which option raises it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace illum {

struct Limits {
  // Triangles in one scene or model (GLUT tessellation, declared counts, instanced nodes).
  std::uint64_t maxTriangles = 20'000'000;  // --max-triangles
  // Pixels of the output image and of each texture (checked from the image header, before decoding).
  std::uint64_t maxPixels = std::uint64_t(8192) * 8192;  // --max-pixels
  // Memory the importer may use, in MiB; 0 chooses 512 MiB + 32 × the file's size.
  std::uint64_t maxMemoryMiB = 0;  // --max-memory
  // Seconds (CPU and wall clock) the importer may take; 0 chooses 1.5 s + 0.5 s per MiB of the file.
  double maxSeconds = 0;  // --max-time
  // Bytes of a scene file (or a scene on standard input), checked before it is read; its JSON may
  // hold at most one value for every 4 of these bytes (an empty array or object counts 4), so
  // that the parsed tree stays within a small multiple of this.
  std::uint64_t maxSceneBytes = std::uint64_t(64) << 20;  // --max-scene-size, in MiB
  // Pixels that wide points and lines may cover in one picture, summed over multisample passes
  // (a scene file alone can ask for lines 256 pixels wide): estimated before any is drawn.
  std::uint64_t maxFill = 1'000'000'000;  // --max-fill
  // Bytes of a model on standard input (held in memory: it has no file).
  std::uint64_t maxStdinBytes = std::uint64_t(256) << 20;  // --max-stdin-size, in MiB
  // How deep a scene file's arrays and objects may nest (a real scene nests 5 deep).
  int maxJsonDepth = 64;  // --max-json-depth

  std::uint64_t memoryBytesFor(std::uint64_t fileBytes) const;
  double secondsFor(std::uint64_t fileBytes) const;
};

// "12,345,678" for messages.
std::string withThousands(std::uint64_t n);

}  // namespace illum

// Model files through assimp (OBJ+MTL, PLY, STL, glTF 2.0, FBX, Collada, 3DS and the rest of what
// assimp reads), with their node transforms, materials, vertex colours and diffuse textures.
#pragma once

#include <illum/limits.h>
#include <illum/scene.h>

#include <filesystem>
#include <memory>
#include <exception>
#include <optional>
#include <string>
#include <vector>

namespace illum {

struct ImportOptions {
  NormalMode normals = NormalMode::Auto;
  Real creaseAngle = 40;  // degrees, for generated normals
  Limits limits;
  // The importer's wall-clock limit is its CPU-time limit times this: more than 1 when it shares
  // the cores with other work (a batch drawing one picture while it reads the next file).
  double wallClockAllowance = 1;
  // A file whose name says nothing of its format (standard input, read through /proc/self/fd): the
  // extension to read it as (".ply"), and the folder its textures and companion files (.mtl, .bin)
  // are looked for in instead of the file's own.
  std::string format;
  std::filesystem::path companionDir;
};

struct ImportedModel {
  std::vector<Object> objects;  // one per (node, mesh) instance, in world space
  Vec3 boundsMin{0}, boundsMax{0};
  std::size_t vertexCount = 0, triangleCount = 0, materialCount = 0, textureCount = 0;
  std::size_t pointCount = 0, lineCount = 0;  // of point clouds and line sets
  bool transparencyIgnored = false;  // every surface was fully transparent: drawn opaque instead
  // The up axis the file says it has (FBX's UpAxis metadata), or its format's habit (STL and 3DS
  // are +Z up); unset: the +Y of glTF and most formats.
  std::optional<Vec3> upAxis;
  std::vector<std::string> warnings;  // e.g. a texture that could not be loaded
  std::vector<std::string> files;     // the texture files it read (an output must not replace them)
};

// Reads a model file in an isolated child process (core/isolate.h) under options.limits, so that
// a reader that crashes, aborts, loops or allocates without end costs a clean InputError naming
// the file and the reason ("the importer crashed", "would need more than N MiB: raise
// --max-memory"), never illum itself. Throws InputError for a missing, empty, truncated or
// malformed file, out-of-range indices, non-finite positions, nothing drawable, or a size
// beyond a limit.
ImportedModel importModel(const std::filesystem::path& path, const ImportOptions& options = {});
// importModel in two halves: startImport starts the isolated child and returns at once (a batch
// draws one picture while the next files are read); finish() waits for it and gives the model,
// or throws what importModel would have. Call startImport from the main thread, between renders
// (core/isolate.h says why). A PendingImport destroyed unfinished stops its child.
class IsolatedChild;
class PendingImport {
 public:
  PendingImport();
  PendingImport(PendingImport&&) noexcept;
  PendingImport& operator=(PendingImport&&) noexcept;
  ~PendingImport();
  ImportedModel finish();

 private:
  friend PendingImport startImport(const std::filesystem::path& path, const ImportOptions& options);
  std::filesystem::path path_;
  std::size_t memoryBytes_ = 0;  // its limits, for the messages
  double cpuSeconds_ = 0;
  std::unique_ptr<IsolatedChild> child_;
  std::exception_ptr error_;  // a refusal before any child was started
};
PendingImport startImport(const std::filesystem::path& path, const ImportOptions& options = {});

// The same, in this process (for the fuzzer and for the isolated child itself).
ImportedModel importModelInProcess(const std::filesystem::path& path, const ImportOptions& options = {});

// Whether assimp has a reader for files named so (by extension, case ignored): which files of a
// folder a batch renders.
bool isModelFileName(const std::filesystem::path& path);

// The material illum derives from a file's: see docs/models.md for the mapping.
struct FileMaterialValues {
  bool hasAmbient = false, hasSpecular = false, isMetallicRoughness = false;
  Color4 diffuse{0.8, 0.8, 0.8, 1};
  Color3 ambient{0}, specular{0}, emission{0};
  Real shininess = 0, opacity = 1, metallic = 0, roughness = 1;
};
Material materialFromFile(const FileMaterialValues& values);
// The material of models whose format has none (PLY, STL, OBJ without MTL): a light neutral grey
// with a soft highlight.
Material defaultModelMaterial();

// What previews do to a model's colour textures (diffuse and emissive), and a scene file's
// "colour_textures": "srgb": read as sRGB-encoded, decoded to the linear values the equation lights.
void decodeColourTextures(std::vector<Object>& objects);
// What --color and --geometry-only do, and a scene file's "file_colours": false: the objects'
// textures, glTF maps and vertex colours dropped, so that the material's colours show.
void dropFileColours(std::vector<Object>& objects);

}  // namespace illum

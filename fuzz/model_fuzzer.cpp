// libFuzzer target: model files through illum's import, isolation included. The first byte picks
// the file's extension (assimp chooses its reader by it), the rest is the file. Any bytes must end
// as a model or an InputError: the pre-checks, the wire format and the isolated child's outcomes
// are illum's code under test; assimp's own crashes are contained by the child and reported.
#include <illum/error.h>
#include <illum/import.h>

#include "scene/model_precheck.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace {

constexpr std::array<const char*, 16> kExtensions = {".ply", ".off", ".stl", ".obj", ".gltf", ".glb", ".ac", ".nff",
                                                    ".dae", ".3ds", ".ase", ".md5mesh", ".cob", ".x", ".smd", ".fbx"};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("illum_model_fuzz_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / (std::string("input") + kExtensions[data[0] % kExtensions.size()]);
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  }
  illum::ImportOptions options;
  options.limits.maxTriangles = 200'000;
  options.limits.maxPixels = 1024 * 1024;
  options.limits.maxMemoryMiB = 256;
  options.limits.maxSeconds = 2;
  // The header checks run here too, in this process, so that their coverage guides the fuzzer and
  // their faults are caught here rather than contained in the child.
  try {
    illum::precheckModelFile(file, options.limits, kExtensions[data[0] % kExtensions.size()]);
  } catch (const illum::InputError&) {
  }
  try {
    (void)illum::importModel(file, options);
  } catch (const illum::InputError&) {
  }
  std::filesystem::remove(file);
  std::error_code left;  // (the folder is empty now; if not, it stays)
  std::filesystem::remove(dir, left);
  return 0;
}

// Where a model's texture is, given the name its file stores. Exporters write Windows paths
// ("C:\\maps\\wood.JPG"), absolute paths from the author's machine, and names whose case differs
// from the file on disk; a user would look beside the model, so illum does too.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace illum {

struct TextureLookup {
  std::optional<std::filesystem::path> found;
  std::vector<std::string> tried;  // what was looked for, for the warning when nothing is found
};

// In order: the stored path (with '\\' as a separator; relative to `modelDir` unless absolute),
// the same path matched without regard to case (and a "\\..\\x.jpg" rooted on the author's drive
// taken from the model's folder), then the file name alone (any case) in
// `modelDir` and in its subfolders one level down.
TextureLookup findTextureFile(const std::string& storedName, const std::filesystem::path& modelDir);

}  // namespace illum

// What a model file's own header says it holds, checked before a reader allocates for it: declared
// counts against the bytes that follow (PLY, OFF, binary STL), a PLY header that never ends,
// AC3D subdivision and glTF node instancing against --max-triangles. Cheap: headers only (glTF's
// JSON), so a 1 KB file can no longer ask for gigabytes.
#pragma once

#include <illum/limits.h>

#include <filesystem>
#include <string>

namespace illum {

// Throws InputError naming the file, what it declares and the limit or size it exceeds. `ext`
// (".ply", lower case) is the format to check it as.
void precheckModelFile(const std::filesystem::path& path, const Limits& limits, const std::string& ext);

}  // namespace illum

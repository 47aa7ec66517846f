// Model files through assimp (OBJ, PLY, STL, glTF, FBX, Collada, 3DS, ...).
#pragma once

#include <illum/mesh.h>

#include <filesystem>

namespace illum {

// Loads every triangle of the file into one mesh, with the node transforms applied.
// Normals are kept when present and non-zero, generated otherwise.
// Throws InputError for a missing, empty, malformed or degenerate file.
Mesh importMergedMesh(const std::filesystem::path& path);

}  // namespace illum

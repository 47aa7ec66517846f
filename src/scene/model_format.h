// Which format a model file is in, from its content: for files whose name says nothing of it or
// says something else (a file manager's temporary copy, a download without its extension).
#pragma once

#include <filesystem>
#include <string>

namespace illum {

// The format the file's first bytes (and its size) show, as an extension: ".glb" ("glTF" magic),
// ".gltf" (a JSON object with "asset"), ".ply" ("ply" line), ".stl" ("solid ... facet", or a
// binary STL's exact size 84 + 50·n), ".fbx" (Kaydara's binary header, or an ASCII FBX's
// "; FBX" comment), ".3ds" (a 0x4D4D chunk as long as the file), ".dae" (XML with <COLLADA), ".obj"
// (lines of v, vn, vt, f, o, g, usemtl, mtllib); empty when none of them.
std::string sniffModelFormat(const std::filesystem::path& path);

// The extension a model file is read as: its own when the content agrees or says nothing sure,
// else the content's (an OBJ is trusted from its content only when the name has no extension
// assimp knows).
std::string modelFormatOf(const std::filesystem::path& path);

}  // namespace illum

// What a file's name says, read one way everywhere: extensions compare without case ("DUCK.DAE" is
// a Collada file, "scene.JSON" a scene).
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace illum {

// ASCII letters lower-cased (the C locale's: names are bytes, not text in a language).
inline std::string asciiLower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// ".dae" for "DUCK.DAE"; empty without an extension.
inline std::string lowerExtension(const std::filesystem::path& p) { return asciiLower(p.extension().string()); }

// A scene file: its name ends in .json.
inline bool isSceneFileName(const std::filesystem::path& p) { return lowerExtension(p) == ".json"; }

}  // namespace illum

#include "scene/model_format.h"

#include <illum/file_names.h>
#include <illum/import.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>

namespace illum {
namespace {

constexpr std::size_t kHead = 4096;  // bytes looked at

bool startsWith(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

std::string_view trimmedStart(std::string_view s) {
  if (startsWith(s, "\xEF\xBB\xBF")) s.remove_prefix(3);  // a UTF-8 byte order mark
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  return s;
}

std::uint32_t le32(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = v << 8 | static_cast<unsigned char>(s[at + std::size_t(i)]);
  return v;
}

// Whether the text's first lines are OBJ statements (comments and blank lines aside).
bool looksLikeObj(std::string_view text) {
  std::istringstream in{std::string(text)};
  int statements = 0;
  for (std::string line; std::getline(in, line) && statements < 8;) {
    const std::string_view l = trimmedStart(line);
    if (l.empty() || l[0] == '#') continue;
    static constexpr std::string_view kStarts[] = {"v ", "vn ", "vt ", "f ", "o ", "g ", "s ", "usemtl ", "mtllib ", "l ", "p "};
    if (std::none_of(std::begin(kStarts), std::end(kStarts), [&](std::string_view k) { return startsWith(l, k); }))
      return false;
    ++statements;
  }
  return statements > 0;
}

}  // namespace

std::string sniffModelFormat(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(kHead, '\0');
  in.read(head.data(), std::streamsize(kHead));
  head.resize(std::size_t(in.gcount()));
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return "";
  if (startsWith(head, "glTF")) return ".glb";
  if (startsWith(head, "ply\n") || startsWith(head, "ply\r\n")) return ".ply";
  if (startsWith(head, "Kaydara FBX Binary")) return ".fbx";
  const std::string_view text = trimmedStart(head);
  if (startsWith(text, "; FBX")) return ".fbx";
  if (startsWith(text, "<") && head.find("<COLLADA") != std::string::npos) return ".dae";
  if (startsWith(text, "{") && head.find("\"asset\"") != std::string::npos) return ".gltf";
  if (startsWith(text, "solid") && head.find("facet") != std::string::npos) return ".stl";
  if (head.size() >= 84 && size == 84 + 50 * std::uintmax_t(le32(head, 80))) return ".stl";
  if (head.size() >= 6 && static_cast<unsigned char>(head[0]) == 0x4D && static_cast<unsigned char>(head[1]) == 0x4D &&
      le32(head, 2) == size)
    return ".3ds";
  if (looksLikeObj(text)) return ".obj";
  return "";
}

std::string modelFormatOf(const std::filesystem::path& path) {
  const std::string own = lowerExtension(path), content = sniffModelFormat(path);
  if (content.empty() || content == own) return own;
  if (content == ".obj" && isModelFileName(path)) return own;  // a text format's guess yields to a known name
  return content;
}

}  // namespace illum

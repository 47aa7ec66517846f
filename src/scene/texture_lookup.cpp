#include "scene/texture_lookup.h"

#include <illum/file_names.h>

#include <algorithm>
#include <cctype>
#include <system_error>

namespace illum {
namespace {

namespace fs = std::filesystem;

bool isFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

// The entry of `dir` whose name equals `name` ignoring case (an exact match first).
std::optional<fs::path> entryIgnoringCase(const fs::path& dir, const std::string& name, bool wantDirectory) {
  std::error_code ec;
  if (fs::exists(dir / name, ec) && (wantDirectory ? fs::is_directory(dir / name, ec) : isFile(dir / name)))
    return dir / name;
  const std::string key = asciiLower(name);
  std::optional<fs::path> best;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (asciiLower(it->path().filename().string()) != key) continue;
    if (wantDirectory ? it->is_directory(ec) : it->is_regular_file(ec))
      if (!best || it->path() < *best) best = it->path();  // the same answer on every file system order
  }
  return best;
}

// `relative` resolved one component at a time under `base`, each ignoring case.
std::optional<fs::path> resolveIgnoringCase(const fs::path& base, const fs::path& relative) {
  fs::path at = base;
  const auto last = std::prev(relative.end());
  for (auto it = relative.begin(); it != relative.end(); ++it) {
    const std::string part = it->string();
    if (part.empty() || part == ".") continue;
    if (part == "..") {
      at = at / "..";
      continue;
    }
    const auto next = entryIgnoringCase(at, part, it != last);
    if (!next) return std::nullopt;
    at = *next;
  }
  return isFile(at) ? std::optional<fs::path>(at) : std::nullopt;
}

}  // namespace

TextureLookup findTextureFile(const std::string& storedName, const fs::path& modelDir) {
  TextureLookup r;
  std::string name = storedName;
  std::replace(name.begin(), name.end(), '\\', '/');
  const fs::path stored(name);
  const fs::path dir = modelDir.empty() ? fs::path(".") : modelDir;
  // A Windows drive ("C:/...") is absolute on its own machine, never here.
  const bool windowsAbsolute = name.size() > 2 && std::isalpha(static_cast<unsigned char>(name[0])) && name[1] == ':';
  if (!windowsAbsolute) {
    const fs::path direct = stored.is_absolute() ? stored : dir / stored;
    r.tried.push_back(direct.string());
    if (isFile(direct)) return r.found = direct, r;
    if (!stored.is_absolute() && !stored.empty())
      if (auto p = resolveIgnoringCase(dir, stored)) return r.found = *p, r;
    // "\..\maps\x.jpg": rooted on the author's drive, meant from the model's folder.
    if (storedName.size() > 1 && storedName[0] == '\\' && storedName[1] != '\\') {
      const fs::path relative = stored.relative_path();
      r.tried.push_back((dir / relative).string());
      if (auto p = resolveIgnoringCase(dir, relative)) return r.found = *p, r;
    }
  }
  const std::string file = stored.filename().string();
  if (file.empty()) return r;
  r.tried.push_back(file + " in " + dir.string() + " and its subfolders (any case)");
  if (auto p = entryIgnoringCase(dir, file, false)) return r.found = *p, r;
  std::vector<fs::path> subfolders;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_directory(ec)) subfolders.push_back(it->path());
  std::sort(subfolders.begin(), subfolders.end());
  for (const fs::path& sub : subfolders)
    if (auto p = entryIgnoringCase(sub, file, false)) return r.found = *p, r;
  return r;
}

}  // namespace illum

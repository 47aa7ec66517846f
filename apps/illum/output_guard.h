// Where pictures may be written: never over an input or a file a scene reads, never two jobs to
// one file, never outside --output-dir. Files are compared by what they are, not how they are
// named: a symbolic link (dangling too: the first job would create its target) is followed, and
// a hard link is the file it links.
#pragma once

#include <illum/scene.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace illum::cli {

class OutputGuard {
 public:
  // `file` may not be written: an input, or a file a scene reads.
  void protect(const std::filesystem::path& file);
  // Throws InputError when `output` is (or resolves to) a protected file.
  void checkNotInput(const std::string& output) const;
  // Throws InputError when `output` is a file another owner claimed; then it is `owner`'s.
  void claim(const std::string& output, const std::string& owner);

 private:
  // Keys that name one file: its resolved path, and its device and inode where it exists.
  static std::vector<std::string> keysOf(const std::filesystem::path& file);
  std::map<std::string, std::string> protected_, claimed_;  // key → the name given for it
};

// Throws InputError when one of `outputs` is a file `scene` was read from (Scene::files): its
// scene file, models, textures or environment map.
void checkOutputsSpareScene(const Scene& scene, const std::vector<std::string>& outputs);

// The path `output` will be written at: symbolic links followed (a dangling one to where its
// target would be made), made absolute and normal.
std::filesystem::path resolvedOutput(const std::filesystem::path& output);

}  // namespace illum::cli

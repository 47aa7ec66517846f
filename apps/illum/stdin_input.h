// Standard input ('-'), read once and whole before anything is drawn. A scene's text is kept in
// memory; a model's bytes go to an anonymous memory file (memfd) that has no name on disk, so
// nothing is left behind however illum ends, and nothing in /tmp can be planted in its place or
// read by others. Readers open it as /proc/self/fd/N with --format as its format; a scene read
// from standard input finds its files, and a model its textures, in the working folder.
#pragma once

#include <illum/limits.h>

#include <string>

namespace illum::cli {

class StdinInput {
 public:
  // Reads standard input to its end. Throws InputError ("standard input: ...") when --format is
  // missing, nothing came, or more came than the limit (scenes: --max-scene-size; models:
  // --max-stdin-size).
  StdinInput(const std::string& format, const Limits& limits);
  ~StdinInput();
  StdinInput(const StdinInput&) = delete;
  StdinInput& operator=(const StdinInput&) = delete;

  bool isScene() const { return format_ == ".json"; }
  const std::string& text() const { return text_; }  // a scene's JSON
  const std::string& path() const { return path_; }  // a model's bytes: /proc/self/fd/N
  const std::string& format() const { return format_; }  // ".ply", lower case

 private:
  std::string format_, text_, path_;
  int fd_ = -1;
};

// Messages of readers name the file they read: for standard input, "standard input".
std::string sayStandardInput(std::string message, const std::string& path);

}  // namespace illum::cli

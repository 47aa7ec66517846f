#include "stdin_input.h"

#include <illum/error.h>
#include <illum/file_names.h>

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

namespace illum::cli {
namespace {

std::string mib(std::uint64_t bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB"; }

}  // namespace

StdinInput::StdinInput(const std::string& format, const Limits& limits) {
  if (format.empty() || format.find_first_of("/\\. ") != std::string::npos)
    throw InputError("standard input (-) needs --format, the extension of what it holds (--format ply, --format json)");
  format_ = asciiLower("." + format);
  const std::uint64_t limit = isScene() ? limits.maxSceneBytes : limits.maxStdinBytes;
  const char* raise = isScene() ? "--max-scene-size" : "--max-stdin-size";
  if (!isScene()) {
    fd_ = ::memfd_create("illum-stdin", MFD_CLOEXEC);
    if (fd_ < 0) throw Error(std::string("cannot hold standard input in memory: ") + std::strerror(errno));
    path_ = "/proc/self/fd/" + std::to_string(fd_);
  }
  std::uint64_t total = 0;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(STDIN_FILENO, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(std::string("standard input: cannot read it: ") + std::strerror(errno));
    if (n == 0) break;
    total += std::uint64_t(n);
    if (total > limit)
      throw InputError("standard input: more than " + mib(limit) + " (raise it with " + raise + ")");
    if (isScene()) {
      text_.append(buffer, std::size_t(n));
      continue;
    }
    for (ssize_t done = 0; done < n;) {
      const ssize_t w = ::write(fd_, buffer + done, std::size_t(n - done));
      if (w < 0 && errno == EINTR) continue;
      if (w < 0) throw Error(std::string("cannot hold standard input in memory: ") + std::strerror(errno));
      done += w;
    }
  }
  if (total == 0)
    throw InputError("standard input is empty (expected a " + std::string(isScene() ? "scene" : format + " model") +
                     " piped in)");
}

StdinInput::~StdinInput() {
  if (fd_ >= 0) ::close(fd_);
}

std::string sayStandardInput(std::string message, const std::string& path) {
  if (path.empty()) return message;
  for (std::size_t at = message.find(path); at != std::string::npos; at = message.find(path, at))
    message.replace(at, path.size(), "standard input"), at += 14;
  return message;
}

}  // namespace illum::cli

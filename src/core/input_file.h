// The one gate every file illum reads itself passes (scene files, environment maps, standard
// input's bytes): regular files only, and no more bytes than a limit, checked before reading.
// A FIFO, a device or a socket would block a read for ever or never end: they are refused from
// what the open file descriptor is, not from its name, so a file swapped after a check cannot slip
// through. Model files are read by assimp in a child process; they pass checkRegularFile first.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace illum {

// What the bytes are, for messages: "scene file", "environment map".
struct InputFileKind {
  const char* noun;
  const char* raiseWith;  // the option that raises the size limit, or nullptr when it follows another
};

// The file's bytes. Throws InputError naming the file: "no such scene file", "not a regular file
// (a FIFO)", "the scene file is 70.0 MiB, more than the limit of 64 MiB (raise it with ...)".
std::string readInputFile(const std::filesystem::path& path, std::uint64_t maxBytes, const InputFileKind& kind);

// Refuses what is not a regular file (following symbolic links), or is missing, as above.
void checkRegularFile(const std::filesystem::path& path, const InputFileKind& kind);

// "a FIFO", "a folder", "a character device": what a file's mode says it is, for messages.
std::string describeFileType(unsigned mode);

}  // namespace illum

// Errors a user can act on. The CLI maps InputError to exit 2 and every other Error to exit 1.
#pragma once

#include <stdexcept>
#include <string>

namespace illum {

// Both are part of the library's API (lib/include/illum/illum.h): visible from libillum.so, so that
// a program catches them by type.
// A failure of the program or the system (cannot write a file, out of memory, ...): exit 1.
class __attribute__((visibility("default"))) Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad input from the user: a scene, a model file or a command-line value. Exit 2.
// The message says what and where (file, JSON path or line) and what was expected.
class __attribute__((visibility("default"))) InputError : public Error {
 public:
  using Error::Error;
};

}  // namespace illum

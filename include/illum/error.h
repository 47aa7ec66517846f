// Errors a user can act on. The CLI maps InputError to exit 2 and every other Error to exit 1.
#pragma once

#include <stdexcept>
#include <string>

namespace illum {

// A failure of the program or the system (cannot write a file, out of memory, ...): exit 1.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad input from the user: a scene, a model file or a command-line value. Exit 2.
// The message says what and where (file, JSON path or line) and what was expected.
class InputError : public Error {
 public:
  using Error::Error;
};

}  // namespace illum

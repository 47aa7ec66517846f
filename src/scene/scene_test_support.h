// What the scene reader's tests share: a scene parsed from text as if it were "scene.json" in the
// working folder, and the message of the error it throws.
#pragma once

#include <illum/error.h>
#include <illum/scene.h>

#include <string>

namespace illum::test {

inline Scene parse(const std::string& text) { return parseScene(text, "scene.json", "."); }

// The InputError's message, or "(no error)".
inline std::string errorOf(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace illum::test

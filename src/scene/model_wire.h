// An imported model as bytes, so that the isolated importer (a child process) can hand it back to
// illum: meshes (shared ones once), materials, textures (their 8-bit images), transforms, warnings.
// Both ends are the same binary, so values travel in their in-memory form; the reader still
// checks every length against what it was given.
#pragma once

#include <illum/import.h>

#include "core/isolate.h"

#include <cstdint>
#include <span>

namespace illum {

void writeModel(const ImportedModel& model, IsolatedWriter& out);
// Throws Error if the bytes are not a whole model.
ImportedModel readModel(std::span<const std::uint8_t> bytes);

}  // namespace illum

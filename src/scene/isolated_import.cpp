// importModel: the in-process importer run in a child with limits (core/isolate.h), and its
// outcomes turned into messages that say what happened and which option to raise.
#include <illum/import.h>

#include <illum/error.h>

#include "core/input_file.h"
#include "core/isolate.h"
#include "scene/model_wire.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <system_error>
#include <utility>

namespace illum {

PendingImport startImport(const std::filesystem::path& path, const ImportOptions& options) {
  PendingImport pending;
  pending.path_ = path;
  try {
    std::error_code ec;
    // The quick refusals need no child.
    checkRegularFile(path, {"model file", nullptr});
    const std::uint64_t size = std::filesystem::file_size(path, ec);
    if (ec || size == 0) throw InputError(path.string() + ": the model file is empty");

    IsolationLimits limits;
    limits.memoryBytes = std::size_t(options.limits.memoryBytesFor(size));
    limits.cpuSeconds = options.limits.secondsFor(size);
    limits.wallSeconds = limits.cpuSeconds * std::max(1.0, options.wallClockAllowance);
    limits.outputBytes = limits.memoryBytes;
    pending.memoryBytes_ = limits.memoryBytes;
    pending.cpuSeconds_ = limits.cpuSeconds;
    pending.child_ = std::make_unique<IsolatedChild>(
        startIsolated([path, options](IsolatedWriter& out) { writeModel(importModelInProcess(path, options), out); }, limits));
  } catch (...) {
    pending.error_ = std::current_exception();  // the import's error, reported by finish()
  }
  return pending;
}

PendingImport::PendingImport() = default;
PendingImport::PendingImport(PendingImport&&) noexcept = default;
PendingImport& PendingImport::operator=(PendingImport&&) noexcept = default;
PendingImport::~PendingImport() = default;

ImportedModel PendingImport::finish() {
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  if (!child_) throw Error("the model import was already finished");
  const IsolationOutcome outcome = std::exchange(child_, nullptr)->wait();
  const std::string mib = std::to_string(memoryBytes_ / (1 << 20) + (memoryBytes_ % (1 << 20) != 0));
  const std::string where = path_.string() + ": ";
  switch (outcome.kind) {
    case IsolationOutcome::Kind::Finished: return readModel({outcome.payload.begin(), outcome.payload.size()});
    case IsolationOutcome::Kind::Refused: throw InputError(outcome.message);
    case IsolationOutcome::Kind::Failed: throw InputError(where + "cannot read the model: " + outcome.message);
    case IsolationOutcome::Kind::OutOfMemory:
      throw InputError(where + "reading the model would need more than " + mib + " MiB (raise it with --max-memory)");
    case IsolationOutcome::Kind::OutputTooBig:
      throw InputError(where + "the model is larger than " + mib + " MiB (raise it with --max-memory)");
    case IsolationOutcome::Kind::TimedOut:
    {
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%.1f", cpuSeconds_);
      throw InputError(where + "reading the model took more than " + seconds + " s (raise it with --max-time)");
    }
    case IsolationOutcome::Kind::Crashed:
      throw InputError(where + "the importer crashed (" + outcome.message + "): the file is broken or not the format its name says");
  }
  throw InputError(where + "the importer ended in an unknown way");
}

ImportedModel importModel(const std::filesystem::path& path, const ImportOptions& options) {
  return startImport(path, options).finish();
}

}  // namespace illum

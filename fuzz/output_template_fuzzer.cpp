// libFuzzer target: batch output names against a scratch tree of models, links and folders. Any
// template, any input names and any --output-dir must give names that stay inside the output
// folder and never resolve to an input, or an InputError; nothing may crash.
// Input bytes: the template, the output folder, then input names, one a line.
#include <illum/error.h>

#include "batch_inputs.h"
#include "output_guard.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <system_error>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {
fs::path gScratch;
void removeScratch() {
  std::error_code ec;
  fs::remove_all(gScratch, ec);
}
}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // The scratch tree: models in folders, a link to one, an output folder with a dangling link. The
  // fuzzer works inside it (run.sh gives libFuzzer absolute paths).
  std::string scratch = (fs::temp_directory_path() / "illum-template-fuzz-XXXXXX").string();
  if (!::mkdtemp(scratch.data())) std::abort();
  gScratch = scratch;
  std::atexit(removeScratch);
  fs::current_path(scratch);
  fs::create_directories("models/a");
  fs::create_directories("models/c");
  fs::create_directories("out");
  for (const char* m : {"models/a/m.obj", "models/c/m.obj", "p.obj", "q.obj"}) std::ofstream(m) << "v 0 0 0\n";
  fs::create_symlink("p.obj", "link.obj");
  fs::create_symlink("../p.obj", "out/1.png");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::string pattern, dir, name;
  std::getline(in, pattern);
  std::getline(in, dir);
  std::vector<illum::cli::BatchJob> jobs;
  while (jobs.size() < 8 && std::getline(in, name))
    if (!name.empty() && name.find('\0') == std::string::npos)
      jobs.push_back({name, jobs.size(), jobs.size() % 2 ? "models" : ""});
  if (pattern.empty() || pattern.find('\0') != std::string::npos || dir.find('\0') != std::string::npos) return 0;
  const illum::cli::OutputPattern out{pattern, dir};
  try {
    illum::cli::OutputGuard guard;
    for (const auto& job : jobs) guard.protect(job.input);
    for (const auto& job : jobs)
      for (int frame : {0, 7}) {
        const std::string output = out.name(job, frame);
        if (!dir.empty()) {
          // Inside the output folder, lexically: the rule OutputPattern::name promises.
          const fs::path relative = fs::path(output).lexically_normal().lexically_relative(fs::path(dir).lexically_normal());
          if (relative.empty() || *relative.begin() == "..") std::abort();
        }
        guard.checkNotInput(output);
        for (const auto& other : jobs)  // a name that passed is no input, however it is reached
          if (fs::exists(other.input) && fs::exists(output) && fs::equivalent(other.input, output)) std::abort();
        guard.claim(output, job.input);
      }
  } catch (const illum::InputError&) {
  }
  return 0;
}

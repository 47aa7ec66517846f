// What a batch renders, and where each picture goes. The command line names files, folders
// (searched recursively for the model files assimp reads and .json scenes), glob patterns (`*`,
// `?`, `**` for any depth of folders: 'scans/**/*.ply') and `-` for standard input; they become
// one list of jobs in a fixed order, so that `--shard I/N` picks the same slice on every machine.
// Output names come from a template: {stem} {name} {ext} {dir} {n} {frame}, each with an optional
// zero-padded width ({n:03}, {frame:04}).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace illum::cli {

struct BatchJob {
  std::string input;   // a path, or "-" for standard input
  std::size_t index;   // in the whole, unsharded list (the template's {n} counts from 1)
  std::string root;    // the folder or pattern base it was found under; empty when named alone
};

// Expands `inputs` into jobs: files as given, folders and patterns in sorted order; a file named
// twice is rendered once. Throws InputError naming an input that matches nothing.
std::vector<BatchJob> expandInputs(const std::vector<std::string>& inputs);

// The I-th of N contiguous, equal slices of `jobs` ("I/N", I from 0): the jobs
// [⌊I·J/N⌋, ⌊(I+1)·J/N⌋). Throws InputError for a malformed or out-of-range shard.
std::vector<BatchJob> shardOf(const std::vector<BatchJob>& jobs, const std::string& shard);

// Whether `pattern` holds a field in braces, so that many pictures get different names.
bool isTemplate(const std::string& pattern);
// The output name for a job (and frame, for turntables). Throws InputError for an unknown field.
// `confined` (under --output-dir): {dir} is the input's folder relative to the folder or pattern
// it was found under, or for a file named alone its folder as given without a leading / or any
// .., so that no name leaves the output folder.
std::string expandTemplate(const std::string& pattern, const BatchJob& job, int frame = 0, bool confined = false);

// Where a batch writes: the -o template, inside --output-dir if one is given.
struct OutputPattern {
  std::string pattern;  // the template
  std::string dir;      // --output-dir, or empty
  // The file a job's frame goes to. Throws InputError when it would leave `dir`.
  std::string name(const BatchJob& job, int frame = 0) const;
};

}  // namespace illum::cli

// `illum compare`'s options and its sheet, which the library's compare() returns too.
#pragma once

#include <illum/sheet.h>

#include "scene_options.h"
#include "sheet_output.h"

#include <CLI/CLI.hpp>

#include <string>

namespace illum::cli {

struct CompareOptions {
  SceneOptions scene;
  std::string rows = "model", cols = "shading", diff;
  SheetOutput out{"compare.png", false, false, std::nullopt};
};

// The options of `illum compare` but its output's (-o, --quality, -q, --force), on `cmd`.
void addCompareOptions(CLI::App& cmd, CompareOptions& o);

// The sheet, its panels drawn: the scene under every pair of the axes' values. Model files are
// read through `models` (when given) as prepareScene reads them.
Sheet compareSheet(const CompareOptions& o, ModelCache* models = nullptr);

}  // namespace illum::cli

// What `illum compare` and `illum history` share: the panels' default size, the input's name for
// the title, and writing the sheet (with -v, where each panel landed).
#pragma once

#include <illum/sheet.h>

#include "scene_options.h"

#include <functional>
#include <optional>
#include <string>

namespace illum::cli {

// Unless the options size the pictures, panels are the scene's size scaled to 400 pixels wide (a
// model's 1000×600: 400×240); `first` is the scene as the options make it.
void defaultPanelSize(SceneOptions& o, const Scene& first);

// Refuses (InputError) a sheet whose panels hold more pixels together than --max-pixels allows
// one picture, before any is drawn: the sheet is one picture. `first` as above, with `o` sized.
void checkSheetPixels(std::size_t panels, const SceneOptions& o, const Scene& first);

// "the built-in scene", or the input file's name.
std::string inputName(const SceneOptions& o);

// A sheet shows its panels through one transform from radiance to bytes, the one the options give
// the sheet's scene (`first`): a path-traced panel of a preview takes it instead of its own ACES,
// so that panels compare. The title says which ("display: sRGB, no tone map").
std::string displayCaption(const Display& display);

struct SheetOutput {
  std::string path;
  bool force = false, quiet = false;
  std::optional<int> quality;
};
// -o, -q, --quality and --force.
void addSheetOutputOptions(CLI::App& cmd, SheetOutput& out);
// Refuses (InputError) an output name that is not a still 8-bit picture, before anything is drawn.
void checkSheetOutput(const SheetOutput& out);

// A panel's caption when it comes out black (every pixel black or the background): "black: " and
// why no light reaches what it shows (captions.h, whyUnlit); otherwise empty.
std::string unlitPanelCaption(const Image& image, const Scene& scene);

// Composes and writes the sheet; with verbose, one line per panel naming it by `describe(r, c)`.
void writeSheet(const Sheet& sheet, const SheetOutput& out, bool verbose,
                const std::function<std::string(std::size_t, std::size_t)>& describe);

}  // namespace illum::cli

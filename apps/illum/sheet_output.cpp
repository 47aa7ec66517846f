#include "sheet_output.h"

#include <illum/captions.h>
#include <illum/display.h>
#include <illum/error.h>
#include <illum/image.h>
#include <illum/output_file.h>

#include "cli_values.h"
#include "output_format.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace illum::cli {

constexpr int kDefaultPanelWidth = 400;

void defaultPanelSize(SceneOptions& o, const Scene& first) {
  if (o.width || o.height || !o.resolution.empty()) return;
  o.width = std::min(first.width, kDefaultPanelWidth);
  o.height = std::max(1, int(std::lround(double(first.height) * *o.width / first.width)));
}

void checkSheetPixels(std::size_t panels, const SceneOptions& o, const Scene& first) {
  const std::uint64_t w = std::uint64_t(o.width.value_or(first.width)), h = std::uint64_t(o.height.value_or(first.height));
  const std::uint64_t pixels = std::uint64_t(panels) * w * h;
  if (pixels > o.limits.maxPixels)
    throw InputError("the sheet would hold " + std::to_string(panels) + " panels of " + std::to_string(w) + "×" +
                     std::to_string(h) + " = " + withThousands(pixels) + " pixels, more than the limit of " +
                     withThousands(o.limits.maxPixels) + " for one picture (smaller panels with --resolution, or raise it "
                     "with --max-pixels)");
}

std::string displayCaption(const Display& display) {
  if (display.identity()) return "display: linear, as GL writes it";
  std::string text = display.encoding == Encoding::Srgb ? "display: sRGB" : "display: linear";
  text += display.toneMap == ToneMap::None ? ", no tone map" : ", " + std::string(toString(display.toneMap)) + " tone map";
  return text;
}

std::string inputName(const SceneOptions& o) {
  if (o.memoryScene) return "the scene given";
  return o.input.empty() ? "the built-in scene" : std::filesystem::path(o.input).filename().string();
}

void addSheetOutputOptions(CLI::App& cmd, SheetOutput& out) {
  cmd.add_option("-o,--output", out.path, "Output picture, written atomically: .png, .jpg/.jpeg, .webp (lossless) or .gif")
      ->capture_default_str();
  cmd.add_option("--quality", out.quality, "JPEG quality [90], or lossy WebP at this quality")->check(wholeRange(1, 100));
  cmd.add_flag("-q,--quiet", out.quiet, "Do not print the output's path on standard output");
  cmd.add_flag("--force", out.force, "Replace a read-only output file (its permissions are kept)");
}

void checkSheetOutput(const SheetOutput& out) {
  const OutputFormat format = outputFormatOf(out.path);
  if (format == OutputFormat::Exr || format == OutputFormat::Mp4)
    throw InputError("-o " + out.path + ": a sheet is one 8-bit picture: expected .png, .jpg, .webp or .gif");
  checkQuality(format, out.quality);
}

std::string unlitPanelCaption(const Image& image, const Scene& scene) {
  const std::array<std::uint8_t, 4> background = backgroundBytes(scene.background, scene.display);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    const std::uint8_t* p = &image.rgba[i];
    const bool isBackground = p[0] == background[0] && p[1] == background[1] && p[2] == background[2];
    if (!isBackground && std::max({p[0], p[1], p[2]}) > 2) return "";
  }
  const std::string why = whyUnlit(scene);
  return why.empty() ? "" : "black: " + why;
}

void writeSheet(const Sheet& sheet, const SheetOutput& out, bool verbose,
                const std::function<std::string(std::size_t, std::size_t)>& describe) {
  const Image image = composeSheet(sheet);
  if (verbose) {
    const SheetLayout layout = layoutSheet(sheet);
    for (std::size_t r = 0; r < sheet.panels.size(); ++r)
      for (std::size_t c = 0; c < sheet.panels[r].size(); ++c)
        std::fprintf(stderr, "illum: panel %zu,%zu (%s) at %d,%d, %dx%d%s%s\n", r, c, describe(r, c).c_str(),
                     layout.panelOrigin[r][c].first, layout.panelOrigin[r][c].second, sheet.panels[r][c].image.width,
                     sheet.panels[r][c].image.height, sheet.panels[r][c].caption.empty() ? "" : ": ",
                     sheet.panels[r][c].caption.c_str());
  }
  writeOutputFile(out.path, encodeStill(outputFormatOf(out.path), image, out.quality), OutputOptions{out.force});
  if (!out.quiet) std::printf("%s\n", out.path.c_str());
}

}  // namespace illum::cli

// What an output's name means: the format of its extension (case aside). Every picture illum
// writes goes through here, so that `-o picture.jpg` is a JPEG and `-o picture.tif`, a format
// illum does not write, is refused before anything is drawn.
#pragma once

#include <illum/image.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace illum::cli {

enum class OutputFormat { Png, Jpeg, Webp, Exr, Gif, Mp4 };

// The format `path` names: .png, .jpg or .jpeg, .webp, .exr, .gif, .mp4; standard output ("-")
// and a name without an extension are PNG. Anything else is an InputError naming `option`, the
// extension and the formats illum writes.
OutputFormat outputFormatOf(const std::string& path, const std::string& option = "-o");

// "PNG", "JPEG", "WebP", "EXR", "GIF" or "MP4".
const char* formatName(OutputFormat format);

// "--quality" is for JPEG and lossy WebP: refused (InputError) with any other format.
void checkQuality(OutputFormat format, std::optional<int> quality);

// One picture's bytes in a still format: PNG, JPEG (quality 90 unless given), WebP (lossless
// unless a quality is given), or a GIF of one frame whose palette keeps `background` exactly.
std::vector<std::uint8_t> encodeStill(OutputFormat format, const Image& image, std::optional<int> quality,
                                      std::optional<std::array<std::uint8_t, 3>> background = std::nullopt);

}  // namespace illum::cli

#include "output_format.h"

#include <illum/animation.h>
#include <illum/error.h>
#include <illum/file_names.h>

namespace illum::cli {

OutputFormat outputFormatOf(const std::string& path, const std::string& option) {
  if (path == "-") return OutputFormat::Png;
  const std::string ext = lowerExtension(path);
  if (ext.empty() || ext == ".png") return OutputFormat::Png;
  if (ext == ".jpg" || ext == ".jpeg") return OutputFormat::Jpeg;
  if (ext == ".webp") return OutputFormat::Webp;
  if (ext == ".exr") return OutputFormat::Exr;
  if (ext == ".gif") return OutputFormat::Gif;
  if (ext == ".mp4") return OutputFormat::Mp4;
  throw InputError(option + " " + path + ": illum does not write " + ext +
                   " files; expected .png, .jpg (or .jpeg), .webp, .exr, .gif, or .mp4 for an animation");
}

const char* formatName(OutputFormat format) {
  switch (format) {
    case OutputFormat::Png: return "PNG";
    case OutputFormat::Jpeg: return "JPEG";
    case OutputFormat::Webp: return "WebP";
    case OutputFormat::Exr: return "EXR";
    case OutputFormat::Gif: return "GIF";
    case OutputFormat::Mp4: return "MP4";
  }
  return "?";
}

void checkQuality(OutputFormat format, std::optional<int> quality) {
  if (quality && format != OutputFormat::Jpeg && format != OutputFormat::Webp)
    throw InputError("--quality: only .jpg and .webp outputs have one (PNG, GIF and OpenEXR are lossless)");
}

std::vector<std::uint8_t> encodeStill(OutputFormat format, const Image& image, std::optional<int> quality,
                                      std::optional<std::array<std::uint8_t, 3>> background) {
  switch (format) {
    case OutputFormat::Png: return encodePng(image);
    case OutputFormat::Jpeg: return encodeJpeg(image, quality.value_or(90));
    case OutputFormat::Webp: return encodeWebp(image, quality);
    case OutputFormat::Gif: {
      const std::unique_ptr<AnimationEncoder> gif = makeGifEncoder(image.width, image.height, 0, background);
      gif->add(image);
      return gif->finish();
    }
    case OutputFormat::Exr:
    case OutputFormat::Mp4: break;
  }
  throw Error("encodeStill: not a still format");
}

}  // namespace illum::cli

// `illum render [SCENE.json | MODEL] [-o OUT.png]`: render a scene file, a model file (any format
// assimp reads, framed and lit automatically), or with neither the built-in scene, to PNG.
#include <illum/display.h>
#include <illum/error.h>
#include <illum/image.h>
#include <illum/output_file.h>
#include <illum/render.h>
#include <illum/scene.h>
#include <illum/file_names.h>

#include "cli_values.h"
#include "commands.h"
#include "output_guard.h"
#include "pixel_report.h"
#include "output_format.h"
#include "render_options.h"
#include "scene_options.h"
#include "stdin_input.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <cstdio>
#include <memory>
#include <mutex>
#include <optional>
#include <limits>
#include <utility>
#include <cmath>

namespace illum::cli {
namespace {

using Clock = std::chrono::steady_clock;


// Whether `path` names the file standard output already goes to (/dev/stdout, /proc/self/fd/1, or
// the file the shell redirected to): then the path is not printed after the PNG.
bool isStandardOutput(const std::string& path) {
  struct stat out{}, target{};
  return ::fstat(STDOUT_FILENO, &out) == 0 && ::stat(path.c_str(), &target) == 0 && out.st_dev == target.st_dev &&
         out.st_ino == target.st_ino;
}

// "illum: path tracing 42 % · 3.1 s · about 4.3 s left", redrawn in place at most ten times a second.
class ProgressLine {
 public:
  void update(double fraction) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto now = Clock::now();
    if (fraction < 1 && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    std::fprintf(stderr, "\rillum: path tracing %3.0f %% · %.1f s · about %.1f s left   ", fraction * 100, elapsed,
                 fraction > 0 ? elapsed * (1 - fraction) / fraction : 0.0);
    shown_ = true;
  }
  void finish() {
    if (shown_) std::fprintf(stderr, "\n");
  }

 private:
  std::mutex mutex_;
  Clock::time_point start_ = Clock::now(), last_{};
  bool shown_ = false;
};

// "OBJECT:x,y,z" (a point in the object's own coordinates) or "OBJECT" (the centre of its
// bounds): the pixel it lands on.
std::pair<int, int> pixelOfPoint(const Scene& scene, const std::string& text) {
  const auto colon = text.find(':');
  const std::size_t n = std::size_t(parseInteger("--debug-point", text.substr(0, colon), 0, 1 << 30));
  if (n >= scene.objects.size())
    throw InputError("--debug-point " + text + ": the scene has " + std::to_string(scene.objects.size()) +
                     " objects (0 .. " + std::to_string(scene.objects.size() - 1) + ")");
  const Object& object = scene.objects[n];
  Vec3 local(0);
  if (colon != std::string::npos) {
    local = parseVec3("--debug-point", text.substr(colon + 1));
  } else {
    Vec3 lo(std::numeric_limits<Real>::max()), hi(std::numeric_limits<Real>::lowest());
    for (const Vec3& p : object.mesh->positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    if (!object.mesh->positions.empty()) local = (lo + hi) / Real(2);
  }
  const Vec4 clip = scene.camera.clipFromView(Real(scene.width) / Real(scene.height)) * scene.camera.viewFromWorld() *
                    object.worldFromObject * Vec4(local, 1);
  if (!(clip.w > 0)) throw InputError("--debug-point " + text + ": the point is behind the camera");
  const Real px = (clip.x / clip.w + 1) / 2 * Real(scene.width), py = (1 - clip.y / clip.w) / 2 * Real(scene.height);
  if (!(px >= 0 && py >= 0 && px < Real(scene.width) && py < Real(scene.height)))
    throw InputError("--debug-point " + text + ": the point is outside the picture (at pixel " +
                     std::to_string(int(std::floor(px))) + ", " + std::to_string(int(std::floor(py))) + ")");
  return {int(px), int(py)};
}

// A ring of radius 6 around (x, y), magenta over a dark edge, the pixel itself untouched.
void markPixel(Image& image, int x, int y) {
  for (int dy = -8; dy <= 8; ++dy)
    for (int dx = -8; dx <= 8; ++dx) {
      const int px = x + dx, py = y + dy;
      if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
      const double d = std::sqrt(double(dx * dx + dy * dy));
      std::uint8_t* p = image.pixel(px, py);
      if (d >= 4.5 && d < 6.5) p[0] = 255, p[1] = 0, p[2] = 255, p[3] = 255;
      else if ((d >= 3.5 && d < 4.5) || (d >= 6.5 && d < 7.5)) p[0] = p[1] = p[2] = 0, p[3] = 255;
    }
}

int renderPicture(const RenderOptions& o) {
  // What the output's name means, before anything is read or drawn.
  const OutputFormat format = outputFormatOf(o.output);
  checkQuality(format, o.quality);
  if (format == OutputFormat::Mp4)
    throw InputError("-o " + o.output + ": an .mp4 is a video of several frames: add --turntable N or --orbit-light N");
  if (o.bitDepth == 16 && format != OutputFormat::Png)
    throw InputError("--bit-depth 16: PNG only (OpenEXR is 32-bit float already; JPEG, WebP and GIF are 8-bit)");
  const ThreadLimit limit(o.scene);
  double loadMs = 0;
  Scene scene = prepareScene(o.scene, &loadMs);
  if (o.output != "-") checkOutputsSpareScene(scene, {o.output});
  if (!o.saveScene.empty()) checkOutputsSpareScene(scene, {o.saveScene});
  // The scene as a file, made before anything is drawn: one that cannot be written stops the command.
  const std::string sceneFile = o.saveScene.empty() ? std::string() : sceneJson(scene);
  const auto loaded = Clock::now();
  RenderStats stats;
  std::optional<PixelProbe> probe;
  if ((!o.debugPixel.empty() || !o.debugPoint.empty()) && o.output == "-")
    throw InputError(std::string(o.debugPixel.empty() ? "--debug-point" : "--debug-pixel") +
                     ": its report goes to standard output, so it cannot go with -o -");
  if (!o.debugPixel.empty() && !o.debugPoint.empty()) throw InputError("--debug-pixel and --debug-point: one pixel at a time");
  if (o.markPixel && o.debugPixel.empty() && o.debugPoint.empty())
    throw InputError("--mark-pixel: marks the pixel --debug-pixel or --debug-point reports: give one of them");
  if (!o.debugPixel.empty()) {
    const auto comma = o.debugPixel.find(',');
    if (comma == std::string::npos) throw InputError("--debug-pixel: expected x,y, got \"" + o.debugPixel + "\"");
    probe.emplace();
    probe->x = parseInteger("--debug-pixel", o.debugPixel.substr(0, comma), 0, scene.width - 1);
    probe->y = parseInteger("--debug-pixel", o.debugPixel.substr(comma + 1), 0, scene.height - 1);
  }
  if (!o.debugPoint.empty()) {
    probe.emplace();
    const auto [x, y] = pixelOfPoint(scene, o.debugPoint);
    probe->x = x;
    probe->y = y;
  }
  // A .exr output gets the linear values, unclamped (OpenEXR); the others the picture's bytes.
  const bool exr = format == OutputFormat::Exr;
  if (o.bitDepth != 8 && o.bitDepth != 16) throw InputError("--bit-depth: expected 8 or 16, got " + std::to_string(o.bitDepth));
  const bool deep = o.bitDepth == 16;
  FloatImage linear;
  Renderer renderer;
  // A path tracer's picture takes a while: on a terminal, a line on stderr says how far it is.
  ProgressLine progressLine;
  if (scene.renderer == RendererKind::Path && !o.quiet && ::isatty(STDERR_FILENO))
    renderer.onProgress([&](double fraction) { progressLine.update(fraction); });
  Image image;
  renderer.render(scene, image, &stats, probe ? &*probe : nullptr, exr || deep ? &linear : nullptr);
  progressLine.finish();
  const auto rendered = Clock::now();
  auto encoded = rendered;
  if (stats.pixelsDrawn == 0 && !scene.objects.empty())
    std::fprintf(stderr, "illum: warning: the picture shows only the background: nothing drawn is visible (are the "
                         "objects outside the view, behind the camera, transparent or of the background's colour?)\n");
  if (stats.labelsSkipped)
    std::fprintf(stderr, "illum: warning: labels left out: the font /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf "
                         "(Debian package fonts-dejavu-core) is missing\n");
  const bool toStdout = o.output == "-";
  if (toStdout) {
    // `-o -` streams the PNG, for pipelines that make thumbnails.
    const std::vector<std::uint8_t> png = deep ? encodePng16(image.width, image.height, picture16(scene, linear))
                                               : encodePng(image);
    encoded = Clock::now();
    if (std::fwrite(png.data(), 1, png.size(), stdout) != png.size() || std::fflush(stdout) != 0)
      throw Error("cannot write the PNG to standard output");
  } else {
    if (probe && o.markPixel) markPixel(image, probe->x, probe->y);
    const std::array<std::uint8_t, 4> background = backgroundBytes(scene.background, scene.display);
    const std::vector<std::uint8_t> bytes =
        exr    ? encodeExr(linear)
        : deep ? encodePng16(image.width, image.height, picture16(scene, linear))
               : encodeStill(format, image, o.quality, std::array{background[0], background[1], background[2]});
    encoded = Clock::now();
    writeOutputFile(o.output, bytes, OutputOptions{o.force});
  }
  if (!o.saveScene.empty())
    writeOutputFile(o.saveScene, std::vector<std::uint8_t>(sceneFile.begin(), sceneFile.end()), OutputOptions{o.force});
  const auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  if (o.scene.verbose && scene.renderer != RendererKind::Raster) {
    std::fprintf(stderr,
                 "illum: loaded in %.1f ms; ray traced (%s) %dx%d in %.1f ms (%s triangles, BVH built in %.1f ms; "
                 "%s primary, %s reflected/refracted, %s shadow rays; %d threads); %s encoded in %.1f ms; "
                 "peak memory %.0f MiB\n",
                 loadMs, std::string(toString(scene.renderer)).c_str(), scene.width, scene.height, ms(loaded, rendered),
                 withThousands(stats.trianglesIn).c_str(), stats.bvhMs, withThousands(stats.primaryRays).c_str(),
                 withThousands(stats.secondaryRays).c_str(), withThousands(stats.shadowRays).c_str(), limit.threads(),
                 formatName(format), ms(rendered, encoded), peakMemoryMiB());
  } else if (o.scene.verbose) {
    std::fprintf(stderr,
                 "illum: loaded in %.1f ms; rendered %dx%d in %.1f ms (%s triangles in, %s drawn, %s fragments shaded; "
                 "%d threads, %s); %s encoded in %.1f ms; peak memory %.0f MiB\n",
                 loadMs, scene.width, scene.height, ms(loaded, rendered),
                 withThousands(stats.trianglesIn).c_str(), withThousands(stats.trianglesDrawn).c_str(),
                 withThousands(stats.fragmentsShaded).c_str(), limit.threads(), simdTarget(), formatName(format),
                 ms(rendered, encoded), peakMemoryMiB());
  }
  if (toStdout) return 0;
  if (!o.quiet && !isStandardOutput(o.output)) std::printf("%s\n", o.output.c_str());
  if (probe) {
    if (!o.debugPoint.empty()) std::printf("--debug-point %s lands on pixel (%d, %d)\n", o.debugPoint.c_str(), probe->x, probe->y);
    const PixelChain chain = tracePixelChain(scene, probe->x, probe->y);
    printPixelReport(scene, *probe, image, stdout, &chain);
    if (o.markPixel) std::printf("  (marked in the picture by a ring around the pixel, which leaves the pixel itself as it is)\n");
  }
  return 0;
}

}  // namespace

// One picture, or a batch (batch.cpp).
int runRender(RenderOptions o) {
  std::vector<BatchJob> jobs;
  if (!o.inputs.empty()) jobs = expandInputs(o.inputs);
  if (std::count_if(jobs.begin(), jobs.end(), [](const BatchJob& j) { return j.input == "-"; }) > 1)
    throw InputError("-: standard input can be read once");
  if (isBatch(o)) {
    if (!o.saveScene.empty()) throw InputError("--save-scene: writes the scene of one picture, not of a batch");
    // No input: the built-in scene's turntable (or orbit) is a batch of one job too.
    if (o.inputs.empty()) jobs.push_back({"", 0, ""});
    return runBatch(o, jobs);
  }
  if (o.output.empty()) o.output = "illum.png";
  o.scene.input = jobs.empty() ? "" : jobs[0].input;
  if (o.scene.input == "-") o.scene.stdinInput = std::make_shared<const StdinInput>(o.format, o.scene.limits);
  return renderPicture(o);
}


Command addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand(
      "render", "Render scene files, model files, folders of them, or with none the built-in scene (PNG, EXR, GIF, WebP, MP4)");
  cmd->footer(
      "A .json input is a scene file (docs/scene-format.md); anything else is a model file read by\n"
      "assimp (OBJ+MTL, PLY, STL, glTF/GLB, FBX, Collada, 3DS, ...), framed and lit automatically.\n"
      "Colours are R,G,B in [0,1] or #rrggbb; both are written to the image as they are (docs/cli.md).");
  addSceneOptions(*cmd, o->scene, &o->inputs);
  cmd->add_option("-o,--output", o->output,
                  "Output picture [illum.png]: its extension says its format, .png, .jpg/.jpeg, .webp (lossless), .gif, "
                  "or .exr (linear, unclamped); written atomically; - for standard output (PNG). Many inputs: a template "
                  "[{stem}.png] of {stem} {name} {ext} {dir} {n} {frame}; turntables: .gif, .webp, .mp4 (ffmpeg) or "
                  "pictures named with {frame}");
  cmd->add_option("--quality", o->quality, "JPEG quality [90], or lossy WebP at this quality (WebP is lossless without it)")
      ->check(wholeRange(1, 100));
  cmd->add_option("--output-dir", o->outputDir, "Many inputs: the folder the output names are in (made if missing)");
  cmd->add_option("--format", o->format, "What standard input (-) holds: its extension (ply, stl, obj, glb, json, ...)");
  cmd->add_option("--turntable", o->turntable, "Render N frames with the camera orbiting the up axis")
      ->check(wholeRange(1, kMaxFrames));
  cmd->add_option("--orbit-light", o->orbitLight, "Render N frames with the key light orbiting the up axis")
      ->check(wholeRange(1, kMaxFrames));
  cmd->add_option("--fps", o->fps, "Frames per second of .gif, .webp and .mp4 outputs")
      ->check(wholeRange(1, 120))
      ->capture_default_str();
  cmd->add_option("--shard", o->shard, "I/N: render only the I-th (from 0) of N equal slices of the inputs (job arrays)");
  cmd->add_flag("--skip-existing", o->skipExisting, "Skip inputs whose outputs exist (resume a batch)");
  cmd->add_flag("--fail-fast", o->failFast, "Stop a batch at the first input that fails");
  cmd->add_flag("--progress", o->progress, "Show the batch's progress bar even when stderr is not a terminal");
  cmd->add_flag("--json", o->json, "Print one JSON line per input (input, output, times, triangles, warnings, error)");
  cmd->add_flag("-q,--quiet", o->quiet, "Do not print the output's path on standard output");
  cmd->add_option("--bit-depth", o->bitDepth, "PNG bits per channel: 8, or 16 (the display encoding at full precision)")
      ->capture_default_str();
  cmd->add_flag("--force", o->force, "Replace a read-only output file (its permissions are kept)");
  cmd->add_option("--save-scene", o->saveScene,
                  "Also write the scene drawn as a scene file (.json) that `illum render` draws to the same bytes: "
                  "a model preview becomes a scene to edit");
  cmd->add_option("--debug-pixel", o->debugPixel,
                  "Print every term of the lighting equation at pixel x,y (0,0 top-left), and every step from the "
                  "fragment to the file's bytes");
  cmd->add_option("--debug-point", o->debugPoint,
                  "As --debug-pixel, at the pixel where a point of an object lands: OBJECT:x,y,z (in the object's own "
                  "coordinates), or OBJECT alone for the centre of its bounds");
  cmd->add_flag("--mark-pixel", o->markPixel, "Draw a ring around the pixel --debug-pixel or --debug-point reports");
  return [o] { return runRender(*o); };
}

}  // namespace illum::cli

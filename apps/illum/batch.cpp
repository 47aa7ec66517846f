// `illum render` over many inputs in one process: a folder of models to thumbnails, a turntable
// to a GIF. Jobs run in order, each with every core; a failing input is reported and the rest go
// on (unless --fail-fast); every picture is written atomically; Ctrl-C stops after the picture in
// hand; --shard I/N renders one slice of the list, for cluster job arrays.
#include <illum/animation.h>
#include <illum/display.h>
#include <illum/error.h>
#include <illum/image.h>
#include <illum/output_file.h>
#include <illum/render.h>
#include <illum/file_names.h>

#include "output_guard.h"
#include "output_format.h"
#include "render_options.h"
#include "stdin_input.h"

#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <deque>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <unistd.h>

namespace illum::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::atomic<bool> gInterrupted{false};

// The first Ctrl-C asks the batch to stop after the picture in hand; a second one stops at once.
void onInterrupt(int) {
  gInterrupted = true;
  std::signal(SIGINT, SIG_DFL);
}

// Whether a job's frames go into one file: an .mp4 always, a .gif or .webp when there are several
// (one frame of them is a still picture).
bool isAnimation(OutputFormat format, int frames) {
  return format == OutputFormat::Mp4 || (frames > 1 && (format == OutputFormat::Gif || format == OutputFormat::Webp));
}

bool onPath(const char* program) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const fs::path candidate = fs::path(dirs.substr(start, end - start)) / program;
    if (::access(candidate.c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

// MP4 through ffmpeg, when it is installed: raw RGBA frames down a pipe as they are drawn, into a
// file in a private temporary folder (mkdtemp: no name another user can plant), whose bytes are
// then written in place of the output as every output is.
class Mp4Encoder final : public AnimationEncoder {
 public:
  Mp4Encoder(int width, int height, int fps) : width_(width), height_(height) {
    if (!onPath("ffmpeg"))
      throw InputError("an .mp4 output needs ffmpeg on the PATH (apt-get install ffmpeg); .gif and .webp need nothing");
    std::string folder = (fs::temp_directory_path() / "illum-mp4-XXXXXX").string();
    if (!::mkdtemp(folder.data())) throw Error("cannot make a temporary folder for ffmpeg in " + fs::temp_directory_path().string());
    folder_ = folder;
    const int w = width & ~1, h = height & ~1;  // H.264's 4:2:0 wants even sizes
    const std::string command = "ffmpeg -loglevel error -y -f rawvideo -pixel_format rgba -video_size " +
                                std::to_string(width) + "x" + std::to_string(height) + " -framerate " + std::to_string(fps) +
                                " -i - -vf crop=" + std::to_string(w) + ":" + std::to_string(h) +
                                ":0:0 -pix_fmt yuv420p -movflags +faststart '" + (folder_ / "out.mp4").string() + "'";
    pipe_ = ::popen(command.c_str(), "w");
    if (!pipe_) throw Error("cannot start ffmpeg");
  }
  ~Mp4Encoder() override {
    if (pipe_) ::pclose(pipe_);
    std::error_code ec;
    fs::remove_all(folder_, ec);
  }
  void add(const Image& frame) override {
    if (frame.width != width_ || frame.height != height_ || std::fwrite(frame.rgba.data(), 1, frame.rgba.size(), pipe_) != frame.rgba.size())
      throw Error("ffmpeg could not encode the MP4 (it stopped taking frames)");
  }
  std::vector<std::uint8_t> finish() override {
    const int status = ::pclose(std::exchange(pipe_, nullptr));
    std::ifstream in(folder_ / "out.mp4", std::ios::binary);
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (status != 0 || bytes.empty()) throw Error("ffmpeg could not encode the MP4");
    return bytes;
  }

 private:
  int width_, height_;
  fs::path folder_;
  FILE* pipe_ = nullptr;
};

std::unique_ptr<AnimationEncoder> makeEncoder(OutputFormat format, const Image& first, int fps,
                                             const std::array<std::uint8_t, 3>& background) {
  const int delay = 1000 / std::max(1, fps);
  switch (format) {
    case OutputFormat::Gif: return makeGifEncoder(first.width, first.height, delay, background);
    case OutputFormat::Webp: return makeWebpEncoder(first.width, first.height, delay);
    case OutputFormat::Mp4: return std::make_unique<Mp4Encoder>(first.width, first.height, fps);
    default: break;
  }
  throw Error(std::string("a ") + formatName(format) + " is not an animation");
}

// Turns the camera (turntable) or the first light (orbit) about the camera's up axis through the
// point it looks at, by `degrees`.
void orbit(Scene& scene, Real degrees, bool light) {
  const Vec3 axis = glm::normalize(scene.camera.up), centre = scene.camera.center;
  const Mat4 turn = glm::translate(Mat4(1), centre) * glm::rotate(Mat4(1), glm::radians(degrees), axis) *
                    glm::translate(Mat4(1), -centre);
  if (!light) {
    scene.camera.eye = Vec3(turn * Vec4(scene.camera.eye, 1));
    return;
  }
  if (scene.lights.empty()) return;
  Light& l = scene.lights.front();
  l.position = l.position.w == 0 ? Vec4(Mat3(turn) * Vec3(l.position), 0) : turn * (l.position / l.position.w);
  l.spotDirection = Mat3(turn) * l.spotDirection;
}

// "illum: [########------] 12/40 · 3.1 pictures/s · about 9 s left · 1 failed", redrawn in place.
class BatchProgress {
 public:
  BatchProgress(std::size_t total, bool shown) : total_(total), shown_(shown) {}
  void update(std::size_t done, std::size_t failed) {
    if (!shown_) return;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    const double rate = elapsed > 0 ? double(done) / elapsed : 0;
    const int width = 24, filled = total_ ? int(width * done / total_) : width;
    std::string bar(std::size_t(filled), '#');
    bar.append(std::size_t(width - filled), '-');
    std::fprintf(stderr, "\r\033[Killum: [%s] %zu/%zu · %.1f pictures/s", bar.c_str(), done, total_, rate);
    if (rate > 0 && done < total_) std::fprintf(stderr, " · about %.0f s left", double(total_ - done) / rate);
    if (failed) std::fprintf(stderr, " · %zu failed", failed);
    std::fflush(stderr);
    drawn_ = true;
  }
  // A line of its own (an error) above the bar.
  void say(const std::string& line) {
    if (drawn_) std::fprintf(stderr, "\r\033[K");
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  void finish() {
    if (drawn_) std::fprintf(stderr, "\n");
  }

 private:
  std::size_t total_;
  bool shown_, drawn_ = false;
  Clock::time_point start_ = Clock::now();
};

struct JobResult {
  std::vector<std::string> outputs;
  std::vector<std::string> warnings;
  std::size_t triangles = 0, points = 0, lines = 0;
  double loadMs = 0, renderMs = 0, encodeMs = 0;
  bool skipped = false;
  int framesDone = 0, framesWanted = 1;  // less than wanted: Ctrl-C cut the job short, nothing of it kept
};

double msBetween(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

// The files a job writes: one animation, or one picture per frame.
std::vector<std::string> outputNames(const RenderOptions& o, const BatchJob& job, const OutputPattern& out) {
  const int frames = std::max({1, o.turntable, o.orbitLight});
  const bool animation = isAnimation(outputFormatOf(out.name(job, 0)), frames);
  std::vector<std::string> names;
  for (int f = 0; f < (animation ? 1 : frames); ++f) names.push_back(out.name(job, f));
  return names;
}

// --skip-existing: every file the job would write is there and not empty.
bool alreadyDone(const RenderOptions& o, const std::vector<std::string>& names) {
  return o.skipExisting && std::all_of(names.begin(), names.end(), [](const std::string& n) {
           std::error_code ec;
           return fs::is_regular_file(n, ec) && fs::file_size(n, ec) > 0;
         });
}

// A job's model file read ahead, in its isolated child, while the job before it is drawn: the
// reading (one core) and the drawing (every core) overlap. The child is started here, on the main
// thread between renders, as forking safely requires.
struct ReadAhead {
  std::size_t job = 0;  // index in the job list
  std::string key;      // modelCacheKey
  PendingImport model;
};

// Starts reading jobs[index]'s model, if it is a model file worth reading ahead; whatever goes
// wrong here is left for the job itself to meet and report.
std::optional<ReadAhead> startReadAhead(const RenderOptions& o, const std::vector<BatchJob>& jobs, std::size_t index,
                                        const OutputPattern& out, int threads) {
  // A big model is read in its turn: several read ahead would be held in memory at once.
  constexpr std::uintmax_t kLargestReadAhead = std::uintmax_t(64) << 20;
  const BatchJob& job = jobs[index];
  try {
    std::error_code ec;
    if (job.input == "-" || !isModelInput(job.input) || fs::file_size(job.input, ec) > kLargestReadAhead || ec ||
        alreadyDone(o, outputNames(o, job, out)))
      return std::nullopt;
    SceneOptions so = o.scene;
    so.input = job.input;
    ReadAhead ahead;
    ahead.job = index;
    ahead.key = modelCacheKey(so);
    // Sharing the cores with the drawing, the reader is allowed that much more wall-clock time
    // (its CPU time is held to the same limit).
    ahead.model = startModelImport(so, double(threads + 1));
    return ahead;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

JobResult renderJob(const RenderOptions& o, const BatchJob& job, const std::string& input, const OutputPattern& out,
                    Renderer& renderer, ModelCache& cache, std::optional<ReadAhead> ahead) {
  JobResult result;
  const int frames = std::max({1, o.turntable, o.orbitLight});
  const OutputFormat format = outputFormatOf(out.name(job, 0));
  const bool animation = isAnimation(format, frames);
  if (o.bitDepth == 16 && format != OutputFormat::Png)
    throw InputError("--bit-depth 16: PNG only (OpenEXR is 32-bit float already; JPEG, WebP and GIF are 8-bit)");
  if (frames > 1 && !animation && out.pattern.find("{frame") == std::string::npos)
    throw InputError("-o: " + std::to_string(frames) + " frames need {frame} in the name (\"{stem}_{frame:03}.png\"), or a "
                     ".gif, .webp or .mp4 output");
  const std::vector<std::string> names = outputNames(o, job, out);
  if (alreadyDone(o, names)) {
    result.outputs = names;
    result.skipped = true;
    return result;
  }
  // A model file is this job's alone (its frames share it); the models scene files name are kept
  // for the next scene, which may name them too.
  cache.models.clear();
  if (ahead)  // its error, if any, is this job's
    cache.models[ahead->key] = {std::make_shared<const ImportedModel>(ahead->model.finish()), false};
  std::unique_ptr<AnimationEncoder> encoder;  // frames go to it as they are drawn
  result.framesWanted = frames;
  for (int f = 0; f < frames && !(f > 0 && gInterrupted); ++f) {
    SceneOptions so = o.scene;
    so.input = input;
    const Real degrees = Real(360) * Real(f) / Real(frames);
    // A model's light rig follows its camera: its turntable turns the camera by its azimuth.
    const bool model = input == "-" ? !o.scene.stdinInput->isScene()
                                    : !input.empty() && !isSceneFileName(input);
    if (o.turntable && model) so.azimuth = so.azimuth.value_or(35) + double(degrees);
    const auto start = Clock::now();
    double loadMs = 0;
    Scene scene = prepareScene(so, &loadMs, &cache, f == 0 ? &result.warnings : nullptr);
    if (f == 0) checkOutputsSpareScene(scene, names);
    if (o.turntable && !model) orbit(scene, degrees, false);
    if (o.orbitLight) orbit(scene, degrees, true);
    const auto loaded = Clock::now();
    Image image;
    RenderStats stats;
    // OpenEXR and 16-bit PNG take the linear values; the rest the picture's bytes.
    const bool linearOut = !animation && (format == OutputFormat::Exr || o.bitDepth == 16);
    FloatImage linear;
    renderer.render(scene, image, &stats, nullptr, linearOut ? &linear : nullptr);
    const auto rendered = Clock::now();
    result.renderMs += msBetween(loaded, rendered);
    const std::array<std::uint8_t, 4> bg = backgroundBytes(scene.background, scene.display);
    const std::array<std::uint8_t, 3> background{bg[0], bg[1], bg[2]};
    if (animation) {
      if (!encoder) encoder = makeEncoder(format, image, o.fps, background);
      encoder->add(image);
    } else {
      const std::vector<std::uint8_t> bytes =
          format == OutputFormat::Exr ? encodeExr(linear)
          : o.bitDepth == 16          ? encodePng16(image.width, image.height, picture16(scene, linear))
                                      : encodeStill(format, image, o.quality, background);
      writeOutputFile(names[std::size_t(f)], bytes, OutputOptions{o.force});
    }
    ++result.framesDone;
    result.encodeMs += msBetween(rendered, Clock::now());
    result.loadMs += msBetween(start, loaded);
    result.triangles = stats.trianglesIn;
    result.points = result.lines = 0;
    for (const Object& object : scene.objects)
      result.points += object.mesh->pointCount(), result.lines += object.mesh->lineCount();
  }
  if (result.framesDone < frames) {
    // Cut short: a sequence is all its frames or none, as an animation is one file or none.
    std::error_code ec;
    if (!animation)
      for (int f = 0; f < result.framesDone; ++f) fs::remove(names[std::size_t(f)], ec);
    return result;
  }
  if (animation) {
    const auto start = Clock::now();
    writeOutputFile(names[0], encoder->finish(), OutputOptions{o.force});
    result.encodeMs += msBetween(start, Clock::now());
  }
  result.outputs = names;
  return result;
}

}  // namespace

bool isBatch(const RenderOptions& o) {
  if (o.inputs.size() > 1 || !o.shard.empty() || o.turntable > 0 || o.orbitLight > 0 || !o.outputDir.empty() || o.json ||
      o.skipExisting || isTemplate(o.output))
    return true;
  for (const std::string& in : o.inputs) {
    std::error_code ec;
    if (in != "-" && (fs::is_directory(in, ec) || (in.find_first_of("*?[") != std::string::npos && !fs::exists(in, ec))))
      return true;
  }
  return false;
}

int runBatch(const RenderOptions& o, const std::vector<BatchJob>& allJobs) {
  if (!o.debugPixel.empty()) throw InputError("--debug-pixel: reports one picture; render one input for it");
  if (!o.debugPoint.empty()) throw InputError("--debug-point: reports one picture; render one input for it");
  if (o.output == "-") throw InputError("-o -: standard output takes one picture; render one input for it");
  if (o.turntable && o.orbitLight) throw InputError("--turntable and --orbit-light: expected one of them");
  if (o.bitDepth != 8 && o.bitDepth != 16) throw InputError("--bit-depth: expected 8 or 16, got " + std::to_string(o.bitDepth));
  const std::vector<BatchJob> jobs = o.shard.empty() ? allJobs : shardOf(allJobs, o.shard);
  const bool frames = o.turntable > 0 || o.orbitLight > 0;
  OutputPattern out{o.output.empty() ? (frames ? "{stem}.gif" : "{stem}.png") : o.output, o.outputDir};
  if (!isTemplate(out.pattern) && allJobs.size() > 1)
    throw InputError("-o " + out.pattern + ": " + std::to_string(allJobs.size()) +
                     " inputs need different names: use a template such as '{stem}.png' (fields {stem} {name} {ext} {dir} {n} {frame})");
  // What the outputs' names mean, before anything is drawn (a template's {ext} is each job's).
  if (out.pattern.find("{ext}") == std::string::npos) checkQuality(outputFormatOf(out.pattern), o.quality);
  if (!o.outputDir.empty() && fs::path(out.pattern).is_absolute())
    throw InputError("-o " + out.pattern + " and --output-dir " + o.outputDir +
                     ": an absolute output name ignores the output folder; expected one of them");
  // Every output named before anything is drawn: no input is written over, and two inputs may not
  // write one file (nor one through a link to another's).
  OutputGuard guard;
  for (const BatchJob& job : allJobs)
    if (job.input != "-" && !job.input.empty()) guard.protect(job.input);
  for (const BatchJob& job : allJobs)
    for (const std::string& name : outputNames(o, job, out)) {
      guard.checkNotInput(name);
      guard.claim(name, job.input);
    }
  std::shared_ptr<const StdinInput> piped;
  for (const BatchJob& job : jobs)
    if (job.input == "-") piped = std::make_shared<const StdinInput>(o.format, o.scene.limits);
  RenderOptions withInput = o;
  withInput.scene.stdinInput = piped;
  if (!o.outputDir.empty()) {
    std::error_code ec;
    fs::create_directories(o.outputDir, ec);
    if (ec) throw Error(o.outputDir + ": cannot create the output folder: " + ec.message());
  }

  const ThreadLimit limit(o.scene);
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  BatchProgress progress(jobs.size(), !o.quiet && (o.progress || (terminal && !o.json)));
  gInterrupted = false;
  const auto previous = std::signal(SIGINT, onInterrupt);
  Renderer renderer;
  ModelCache cache;
  std::size_t done = 0, failed = 0, inputErrors = 0;
  std::string cutShort;  // which job Ctrl-C stopped in the middle of its frames
  // The next jobs' models, read while this job is drawn: as many at once as there are cores.
  std::deque<ReadAhead> ahead;
  std::size_t considered = 1;  // jobs [1, considered) were looked at for reading ahead
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    if (gInterrupted) break;
    const BatchJob& job = jobs[i];
    for (; considered < jobs.size() && considered <= i + std::size_t(limit.threads()); ++considered)
      if (auto next = startReadAhead(o, jobs, considered, out, limit.threads())) ahead.push_back(std::move(*next));
    std::optional<ReadAhead> readAhead;
    if (!ahead.empty() && ahead.front().job == i) {
      readAhead = std::move(ahead.front());
      ahead.pop_front();
    }
    const std::string& input = job.input;
    nlohmann::json line = {{"input", job.input}};
    try {
      // Folders the template names are made as needed.
      const fs::path first = out.name(job, 0);
      if (first.has_parent_path()) fs::create_directories(first.parent_path());
      const JobResult r = renderJob(withInput, job, input, out, renderer, cache, std::move(readAhead));
      if (!r.skipped && r.framesDone < r.framesWanted) {
        cutShort = job.input + " stopped after " + std::to_string(r.framesDone) + " of " + std::to_string(r.framesWanted) +
                   " frames (what it wrote is removed); ";
        break;  // not done, and no line is printed for it
      }
      line["output"] = r.outputs.size() == 1 ? nlohmann::json(r.outputs[0]) : nlohmann::json(r.outputs);
      line["ok"] = true;
      line["skipped"] = r.skipped;
      line["triangles"] = r.triangles;
      line["lines"] = r.lines, line["points"] = r.points;
      line["load_ms"] = r.loadMs, line["render_ms"] = r.renderMs, line["encode_ms"] = r.encodeMs;
      line["warnings"] = r.warnings;
      if (!o.json && !o.quiet)
        for (const std::string& w : r.warnings) progress.say("illum: warning: " + w);
      if (!o.json && !o.quiet && !terminal && !o.progress)
        for (const std::string& out : r.outputs) std::printf("%s\n", out.c_str());
    } catch (const std::exception& e) {
      ++failed;
      const bool input = dynamic_cast<const InputError*>(&e) != nullptr;
      inputErrors += input;
      line["ok"] = false;
      line["error"] = e.what();
      const std::string what = e.what(),
                        name = job.input == "-" ? "standard input" : job.input.empty() ? "the built-in scene" : job.input;
      progress.say("illum: error: " + (what.rfind(name, 0) == 0 ? "" : name + ": ") + what);
    }
    ++done;
    // File names and the messages that quote them are bytes, not always UTF-8: a byte that is not
    // becomes U+FFFD, so that no name stops the batch.
    if (o.json) std::printf("%s\n", line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace).c_str()), std::fflush(stdout);
    progress.update(done, failed);
    if (failed && o.failFast) break;
  }
  progress.finish();
  std::signal(SIGINT, previous);
  if (gInterrupted) {
    std::fprintf(stderr, "illum: interrupted: %s%zu of %zu inputs done; --skip-existing resumes\n", cutShort.c_str(), done,
                 jobs.size());
    return 130;
  }
  if (failed && !o.quiet)
    std::fprintf(stderr, "illum: %zu of %zu inputs failed%s\n", failed, jobs.size(), o.failFast ? " (--fail-fast)" : "");
  return failed == 0 ? 0 : failed == inputErrors ? 2 : 1;
}


}  // namespace illum::cli

#include "render_worker.h"

#include "pixel_report.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace illum::view {
namespace {

// The --debug-pixel report as text (pixel_report.h writes it to a stream), to the file's bytes.
std::string reportOf(const Scene& scene, const PixelProbe& probe, const Image& image) {
  const cli::PixelChain chain = cli::tracePixelChain(scene, probe.x, probe.y);
  char* text = nullptr;
  std::size_t size = 0;
  std::FILE* out = open_memstream(&text, &size);
  if (!out) return "";
  cli::printPixelReport(scene, probe, image, out, &chain);
  std::fclose(out);
  std::string report(text, size);
  std::free(text);
  return report;
}

}  // namespace

RenderWorker::RenderWorker(std::function<void()> onFrame) : onFrame_(std::move(onFrame)), thread_([this] { run(); }) {
  renderer_.setCancel(&cancel_);
}

RenderWorker::~RenderWorker() {
  {
    const std::lock_guard lock(mutex_);
    quit_ = true;
    cancel_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void RenderWorker::request(std::shared_ptr<const Scene> scene, std::uint64_t version,
                           std::optional<std::pair<int, int>> probe) {
  {
    const std::lock_guard lock(mutex_);
    pending_ = Request{std::move(scene), version, probe};
    // A refinement in flight is out of date: abandoned between tiles. The first frame of a
    // request is finished and shown, so that a drag, whose every step is a request, shows
    // pictures rather than abandoning each one for the next.
    if (refining_) cancel_ = true;
  }
  wake_.notify_all();
}

bool RenderWorker::take(Frame& out) {
  const std::lock_guard lock(mutex_);
  if (!done_) return false;
  spare_ = std::move(out.image);
  out = std::move(*done_);
  done_.reset();
  return true;
}

void RenderWorker::run() {
  for (;;) {
    Request r;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return quit_ || pending_; });
      if (quit_) return;
      r = std::move(*pending_);
      pending_.reset();
      cancel_ = false;
      refining_ = false;
    }
    busy_ = true;
    draw(r);
    busy_ = false;
  }
}

// A tracer's first, quick picture: half the pixels each way, one ray each (its captions halved
// with it). Stretched over the window, it follows a drag; the refinements replace it.
std::shared_ptr<const Scene> quickScene(const Scene& scene) {
  auto quick = std::make_shared<Scene>(scene);
  quick->width = std::max(1, scene.width / 2), quick->height = std::max(1, scene.height / 2);
  quick->rayTracing.samples = 1;
  for (Label& l : quick->labels) {
    if (l.pixel) *l.pixel *= Real(0.5);
    l.size = std::max(Real(4), l.size / 2);
  }
  return quick;
}

void RenderWorker::draw(const Request& r) {
  using Clock = std::chrono::steady_clock;
  // The tracers refine: a quick picture at half resolution, then 1 sample, 4, 16, ... up to the
  // scene's own count, each a whole frame. The rasterizer draws the scene as it is.
  const bool traced = r.scene->renderer != RendererKind::Raster;
  const int full = traced ? samplesPerPixel(*r.scene) : r.scene->multisample;
  const bool quick = traced && r.scene->width >= 64 && r.scene->height >= 64;
  for (int step = 0, samples = traced ? 1 : full;; ++step) {
    std::shared_ptr<const Scene> scene = r.scene;
    const bool coarse = quick && step == 0;
    if (coarse) {
      scene = quickScene(*r.scene);
    } else if (samples != full) {
      auto fewer = std::make_shared<Scene>(*r.scene);
      fewer->rayTracing.samples = samples;
      scene = fewer;
    }
    Frame f;
    {
      const std::lock_guard lock(mutex_);
      f.image = std::exchange(spare_, Image());  // drawn over whole: every pixel is written
    }
    std::optional<PixelProbe> probe;
    if (r.probe && !coarse) {
      probe.emplace();
      probe->x = r.probe->first, probe->y = r.probe->second;
    }
    const auto start = Clock::now();
    renderer_.render(*scene, f.image, nullptr, probe ? &*probe : nullptr);
    if (cancel_) return;  // a newer request came: this frame is not to be shown
    f.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    f.version = r.version;
    f.samples = coarse ? 1 : samples;
    f.final = !coarse && samples == full;
    if (probe) f.report = reportOf(*scene, *probe, f.image);
    f.probe = probe;
    f.scene = scene;
    bool last = false;
    {
      const std::lock_guard lock(mutex_);
      done_ = std::move(f);
      last = pending_ || (!coarse && samples == full);
      refining_ = !last;
    }
    if (onFrame_) onFrame_();
    if (last) return;
    if (!coarse) samples = std::min(full, samples * 4);
  }
}

}  // namespace illum::view

// The viewer's frames, drawn off the input thread: the window asks for the newest scene and keeps
// handling input. Requests are not queued: the newest replaces any waiting one, and a refining
// frame in flight for an older request is abandoned between tiles (Renderer::setCancel); the
// first frame of a request is finished, so that a drag shows pictures as it goes. The ray and path tracers refine
// once the view stands still: one sample per pixel first, then more, up to the scene's own count,
// whose frame is what `illum render` draws of the same scene.
#pragma once

#include <illum/image.h>
#include <illum/render.h>
#include <illum/scene.h>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace illum::view {

struct Frame {
  Image image;
  std::uint64_t version = 0;  // the ViewState version it shows
  double ms = 0;              // how long it took
  int samples = 1;            // per pixel (tracers: rays; the rasterizer: multisamples)
  bool final = true;          // the scene's own sample count (a refining tracer's last frame)
  std::optional<PixelProbe> probe;
  std::string report;         // the --debug-pixel report of the watched pixel
  std::shared_ptr<const Scene> scene;
};

class RenderWorker {
 public:
  // `onFrame` is called on the worker's thread each time a frame is ready to take (the window
  // wakes its event loop with it).
  explicit RenderWorker(std::function<void()> onFrame = {});
  ~RenderWorker();
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  // Draw `scene` (with the pixel (x, y), if any, watched): what is in flight is abandoned.
  void request(std::shared_ptr<const Scene> scene, std::uint64_t version, std::optional<std::pair<int, int>> probe);
  // The newest finished frame, when one came since the last call: it replaces `out`, whose
  // picture's memory the worker draws its next frame into (a new 1280×720 picture each frame
  // would be 3.7 MB zeroed and faulted in, then unmapped on the window's thread).
  bool take(Frame& out);
  // Whether a frame is being drawn (or refined) now.
  bool busy() const { return busy_.load(); }

 private:
  struct Request {
    std::shared_ptr<const Scene> scene;
    std::uint64_t version = 0;
    std::optional<std::pair<int, int>> probe;
  };
  void run();
  void draw(const Request& r);

  std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<Request> pending_;
  std::optional<Frame> done_;
  Image spare_;  // the picture `take` was handed back, drawn into next
  std::atomic<bool> cancel_{false}, quit_{false}, busy_{false};
  bool refining_ = false;  // beyond the first frame of a request (under mutex_)
  Renderer renderer_;
  std::function<void()> onFrame_;
  std::thread thread_;
};

}  // namespace illum::view

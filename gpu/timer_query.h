// GPU time per pass, for benchmarks and the viewer's overlay. Each frame records a GL_TIMESTAMP
// (glQueryCounter) at beginFrame(), at both ends of each named scope and at endFrame(). The
// queries live in a ring of `framesInFlight` frames, and a frame's results are read when its
// slot comes round again, at beginFrame() of frame f + framesInFlight: by then the GPU has long
// finished it, so reading never stalls the frame being recorded (a timer that waited for the
// current frame would serialise CPU and GPU and time the wait). latest() is that delayed,
// non-blocking result; resolve() waits for the last ended frame, for the end of a benchmark.
//
// Timestamps mark when the GPU reaches a point in the command stream, so a scope is the time
// between its two marks: on a GPU that overlaps passes, neighbouring scopes may share work.
// Scopes may nest; an inner scope's time is also in the outer one's. Move-only; the queries
// belong to the context current at construction.
#pragma once

#include <epoxy/gl.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace prism::gpu {

struct GpuTimerDesc {
  int framesInFlight = 0;  // the ring's length, at least 2; 0 means 3
};

// Milliseconds per scope of one frame: {"frame", beginFrame to endFrame} first, then each
// scope in the order it began.
using GpuTimings = std::vector<std::pair<std::string, double>>;

class GpuTimer {
 public:
  explicit GpuTimer(const GpuTimerDesc& desc = {});
  ~GpuTimer();
  GpuTimer(GpuTimer&& other) noexcept;
  GpuTimer& operator=(GpuTimer&& other) noexcept;
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  // Out of order calls (a scope outside a frame, a frame ended with a scope open) throw
  // std::logic_error.
  void beginFrame();
  void endFrame();
  void beginScope(std::string_view name);
  void endScope();

  // beginScope() now, endScope() at the end of the enclosing block.
  class Scope {
   public:
    explicit Scope(GpuTimer& timer, std::string_view name) : mTimer(&timer) {
      timer.beginScope(name);
    }
    ~Scope() {
      if (mTimer) mTimer->endScope();
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    GpuTimer* mTimer;
  };
  [[nodiscard]] Scope scope(std::string_view name) { return Scope(*this, name); }

  // Without waiting: the timings of the frame read at the last beginFrame(), framesInFlight
  // frames old; empty until that many frames have ended.
  const GpuTimings& latest() const { return mLatest; }
  // Whether the last ended frame's timestamps have all arrived, so resolve() would not wait.
  bool available() const;
  // The last ended frame's timings, waiting for the GPU if need be; empty before any frame.
  GpuTimings resolve();

 private:
  struct Marks {
    std::string name;
    std::size_t begin = 0, end = 0;  // indices into Frame::queries
  };
  struct Frame {
    std::vector<GLuint> queries;  // grown on demand and reused
    std::size_t used = 0;
    std::size_t endQuery = 0;
    std::vector<Marks> scopes;
    bool ended = false;
    bool read = false;
    GpuTimings timings;
  };

  std::size_t mark(Frame& frame);  // records a timestamp in the next query; returns its index
  void read(Frame& frame);
  void release();

  std::vector<Frame> mFrames;
  std::size_t mCurrent = 0;    // slot of the frame being recorded (or next to be)
  std::size_t mLastEnded = 0;  // slot of the last ended frame, valid if mAnyEnded
  bool mInFrame = false, mAnyEnded = false;
  std::vector<std::size_t> mOpen;  // indices into the current frame's scopes
  GpuTimings mLatest;
};

}  // namespace prism::gpu

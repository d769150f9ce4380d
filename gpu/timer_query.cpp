#include "gpu/timer_query.h"

#include <cstdint>
#include <stdexcept>

#include "gpu/object_counter.h"

namespace prism::gpu {

GpuTimer::GpuTimer(const GpuTimerDesc& desc) {
  int frames = desc.framesInFlight == 0 ? 3 : desc.framesInFlight;
  // With one slot, beginFrame() would have to read the frame that has just ended: a stall.
  if (frames < 2) throw std::invalid_argument("GpuTimer: framesInFlight must be at least 2");
  mFrames.resize(static_cast<std::size_t>(frames));
}

GpuTimer::~GpuTimer() { release(); }

void GpuTimer::release() {
  for (Frame& frame : mFrames) {
    if (frame.queries.empty()) continue;
    glDeleteQueries(static_cast<GLsizei>(frame.queries.size()), frame.queries.data());
    countGlObjects(GlObjectKind::Query, -static_cast<std::int64_t>(frame.queries.size()));
    frame.queries.clear();
  }
}

GpuTimer::GpuTimer(GpuTimer&& other) noexcept
    : mFrames(std::exchange(other.mFrames, {})),
      mCurrent(other.mCurrent),
      mLastEnded(other.mLastEnded),
      mInFrame(std::exchange(other.mInFrame, false)),
      mAnyEnded(std::exchange(other.mAnyEnded, false)),
      mOpen(std::exchange(other.mOpen, {})),
      mLatest(std::exchange(other.mLatest, {})) {}

GpuTimer& GpuTimer::operator=(GpuTimer&& other) noexcept {
  if (this != &other) {
    release();
    mFrames = std::exchange(other.mFrames, {});
    mCurrent = other.mCurrent;
    mLastEnded = other.mLastEnded;
    mInFrame = std::exchange(other.mInFrame, false);
    mAnyEnded = std::exchange(other.mAnyEnded, false);
    mOpen = std::exchange(other.mOpen, {});
    mLatest = std::exchange(other.mLatest, {});
  }
  return *this;
}

std::size_t GpuTimer::mark(Frame& frame) {
  if (frame.used == frame.queries.size()) {
    GLuint query = 0;
    glCreateQueries(GL_TIMESTAMP, 1, &query);
    countGlObjects(GlObjectKind::Query, 1);
    frame.queries.push_back(query);
  }
  glQueryCounter(frame.queries[frame.used], GL_TIMESTAMP);
  return frame.used++;
}

void GpuTimer::beginFrame() {
  if (mFrames.empty()) throw std::logic_error("GpuTimer: moved from");
  if (mInFrame) throw std::logic_error("GpuTimer::beginFrame: the previous frame has not ended");
  Frame& frame = mFrames[mCurrent];
  if (frame.ended) {
    if (!frame.read) read(frame);  // framesInFlight frames old: finished on the GPU by now
    mLatest = frame.timings;
  }
  frame.used = 0;
  frame.scopes.clear();
  frame.ended = frame.read = false;
  frame.timings.clear();
  mark(frame);  // query 0: the frame's start
  mInFrame = true;
}

void GpuTimer::beginScope(std::string_view name) {
  if (!mInFrame) throw std::logic_error("GpuTimer::beginScope outside a frame");
  Frame& frame = mFrames[mCurrent];
  mOpen.push_back(frame.scopes.size());
  frame.scopes.push_back({std::string(name), mark(frame), 0});
}

void GpuTimer::endScope() {
  if (mOpen.empty()) throw std::logic_error("GpuTimer::endScope without an open scope");
  Frame& frame = mFrames[mCurrent];
  frame.scopes[mOpen.back()].end = mark(frame);
  mOpen.pop_back();
}

void GpuTimer::endFrame() {
  if (!mInFrame) throw std::logic_error("GpuTimer::endFrame outside a frame");
  if (!mOpen.empty())
    throw std::logic_error("GpuTimer::endFrame with scope '" +
                           mFrames[mCurrent].scopes[mOpen.back()].name + "' open");
  Frame& frame = mFrames[mCurrent];
  frame.endQuery = mark(frame);
  frame.ended = true;
  mInFrame = false;
  mAnyEnded = true;
  mLastEnded = mCurrent;
  mCurrent = (mCurrent + 1) % mFrames.size();
}

void GpuTimer::read(Frame& frame) {
  std::vector<GLuint64> ns(frame.used, 0);
  for (std::size_t i = 0; i < frame.used; ++i)
    glGetQueryObjectui64v(frame.queries[i], GL_QUERY_RESULT, &ns[i]);  // waits if need be
  // Differences of unsigned nanoseconds, as signed, so that a misordered pair shows as negative
  // rather than as 584 years.
  auto ms = [&](std::size_t begin, std::size_t end) {
    return static_cast<double>(static_cast<GLint64>(ns[end] - ns[begin])) * 1e-6;
  };
  frame.timings.clear();
  frame.timings.emplace_back("frame", ms(0, frame.endQuery));
  for (const Marks& s : frame.scopes) frame.timings.emplace_back(s.name, ms(s.begin, s.end));
  frame.read = true;
}

bool GpuTimer::available() const {
  if (!mAnyEnded) return false;
  const Frame& frame = mFrames[mLastEnded];
  if (frame.read) return true;
  for (std::size_t i = 0; i < frame.used; ++i) {
    GLuint ready = GL_FALSE;
    glGetQueryObjectuiv(frame.queries[i], GL_QUERY_RESULT_AVAILABLE, &ready);
    if (!ready) return false;
  }
  return true;
}

GpuTimings GpuTimer::resolve() {
  if (!mAnyEnded) return {};
  Frame& frame = mFrames[mLastEnded];
  if (!frame.read) read(frame);
  return frame.timings;
}

}  // namespace prism::gpu

#include "gpu/framebuffer.h"

#include <stdexcept>
#include <utility>

#include "gpu/error.h"
#include "gpu/object_counter.h"

namespace prism::gpu {
namespace {

std::string statusName(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS: return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    default: return "status " + std::to_string(status);
  }
}

bool hasStencil(GLenum internalFormat) {
  return internalFormat == GL_DEPTH24_STENCIL8 || internalFormat == GL_DEPTH32F_STENCIL8;
}

}  // namespace

Framebuffer::Framebuffer(const FramebufferDesc& desc) {
  const DepthAttachment& depth = desc.depth;
  if (depth.texture && depth.array)
    throw std::invalid_argument("Framebuffer: depth is a texture or an array layer, not both");
  GLint maxDrawBuffers = 0;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &maxDrawBuffers);
  if (desc.colour.size() > static_cast<std::size_t>(maxDrawBuffers))
    throw std::invalid_argument("Framebuffer: " + std::to_string(desc.colour.size()) +
                                " colour attachments, at most " + std::to_string(maxDrawBuffers));

  // Every attachment must have the framebuffer's size at its level.
  bool sized = false;
  auto takeSize = [&](GLsizei w, GLsizei h) {
    if (sized && (w != mWidth || h != mHeight))
      throw std::invalid_argument("Framebuffer: attachments of different sizes (" +
                                  std::to_string(mWidth) + "x" + std::to_string(mHeight) + " and " +
                                  std::to_string(w) + "x" + std::to_string(h) + ")");
    mWidth = w;
    mHeight = h;
    sized = true;
  };
  for (const ColourAttachment& c : desc.colour) {
    if (!c.texture) throw std::invalid_argument("Framebuffer: a colour attachment without texture");
    takeSize(c.texture->width(c.level), c.texture->height(c.level));
  }
  if (depth.texture)
    takeSize(depth.texture->width(depth.level), depth.texture->height(depth.level));
  if (depth.array) {
    if (depth.layer < 0 || depth.layer >= depth.array->layers())
      throw std::out_of_range("Framebuffer: depth layer " + std::to_string(depth.layer) + " of " +
                              std::to_string(depth.array->layers()));
    takeSize(depth.array->width(depth.level), depth.array->height(depth.level));
  }

  glCreateFramebuffers(1, &mId);
  countGlObjects(GlObjectKind::Framebuffer, 1);
  std::vector<GLenum> drawBuffers;
  for (std::size_t i = 0; i < desc.colour.size(); ++i) {
    auto attachment = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i);
    glNamedFramebufferTexture(mId, attachment, desc.colour[i].texture->id(), desc.colour[i].level);
    drawBuffers.push_back(attachment);
  }
  mColourCount = desc.colour.size();
  if (depth.texture) {
    GLenum point = hasStencil(depth.texture->internalFormat()) ? GL_DEPTH_STENCIL_ATTACHMENT
                                                               : GL_DEPTH_ATTACHMENT;
    glNamedFramebufferTexture(mId, point, depth.texture->id(), depth.level);
  } else if (depth.array) {
    GLenum point = hasStencil(depth.array->internalFormat()) ? GL_DEPTH_STENCIL_ATTACHMENT
                                                             : GL_DEPTH_ATTACHMENT;
    glNamedFramebufferTextureLayer(mId, point, depth.array->id(), depth.level, depth.layer);
  }
  mHasDepth = depth.texture || depth.array;
  if (drawBuffers.empty()) {
    glNamedFramebufferDrawBuffer(mId, GL_NONE);  // depth only (a shadow map)
    glNamedFramebufferReadBuffer(mId, GL_NONE);
  } else {
    glNamedFramebufferDrawBuffers(mId, static_cast<GLsizei>(drawBuffers.size()),
                                  drawBuffers.data());
    glNamedFramebufferReadBuffer(mId, GL_COLOR_ATTACHMENT0);
  }
  if (!desc.label.empty())
    glObjectLabel(GL_FRAMEBUFFER, mId, static_cast<GLsizei>(desc.label.size()), desc.label.data());

  GLenum status = glCheckNamedFramebufferStatus(mId, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    release();
    throw GpuError(Diagnostic::FramebufferIncomplete,
                   "prism::gpu::Framebuffer" +
                       (desc.label.empty() ? std::string() : " '" + desc.label + "'") +
                       ": incomplete (" + statusName(status) + ")");
  }
}

Framebuffer Framebuffer::window(GLsizei width, GLsizei height) {
  Framebuffer fb;
  fb.mWidth = width;
  fb.mHeight = height;
  fb.mColourCount = 1;
  fb.mHasDepth = true;
  return fb;
}

Framebuffer::~Framebuffer() { release(); }

void Framebuffer::release() {
  if (!mId) return;
  glDeleteFramebuffers(1, &mId);
  countGlObjects(GlObjectKind::Framebuffer, -1);
  mId = 0;
}

Framebuffer::Framebuffer(Framebuffer&& other) noexcept
    : mId(std::exchange(other.mId, 0)),
      mWidth(std::exchange(other.mWidth, 0)),
      mHeight(std::exchange(other.mHeight, 0)),
      mColourCount(std::exchange(other.mColourCount, 0)),
      mUndrawn(std::exchange(other.mUndrawn, 0u)),
      mHasDepth(std::exchange(other.mHasDepth, false)) {}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept {
  if (this != &other) {
    release();
    mId = std::exchange(other.mId, 0);
    mWidth = std::exchange(other.mWidth, 0);
    mHeight = std::exchange(other.mHeight, 0);
    mColourCount = std::exchange(other.mColourCount, 0);
    mUndrawn = std::exchange(other.mUndrawn, 0u);
    mHasDepth = std::exchange(other.mHasDepth, false);
  }
  return *this;
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, mId);
  glViewport(0, 0, mWidth, mHeight);
}

void Framebuffer::checkColourIndex(int index) const {
  if (index < 0 || static_cast<std::size_t>(index) >= mColourCount)
    throw std::out_of_range("Framebuffer: colour attachment " + std::to_string(index) + " of " +
                            std::to_string(mColourCount));
}

void Framebuffer::setColourDrawn(int index, bool drawn) {
  checkColourIndex(index);
  const std::uint32_t bit = 1u << index;
  const std::uint32_t undrawn = drawn ? mUndrawn & ~bit : mUndrawn | bit;
  if (undrawn == mUndrawn) return;
  mUndrawn = undrawn;
  std::vector<GLenum> buffers(mColourCount);
  for (std::size_t i = 0; i < mColourCount; ++i)
    buffers[i] = (mUndrawn >> i) & 1u ? GL_NONE : static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i);
  glNamedFramebufferDrawBuffers(mId, static_cast<GLsizei>(buffers.size()), buffers.data());
}

void Framebuffer::clearColour(int index, const glm::vec4& value) const {
  checkColourIndex(index);
  const GLfloat rgba[4] = {value.r, value.g, value.b, value.a};
  glClearNamedFramebufferfv(mId, GL_COLOR, index, rgba);
}

void Framebuffer::clearColourUint(int index, const std::array<std::uint32_t, 4>& value) const {
  checkColourIndex(index);
  glClearNamedFramebufferuiv(mId, GL_COLOR, index, value.data());
}

void Framebuffer::clearDepth(float depth) const {
  if (!mHasDepth) throw std::logic_error("Framebuffer: no depth attachment to clear");
  glClearNamedFramebufferfv(mId, GL_DEPTH, 0, &depth);
}

void Framebuffer::blitDepthTo(const Framebuffer& dst) const {
  if (!mHasDepth || !dst.mHasDepth) throw std::logic_error("Framebuffer: blit without depth");
  glBlitNamedFramebuffer(mId, dst.mId, 0, 0, mWidth, mHeight, 0, 0, dst.mWidth, dst.mHeight,
                         GL_DEPTH_BUFFER_BIT, GL_NEAREST);
}

void Framebuffer::blitColourTo(const Framebuffer& dst, int index, GLenum filter) const {
  checkColourIndex(index);
  glNamedFramebufferReadBuffer(
      mId, mId ? static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + index) : static_cast<GLenum>(GL_BACK));
  glBlitNamedFramebuffer(mId, dst.mId, 0, 0, mWidth, mHeight, 0, 0, dst.mWidth, dst.mHeight,
                         GL_COLOR_BUFFER_BIT, filter);
}

}  // namespace prism::gpu

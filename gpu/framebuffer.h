// A framebuffer object over direct state access: colour attachments in order (attachment i is
// GL_COLOR_ATTACHMENTi and fragment output location i, all of them drawn to unless
// setColourDrawn says not), an optional depth attachment that is either a Texture2D or one layer
// of a Texture2DArray (a shadow cascade).
// Completeness is checked at construction: an incomplete one throws GpuError(
// FramebufferIncomplete) naming the GL status, rather than rendering nothing later.
//
// Attachments are referenced by name, not owned: the textures must outlive the framebuffer.
// All attachments must have the same size (at their level), which bind() sets as the viewport.
// Framebuffer::window() stands for the default framebuffer (name 0) of a WindowContext, to
// clear it, bind it and blit the final image into it. Move-only.
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <cstdint>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "gpu/texture.h"

namespace prism::gpu {

struct ColourAttachment {
  const Texture2D* texture = nullptr;
  GLint level = 0;
};

// Either `texture`, or layer `layer` of `array`, or neither (no depth).
struct DepthAttachment {
  const Texture2D* texture = nullptr;
  const Texture2DArray* array = nullptr;
  GLint layer = 0;
  GLint level = 0;
};

struct FramebufferDesc {
  std::vector<ColourAttachment> colour;  // at most GL_MAX_COLOR_ATTACHMENTS (8 or more)
  DepthAttachment depth;
  std::string label;
};

class Framebuffer {
 public:
  Framebuffer() = default;  // no GL object
  explicit Framebuffer(const FramebufferDesc& desc);
  ~Framebuffer();
  Framebuffer(Framebuffer&& other) noexcept;
  Framebuffer& operator=(Framebuffer&& other) noexcept;
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  // The default framebuffer of the current (window) context, `width`×`height` pixels (the
  // window's framebufferSize(), which changes on resize). Owns nothing.
  static Framebuffer window(GLsizei width, GLsizei height);

  GLuint id() const { return mId; }
  GLsizei width() const { return mWidth; }
  GLsizei height() const { return mHeight; }
  std::size_t colourCount() const { return mColourCount; }
  // Whether colour attachment `index` is drawn to (every one is, from construction): a pass that
  // has nothing for one leaves it as it is and spares its memory traffic. An undrawn attachment's
  // clears do nothing either (they go through its draw buffer).
  void setColourDrawn(int index, bool drawn);

  // glBindFramebuffer(GL_FRAMEBUFFER) and a viewport covering the whole framebuffer.
  void bind() const;

  // Clear one attachment regardless of what is bound (glClearNamedFramebuffer*). The colour
  // index is the attachment's position; the default framebuffer has one, index 0. Clears
  // ignore the viewport but obey the scissor test and the write masks.
  void clearColour(int index, const glm::vec4& value) const;
  void clearColourUint(int index, const std::array<std::uint32_t, 4>& value) const;
  void clearDepth(float depth) const;

  // Copies the whole depth attachment into `dst`'s (same depth format; scaled with GL_NEAREST
  // when the sizes differ), e.g. to keep a depth prepass's buffer for a forward pass.
  void blitDepthTo(const Framebuffer& dst) const;
  // Copies colour attachment `index` into all of `dst`'s draw buffers, scaled with `filter`
  // (a resolve to the window, usually). Leaves that attachment as this one's read buffer.
  void blitColourTo(const Framebuffer& dst, int index = 0, GLenum filter = GL_NEAREST) const;

 private:
  void release();
  void checkColourIndex(int index) const;

  GLuint mId = 0;
  GLsizei mWidth = 0, mHeight = 0;
  std::size_t mColourCount = 0;
  std::uint32_t mUndrawn = 0;  // bit i: attachment i not drawn
  bool mHasDepth = false;
};

}  // namespace prism::gpu

// The renderer tests' frame: small enough for llvmpipe, with the CPU's own upsampling lookup so
// that the GPU and its CPU twin agree bit for bit.
#pragma once

#include "render/frame_settings.h"

namespace prism::render {

inline FrameSettings smallFrame(RenderMode mode, int wavelengths = 16) {
  FrameSettings s;
  s.width = 192;
  s.height = 108;
  s.mode = mode;
  s.sampling.count = wavelengths;
  s.shadowMapSize = 512;
  s.lookup = UpsamplingLookup::Manual;  // the CPU's lookup, bit for bit
  return s;
}

}  // namespace prism::render

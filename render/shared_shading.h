// The per-pixel formulas of shaders/shared/ that the renderer's CPU side uses, compiled as C++
// once (inside prism::shared), with the GPU buffer layouts checked against std430.
#pragma once

#include <cstddef>

#include "frame_layout.h"
#include "shared_cpp.h"
#include "techniques/atmosphere/atmosphere_layout.h"  // atmosphere_model.glsl, once
#include "techniques/underwater/underwater_layout.h"    // underwater.glsl, once

namespace prism::shared {
#include "sigmoid.glsl"
#include "box_upsampling.glsl"
#include "brdf.glsl"
#include "lights.glsl"
#include "underwater_lamps.glsl"
#include "shadow_filter.glsl"
#include "transfer.glsl"
#include "cielab.glsl"
#include "post.glsl"
#include "surface_inputs.glsl"

// std430 (storage buffers) and std140 (the constants' block) sizes and offsets: a vec3 takes 12
// bytes and the scalar after it the last 4 of its 16, as glm lays them out in C++.
static_assert(sizeof(GpuBatch) == 64 && offsetof(GpuBatch, toZ) == 48);
static_assert(sizeof(GpuLight) == 208 && offsetof(GpuLight, type) == 12 && offsetof(GpuLight, intensity) == 28 &&
              offsetof(GpuLight, shadowLayer) == 40 && offsetof(GpuLight, shadowFromWorld) == 64 &&
              offsetof(GpuLight, shadowCascades) == 128 && offsetof(GpuLight, shadowCascadeCount) == 192);
static_assert(sizeof(GpuMaterial) == 48 && offsetof(GpuMaterial, metallic) == 12 &&
              offsetof(GpuMaterial, lambertian) == 28 && offsetof(GpuMaterial, emission) == 32 &&
              offsetof(GpuMaterial, rgbEmissionWhite) == 36 && offsetof(GpuMaterial, rgbEmissionLuminance) == 40);
static_assert(sizeof(FrameConstants) == 112 && offsetof(FrameConstants, cameraPositionW) == 64 &&
              offsetof(FrameConstants, mode) == 76 && offsetof(FrameConstants, viewportSize) == 80 &&
              offsetof(FrameConstants, batchCount) == 88 && offsetof(FrameConstants, filteredLookup) == 108);
}  // namespace prism::shared

// The per-pixel formulas of shaders/shared/ that the renderer's CPU side uses, compiled as C++
// once (inside prism::shared), with the GPU buffer layouts checked against std430.
#pragma once

#include "shared_cpp.h"
#include "techniques/atmosphere/atmosphere_layout.h"  // atmosphere_model.glsl, once

namespace prism::shared {
#include "sigmoid.glsl"
#include "box_upsampling.glsl"
#include "brdf.glsl"
#include "lights.glsl"
#include "shadow_filter.glsl"
#include "frame_layout.glsl"
#include "transfer.glsl"
#include "post.glsl"
#include "surface_inputs.glsl"
#include "underwater.glsl"

// std430 sizes and offsets of the buffer structs (vec4 = 16 bytes, mat4 = 64, no padding).
static_assert(sizeof(GpuBatch) == 64 && offsetof(GpuBatch, toZ) == 48);
static_assert(sizeof(GpuLight) == 128 && offsetof(GpuLight, shadowFromWorld) == 64);
static_assert(sizeof(GpuMaterial) == 32 && offsetof(GpuMaterial, roughnessKind) == 16);
}  // namespace prism::shared

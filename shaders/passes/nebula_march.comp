#version 450
// The nebula's ray march (Barrès 2023), one invocation per pixel, front to back with early
// termination: the GPU twin of NebulaRenderer::render's projection, light–density and reference
// methods (techniques/nebula/nebula_render.cpp), sample for sample. Projection and light–density
// write each pixel's moments on the orthonormalised basis, not its colour: projection, per star s
// and element j, Σ w_s·cⱼ(g + g_s); light–density, per 2D element k, Σ ρΔt·d_k·cⱼ(g);
// nebula_finish.comp turns the moments into channels through the filters' weights, so a filter
// change re-runs only that pass. The reference (the paper's double integration, its baseline)
// integrates over wavelength at every sample, per star, through the renderer's nodes and weights,
// into the colour directly. Every method writes, per emission line, Σ ερΔt·e^(−g/λₗ): the line's
// light reaching the camera, which the finish weighs by the filters' response at λₗ, so that the
// lines, exact at their wavelengths, need no new march either.
//
// Projection and light–density march once per group of lanes (stars or 2D elements): eight lanes
// (two slabs of uField) for card(B) ≤ 4, else four; the group's moments stay in registers, eight
// vec4, and are written at the ray's end. Added in global memory at every sample, as before, they
// made the march a chain of read-modify-writes. The CPU twin sums in the same order.
//
// In a scene of the renderer (gpu/nebula_pass.h) the rays are its camera's and stop at its
// surfaces (uSceneDepth); samples beyond a surface are left out, the others keep their steps.
//
// Defines: NEBULA_LIGHT_DENSITY selects the light–density method, NEBULA_REFERENCE the
// reference, NEBULA_ANALYTIC the analytic method (the closed form per sample, star and passband
// piece), NEBULA_PRE_INTEGRATION pre-integration (each star's tabulated channels over x), else
// projection. The reference, analytic and pre-integration add into the colour directly.
// NEBULA_NODE_CHUNK: the reference's node loop's chunk (16 unless set).
//
// A march may take several dispatches (nebula_march_segments.h: llvmpipe caps an invocation's
// loop iterations): each marches steps [uStepBegin, uStepEnd) of items [uItemBegin, uItemEnd) —
// the stars of the direct methods, the groups of projection and light–density — and carries on
// from what the dispatches before it left: the colour and lines' light (Marched), the moments, and
// the camera's optical depth at uStepBegin (uOpticalDepth, which the dispatch holding the last
// items advances).
//
// Grids are read with texelFetch and interpolated between voxel centres as the CPU does
// (common_nebula_fields.glsl), not by the sampler, whose quantised weights the twin test would measure.
layout(local_size_x = 8, local_size_y = 8) in;
#include "shared/prelude.glsl"
#include "shared/nebula_integrals.glsl"
#include "shared/nebula_march.glsl"
#include "common_nebula_fields.glsl"

layout(binding = 0) uniform sampler3D uDensity;  // R32F, nx × ny × nz, x fastest
// RGBA32F, nx × ny × (nz · slabs): four values per voxel a slab, slab s at z ∈ [s·nz, (s+1)·nz):
// projection, the optical depth g_s (µm) to stars 4s…4s+3; light–density, coefficients 4s…4s+3.
layout(binding = 1) uniform sampler3D uField;
// Ionisation zones (nebula_ionisation.h), the same layout: zone z in slab z/4, lane z%4; line l
// glows in zone uLineZone[l]. uZoneCount 0: no zones, every line glows wherever the density is.
layout(binding = 3) uniform sampler3D uZones;
uniform int uZoneCount;  // ≤ 8
uniform int uLineZone[16];

// The coefficients cₖ(x) of e^(−x/λ) on the orthonormalised basis (nebula_precomputed.h's
// MomentTable) at x = e·uMomentStep, entry e + 1 (one before 0, two after the end): elements 0…3
// in momentLo, 4…7 in momentHi.
layout(std430, binding = 0) readonly buffer MomentLo { vec4 momentLo[]; };
layout(std430, binding = 1) readonly buffer MomentHi { vec4 momentHi[]; };
layout(std430, binding = 2) readonly buffer Stars { vec4 stars[]; };  // position (unit cube), luminosity
layout(std430, binding = 3) readonly buffer Lines { vec4 lines[]; };  // λ (µm); the finish reads the responses
// Per pixel p of P, value v at moments[v·P + p] (neighbouring invocations write neighbouring
// words): v = s·card + j (projection) or k·card + j (light–density), written once per group at the
// ray's end, so the number of stars has no limit but the int index: 2³¹ floats of moments
// (requireMomentsFit, nebula_gpu_marcher.h).
layout(std430, binding = 4) buffer Moments { float moments[]; };
// What the march made for the finish besides the moments, [v·P + p]: v = 0…2 the colour the direct
// methods integrate in the march (0 for projection and light–density), v = 3 + l the light of
// line l of uLineCount (≤ kMaxNebulaLines).
layout(std430, binding = 5) buffer Marched { float marched[]; };
const int kMaxNebulaLines = 16;
#ifndef NEBULA_ANALYTIC  // its binding holds the analytic pieces' ranges there
layout(std430, binding = 6) readonly buffer BasisMatrix { float basisM[]; };  // M(k, j) at [8k + j]
#endif
#if defined(NEBULA_ANALYTIC)
// Analytic (bindings of the basis matrix and the reference's nodes, which it does not read): per
// star s and channel c, analyticRanges[s·3 + c] = (first piece, pieces, the Wien exponent B as
// float bits, 0), indices into analyticPieces (nebula_integrals.glsl's NebulaAnalyticPiece).
layout(std430, binding = 6) readonly buffer AnalyticRanges { ivec4 analyticRanges[]; };
layout(std430, binding = 7) readonly buffer AnalyticPieces { NebulaAnalyticPiece analyticPieces[]; };
#elif defined(NEBULA_PRE_INTEGRATION)
// Pre-integration: star s's three channels' ∫ P_S·S_s·e^(−x/λ) dλ at x = e·uMomentStep, entry
// e + 1 of [s·(uMomentSize + 3), …) (the moment table's spacing; one before 0, two after the end).
layout(std430, binding = 7) readonly buffer PreIntegrated { vec4 preIntegrated[]; };
#else
// Reference: per star s and channel c, node k at [(s·3 + c)·uNodeStride + k]: (λ µm, weight),
// each channel's nodes padded to a multiple of NEBULA_NODE_CHUNK (16, or 4 for a few nodes a
// channel) with weight 0.
#ifndef NEBULA_NODE_CHUNK
#define NEBULA_NODE_CHUNK 16
#endif
layout(std430, binding = 7) readonly buffer ReferenceNodes { vec2 referenceNodes[]; };
#endif

uniform ivec2 uSize;
uniform vec3 uCameraPosition;
uniform vec3 uForward;
uniform vec3 uRight;
uniform vec3 uUp;
uniform float uTanHalf;
uniform float uAspect;
uniform int uSteps;
uniform int uStepBegin;  // this dispatch's steps and items (above)
uniform int uStepEnd;
uniform int uItemBegin;
uniform int uItemEnd;
uniform float uDepthPerDensity;  // C_T·κ (µm per unit length at ρ = 1)
uniform float uScattering;       // σ₁
uniform float uEmission;         // ε
uniform int uCount;              // stars (projection) or 2D elements (light–density)
uniform int uCard;               // card(B) ≤ 8
uniform int uLineCount;
uniform vec4 uBasisLo;           // the basis's exponents aⱼ (µm), for x beyond the table
uniform vec4 uBasisHi;
uniform float uMomentStep;
uniform int uMomentSize;         // entries from x = 0 to the table's end
uniform float uBandLoUm;
uniform float uBandHiUm;
uniform ivec3 uNodeCount;        // reference: nodes per channel
uniform int uNodeStride;

// The scene in front of the nebula (nebula_gpu_marcher.h's MarchView): each ray stops at its
// surface. GL window depth, row 0 at the bottom, 1 where nothing was drawn.
layout(binding = 2) uniform sampler2D uSceneDepth;
uniform int uHasDepth;
uniform mat4 uInverseProjection;  // window depth → view space (world units)
uniform float uCubePerWorld;

// The camera's optical depth g (µm) where each ray stopped, for the lighting pass to dim what
// lies behind the nebula by e^(−g/λ) (shared/nebula_lighting.glsl); row 0 at the bottom.
layout(r32f, binding = 0) uniform image2D uOpticalDepth;

// How far the ray through pixel px may go, in the cube's units: to the scene's surface, or on.
float rayLimit(ivec2 px) {
  if (uHasDepth == 0) return 1e30f;
  ivec2 texel = ivec2(px.x, uSize.y - 1 - px.y);
  float d = texelFetch(uSceneDepth, texel, 0).r;
  if (d >= 1.0f) return 1e30f;
  vec2 ndc = (vec2(texel) + 0.5f) / vec2(uSize) * 2.0f - 1.0f;
  vec4 v = uInverseProjection * vec4(ndc, 2.0f * d - 1.0f, 1.0f);
  return length(v.xyz / v.w) * uCubePerWorld;
}

#ifndef NEBULA_ANALYTIC
// cₖ(x) for k < 4 (lo) and 4…7 (hi): the table's Catmull–Rom, or beyond it Σⱼ M(k,j)·mⱼ(x) over
// the raw moments' closed form (the CPU's coefficientsAt in NebulaRenderer::render).
void coefficients8(float x, out vec4 lo, out vec4 hi) {
  float u = x / uMomentStep;
  if (u < float(uMomentSize - 1)) {
    int i = int(u);
    vec4 w = nebulaCatmullRomWeights(u - float(i));
    lo = w.x * momentLo[i] + w.y * momentLo[i + 1] + w.z * momentLo[i + 2] + w.w * momentLo[i + 3];
    hi = uCard > 4 ? w.x * momentHi[i] + w.y * momentHi[i + 1] + w.z * momentHi[i + 2] + w.w * momentHi[i + 3]
                   : vec4(0.0f);
    return;
  }
  vec4 mLo = nebulaExpMoments(x, uBasisLo, uBandLoUm, uBandHiUm);
  vec4 mHi = uCard > 4 ? nebulaExpMoments(x, uBasisHi, uBandLoUm, uBandHiUm) : vec4(0.0f);
  float c[8];
  for (int k = 0; k < 8; ++k) {
    c[k] = 0.0f;
    for (int j = 0; j <= k && k < uCard; ++j) c[k] += basisM[8 * k + j] * (j < 4 ? mLo[j] : mHi[j - 4]);
  }
  lo = vec4(c[0], c[1], c[2], c[3]);
  hi = vec4(c[4], c[5], c[6], c[7]);
}
#endif

// DensityGrid::sample: nested lerps, x then y then z; 0 outside the cube.
float densityAt(vec3 p, Cell c) {
  if (any(lessThan(p, vec3(0.0f))) || any(greaterThan(p, vec3(1.0f)))) return 0.0f;
  float v000 = texelFetch(uDensity, ivec3(c.i0.x, c.i0.y, c.i0.z), 0).r;
  float v100 = texelFetch(uDensity, ivec3(c.i1.x, c.i0.y, c.i0.z), 0).r;
  float v010 = texelFetch(uDensity, ivec3(c.i0.x, c.i1.y, c.i0.z), 0).r;
  float v110 = texelFetch(uDensity, ivec3(c.i1.x, c.i1.y, c.i0.z), 0).r;
  float v001 = texelFetch(uDensity, ivec3(c.i0.x, c.i0.y, c.i1.z), 0).r;
  float v101 = texelFetch(uDensity, ivec3(c.i1.x, c.i0.y, c.i1.z), 0).r;
  float v011 = texelFetch(uDensity, ivec3(c.i0.x, c.i1.y, c.i1.z), 0).r;
  float v111 = texelFetch(uDensity, ivec3(c.i1.x, c.i1.y, c.i1.z), 0).r;
  float c00 = v000 + (v100 - v000) * c.f.x;
  float c10 = v010 + (v110 - v010) * c.f.x;
  float c01 = v001 + (v101 - v001) * c.f.x;
  float c11 = v011 + (v111 - v011) * c.f.x;
  float c0 = c00 + (c10 - c00) * c.f.y;
  float c1 = c01 + (c11 - c01) * c.f.y;
  return c0 + (c1 - c0) * c.f.z;
}

void main() {
  ivec2 px = ivec2(gl_GlobalInvocationID.xy);
  if (px.x >= uSize.x || px.y >= uSize.y) return;
  int pixel = px.y * uSize.x + px.x;  // row 0 at the top, as the CPU's image
  int pixelCount = uSize.x * uSize.y;
#if defined(NEBULA_REFERENCE) || defined(NEBULA_ANALYTIC) || defined(NEBULA_PRE_INTEGRATION)
  // Every star of [uItemBegin, uItemEnd) in the one march, into the colour.
  const int groupBegin = 0;
  const int groupEnd = 1;
  const bool lastItems = uItemEnd >= uCount;
#else
  int lanes = nebulaGroupLanes(uCard);  // a march per group of stars or 2D elements
  int groupBegin = uItemBegin;
  int groupEnd = max(groupBegin + 1, uItemEnd);
  const bool lastItems = uItemEnd >= (uCount + lanes - 1) / lanes;
#endif
  const bool resume = uStepBegin > 0 || uItemBegin > 0;  // an earlier dispatch left this pixel's values
  ivec3 n = textureSize(uDensity, 0);

  float u = (2.0f * (float(px.x) + 0.5f) / float(uSize.x) - 1.0f) * uTanHalf * uAspect;
  float vy = (1.0f - 2.0f * (float(px.y) + 0.5f) / float(uSize.y)) * uTanHalf;
  vec3 dir = normalize(uForward + u * uRight + vy * uUp);
  vec3 colour = vec3(0.0f);
  float lineSum[kMaxNebulaLines];
  for (int l = 0; l < kMaxNebulaLines; ++l) lineSum[l] = 0.0f;
  if (resume) {
    for (int ch = 0; ch < 3; ++ch) colour[ch] = marched[ch * pixelCount + pixel];
    for (int l = 0; l < uLineCount; ++l) lineSum[l] = marched[(3 + l) * pixelCount + pixel];
  }
  ivec2 depthTexel = ivec2(px.x, uSize.y - 1 - px.y);
  float gStart = uStepBegin > 0 ? imageLoad(uOpticalDepth, depthTexel).r : 0.0f;
  float t0;
  float t1;
  float gCam = gStart;
  bool inside = nebulaClipToCube(uCameraPosition, dir, 1e30f, t0, t1);
  float tLimit = rayLimit(px);
  for (int group = groupBegin; group < groupEnd; ++group) {
    // The group's moments: lane c's elements j < 4 in acc[c][j]; with four lanes, 4…7 in acc[4 + c].
    vec4 acc[8];
    for (int k = 0; k < 8; ++k) acc[k] = vec4(0.0f);
#if !defined(NEBULA_REFERENCE) && !defined(NEBULA_ANALYTIC) && !defined(NEBULA_PRE_INTEGRATION)
    if (uStepBegin > 0)
      for (int c = 0; c < lanes && group * lanes + c < uCount; ++c)
        for (int j = 0; j < uCard; ++j) {
          float v = moments[((group * lanes + c) * uCard + j) * pixelCount + pixel];
          if (j < 4) acc[c][j] = v; else acc[4 + c][j - 4] = v;
        }
#endif
    gCam = gStart;
    float dt = inside ? (t1 - t0) / float(uSteps) : 0.0f;
    for (int i = uStepBegin; inside && i < uStepEnd; ++i) {
      if (nebulaRayOpaque(gCam)) break;
      float t = t0 + (float(i) + 0.5f) * dt;
      if (t > tLimit) break;  // behind the scene's surface
      vec3 p = uCameraPosition + dir * t;
      Cell cell = cellAt(p, n);
      float rho = densityAt(p, cell);
      if (rho <= 0.0f) continue;
      float dg = uDepthPerDensity * rho * dt;
      float g = gCam + 0.5f * dg;  // the sample sees half of its own step's extinction
      gCam += dg;
      if (group == 0 && uItemBegin == 0 && uLineCount > 0) {  // the lines once, with the first group or stars
        vec4 zone[2] = vec4[2](vec4(1.0f), vec4(1.0f));
        for (int slab = 0; slab * 4 < uZoneCount; ++slab) zone[slab] = fieldOf(uZones, cell, slab, n.z);
        for (int l = 0; l < uLineCount; ++l) {
          float z = uZoneCount > 0 ? zone[uLineZone[l] / 4][uLineZone[l] % 4] : 1.0f;
          lineSum[l] += uEmission * rho * dt * z * nebulaAttenuation(g, lines[l].x);
        }
      }
#ifdef NEBULA_LIGHT_DENSITY
      vec4 mLo;
      vec4 mHi;
      coefficients8(g, mLo, mHi);
      for (int part = 0; part * 4 < lanes; ++part) {  // the group's slabs
        int slab = group * (lanes / 4) + part;
        if (slab * 4 >= uCount) break;
        vec4 d = (rho * dt) * fieldOf(uField, cell, slab, n.z);
        for (int c = 0; c < 4; ++c) {
          acc[part * 4 + c] += d[c] * mLo;
          if (lanes == 4) acc[4 + c] += d[c] * mHi;
        }
      }
#elif defined(NEBULA_REFERENCE)
      for (int slab = uItemBegin / 4; slab * 4 < uItemEnd; ++slab) {
        vec4 gs = fieldOf(uField, cell, slab, n.z);
        for (int c = 0; c < 4 && slab * 4 + c < uItemEnd; ++c) {
          int s = slab * 4 + c;
          if (s < uItemBegin) continue;
          vec3 toStar = stars[s].xyz - p;
          float w = nebulaStarWeight(uScattering * rho * dt, stars[s].w, dot(toStar, toStar));
          float x = g + gs[c];
          vec3 sum = vec3(0.0f);
          // In chunks (padded with zero weights), a loop of constant count the compiler unrolls:
          // Mesa's llvmpipe stops a shader's loops after 65 535 iterations an invocation, nested
          // loops counted together; fewer iterations, fewer dispatches (nebula_march_segments.h).
          for (int ch = 0; ch < 3; ++ch)
            for (int k0 = 0; k0 < uNodeCount[ch]; k0 += NEBULA_NODE_CHUNK)
              for (int u = 0; u < NEBULA_NODE_CHUNK; ++u) {
                vec2 node = referenceNodes[(s * 3 + ch) * uNodeStride + k0 + u];
                sum[ch] += node.y * nebulaAttenuation(x, node.x);
              }
          colour += w * sum;
        }
      }
#elif defined(NEBULA_ANALYTIC)
      for (int slab = uItemBegin / 4; slab * 4 < uItemEnd; ++slab) {
        vec4 gs = fieldOf(uField, cell, slab, n.z);
        for (int c = 0; c < 4 && slab * 4 + c < uItemEnd; ++c) {
          int s = slab * 4 + c;
          if (s < uItemBegin) continue;
          vec3 toStar = stars[s].xyz - p;
          float w = nebulaStarWeight(uScattering * rho * dt, stars[s].w, dot(toStar, toStar));
          float x = g + gs[c];
          vec3 sum = vec3(0.0f);
          for (int ch = 0; ch < 3; ++ch) {
            ivec4 range = analyticRanges[s * 3 + ch];
            float wienB = intBitsToFloat(range.z);
            for (int k = range.x; k < range.x + range.y; ++k)
              sum[ch] += nebulaAnalyticPieceIntegral(analyticPieces[k], x + wienB, wienB > 0.0f);
          }
          colour += w * sum;
        }
      }
#elif defined(NEBULA_PRE_INTEGRATION)
      for (int slab = uItemBegin / 4; slab * 4 < uItemEnd; ++slab) {
        vec4 gs = fieldOf(uField, cell, slab, n.z);
        for (int c = 0; c < 4 && slab * 4 + c < uItemEnd; ++c) {
          int s = slab * 4 + c;
          if (s < uItemBegin) continue;
          vec3 toStar = stars[s].xyz - p;
          float w = nebulaStarWeight(uScattering * rho * dt, stars[s].w, dot(toStar, toStar));
          float u = (g + gs[c]) / uMomentStep;
          if (u < float(uMomentSize - 1)) {  // beyond (x > 16 µm) e^(−x/λ) < 1e-9 over the band: nothing
            int i = int(u);
            vec4 cw = nebulaCatmullRomWeights(u - float(i));
            int at = s * (uMomentSize + 3) + i;
            vec4 t = cw.x * preIntegrated[at] + cw.y * preIntegrated[at + 1] + cw.z * preIntegrated[at + 2] +
                     cw.w * preIntegrated[at + 3];
            colour += w * t.xyz;
          }
        }
      }
#else
      for (int part = 0; part * 4 < lanes; ++part) {  // the group's slabs
        int slab = group * (lanes / 4) + part;
        if (slab * 4 >= uCount) break;
        vec4 gs = fieldOf(uField, cell, slab, n.z);
        for (int c = 0; c < 4; ++c) {
          int s = slab * 4 + c;
          if (s >= uCount) break;
          vec3 toStar = stars[s].xyz - p;
          float w = nebulaStarWeight(uScattering * rho * dt, stars[s].w, dot(toStar, toStar));
          vec4 mLo;
          vec4 mHi;
          coefficients8(g + gs[c], mLo, mHi);
          acc[part * 4 + c] += w * mLo;
          if (lanes == 4) acc[4 + c] += w * mHi;
        }
      }
#endif
    }
#if !defined(NEBULA_REFERENCE) && !defined(NEBULA_ANALYTIC) && !defined(NEBULA_PRE_INTEGRATION)
    for (int c = 0; c < lanes && group * lanes + c < uCount; ++c)
      for (int j = 0; j < uCard; ++j)
        moments[((group * lanes + c) * uCard + j) * pixelCount + pixel] = j < 4 ? acc[c][j] : acc[4 + c][j - 4];
#endif
  }
  for (int ch = 0; ch < 3; ++ch) marched[ch * pixelCount + pixel] = colour[ch];
  for (int l = 0; l < uLineCount; ++l) marched[(3 + l) * pixelCount + pixel] = lineSum[l];
  if (lastItems) imageStore(uOpticalDepth, depthTexel, vec4(gCam));
}

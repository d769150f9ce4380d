// The nebula ray marcher's per-sample formulas (Barrès 2023, §3–4), outside the spectral
// integrals themselves (nebula_integrals.glsl): where a point falls between voxel centres, the
// weights of a Catmull–Rom lookup in the per-frame moment table, a star's single-scattering
// weight, and when a ray may stop. The CPU marcher (techniques/nebula/nebula_render.cpp) calls
// them in double and shaders/passes/nebula_march.comp in float, so that the GPU computes per
// pixel what the CPU computes and their twin test (techniques/nebula/gpu/) compares like with like.
//
// Compiled as GLSL after nebula_integrals.glsl, and as C++ beside it in float and double
// (techniques/nebula/nebula_integrals.h), through NEBULA_REAL / NEBULA_VEC4.
#ifndef NEBULA_REAL
#define NEBULA_REAL float
#define NEBULA_VEC4 vec4
#endif
#ifndef NEBULA_VEC3
#define NEBULA_VEC3 vec3
#endif

// The part of the segment p + t·d, t ∈ [0, tMax], inside the unit cube, as [t0, t1]; false when
// it misses the cube. The march clips its rays with it, the precomputation each voxel's segment to
// a star, and the lighting pass a surface point's (nebula_lighting.glsl).
PRISM_INLINE bool nebulaClipToCube(IN(NEBULA_VEC3) p, IN(NEBULA_VEC3) d, NEBULA_REAL tMax, OUT(NEBULA_REAL) t0,
                                   OUT(NEBULA_REAL) t1) {
  t0 = NEBULA_REAL(0.0f);
  t1 = tMax;
  for (int i = 0; i < 3; ++i) {
    if (abs(d[i]) < NEBULA_REAL(1e-15f)) {
      if (p[i] < NEBULA_REAL(0.0f) || p[i] > NEBULA_REAL(1.0f)) return false;
      continue;
    }
    NEBULA_REAL a = (NEBULA_REAL(0.0f) - p[i]) / d[i];
    NEBULA_REAL b = (NEBULA_REAL(1.0f) - p[i]) / d[i];
    t0 = max(t0, min(a, b));
    t1 = min(t1, max(a, b));
  }
  return t1 > t0;
}

// One axis of a trilinear lookup between voxel centres, clamped at the faces: the voxels i0 and
// i1 around u ∈ [0, 1] on an axis of n voxels (centres at (i + ½)/n), and i1's weight f.
PRISM_INLINE void nebulaTrilinearAxis(NEBULA_REAL u, int n, OUT(int) i0, OUT(int) i1, OUT(NEBULA_REAL) f) {
  NEBULA_REAL x = clamp(u * NEBULA_REAL(n) - NEBULA_REAL(0.5f), NEBULA_REAL(0.0f), NEBULA_REAL(n - 1));
  i0 = min(int(x), n - 1);
  i1 = min(i0 + 1, n - 1);
  f = x - NEBULA_REAL(i0);
}

// The four weights of a Catmull–Rom spline at t ∈ [0, 1) between entries 1 and 2 of four
// (the moment table's and the pre-integration table's lookups: smooth mⱼ(x), C¹, exact on cubics).
PRISM_INLINE NEBULA_VEC4 nebulaCatmullRomWeights(NEBULA_REAL t) {
  NEBULA_REAL t2 = t * t;
  NEBULA_REAL t3 = t2 * t;
  return NEBULA_VEC4(0.5f * (-t3 + 2.0f * t2 - t), 0.5f * (3.0f * t3 - 5.0f * t2 + 2.0f),
                     0.5f * (-3.0f * t3 + 4.0f * t2 + t), 0.5f * (t3 - t2));
}

// A star's single-scattering weight at a ray sample: σ₁ρΔt (the sample's scattering over its
// step) times the isotropic phase function 1/(4π), times the star's flux L/(4πd²) at distance d,
// with d² held at ≥ 1e-4 (a hundredth of the unit cube) so that a star inside the cloud stays
// finite at the voxels next to it. The spectral part, ∫ P_S·S·e^(−x/λ) dλ, multiplies it.
PRISM_INLINE NEBULA_REAL nebulaStarWeight(NEBULA_REAL scatteringTimesStep, NEBULA_REAL luminosity,
                                          NEBULA_REAL distance2) {
  NEBULA_REAL scatter = scatteringTimesStep / NEBULA_REAL(16.0f * kPi * kPi);
  return scatter * luminosity / max(distance2, NEBULA_REAL(1e-4f));
}

// Early termination: once the camera's optical depth g exceeds this (µm), the rest of the ray
// reaches the camera dimmed by e^(−g/λ) < 1e-6 at the band's reddest wavelength (0.78 µm:
// 0.78·ln 10⁶ = 10.8), so it cannot change a pixel beyond float's own rounding of the sum.
PRISM_INLINE bool nebulaRayOpaque(NEBULA_REAL cameraDepthUm) {
  return cameraDepthUm > NEBULA_REAL(10.8f);
}

// Stars or 2D elements one group of projection or light–density marches at once
// (nebula_march.comp keeps a group's moments in eight vec4): eight lanes while card(B) ≤ 4, four
// above; the host sizes its dispatches by it too (nebula_gpu_marcher.cpp).
PRISM_INLINE int nebulaGroupLanes(int card) { return card <= 4 ? 8 : 4; }

// Requires: spherical_harmonics.glsl prt.glsl
// PRT objects inside a medium (the scene's water: TechniqueSection::medium) or behind a nebula,
// dimmed as the lighting pass dims the rest of the scene (underwater.glsl, nebula_lighting.glsl),
// in PRT's spectral basis. The medium fills a box; a point at depth z below the box's top
// receives the distant environment through e^(−Kd·z) (the diffuse attenuation of light from
// above; σt for a medium that gives no Kd), and the camera sees it through e^(−σt·s), s the
// length of the view segment inside the box; a nebula's optical depth g in front of it (µm, its
// march's) dims it by e^(−g/λ). With T(λ) their product, the fragment's tristimulus is a sum over
// the projection's nodes q (prt_evaluation.h's PrtProjection):
//   XYZ = Σ_q T(λ_q)·e_q·ρ_q,   e_q = Σ_j Ê_j a_qj   (the irradiance at λ_q),
// for spectral PRT the 81 grid wavelengths with a_qj = φ_j(λ_q), on which the basis is
// orthonormal; for the 5 nm reference its chunk's wavelengths, a_q the q-th delta; for RGB-PRT
// the wavelengths R, G and B stand for. The reflectance side ρ_q is, for an untextured material,
// f_r(λ_q)·c̄(λ_q)·5 nm itself (RGB-PRT: its R̂_q), so the sum is exact wherever the light E lies
// in the basis's span, whatever T; a textured material has only its projection R̂, and takes
// ρ_q = Σ_k R̂_k a_qk: then the sum is Êᵀ·M(T)·R̂, M_jk = Σ_q T(λ_q)·a_qj·a_qk, exact only where
// T·E lies in the span too (which is why the basis takes attenuated light among its columns).
// With T ≡ 1 both give prtXyz back. The medium's light scattered into the view ray is the
// lighting pass's (the scene's directional lights).

// Per node, an std430 storage buffer of the forward pass (80 bytes, as in C++); and per material
// and node its ρ_q (vec4s: .xyz, at material · nodeCount + q).
const int kPrtMediumNodesBinding = 10;
const int kPrtNodeReflectancesBinding = 11;
struct PrtMediumNode {
  vec4 a[4];          // a_qj for j < 16: a[j / 4][j % 4]
  vec4 coefficients;  // σt (1/m), Kd (1/m), λ (nm), 0
};

PRISM_INLINE float prtNodeBasis(IN(PrtMediumNode) node, int j) { return node.a[j / 4][j % 4]; }

// The length of the segment from `origin` to `point` that lies inside the box (slabs).
PRISM_INLINE float prtMediumViewPath(IN(vec3) origin, IN(vec3) point, IN(vec3) boxMin, IN(vec3) boxMax) {
  PRISM_PRECISE vec3 d = point - origin;
  float tIn = 0.0f;
  float tOut = 1.0f;
  for (int i = 0; i < 3; ++i) {
    if (abs(d[i]) < 1e-20f) {
      if (origin[i] < boxMin[i] || origin[i] > boxMax[i]) return 0.0f;
    } else {
      float t0 = (boxMin[i] - origin[i]) / d[i];
      float t1 = (boxMax[i] - origin[i]) / d[i];
      tIn = max(tIn, min(t0, t1));
      tOut = min(tOut, max(t0, t1));
    }
  }
  return max(tOut - tIn, 0.0f) * length(d);
}

// Depth of a point below the box's top; 0 outside the box.
PRISM_INLINE float prtMediumDepth(IN(vec3) point, IN(vec3) boxMin, IN(vec3) boxMax) {
  for (int i = 0; i < 3; ++i) {
    if (point[i] < boxMin[i] || point[i] > boxMax[i]) return 0.0f;
  }
  return boxMax.y - point.y;
}

// T(λ_q) = e^(−σt·viewPath − Kd·depth − g/λ_q), g the nebula's optical depth in µm.
PRISM_INLINE float prtMediumTransmittance(IN(PrtMediumNode) node, float viewPathM, float depthM, float nebulaDepthUm) {
  return exp(-node.coefficients.x * viewPathM - node.coefficients.y * depthM -
             nebulaDepthUm * 1000.0f / node.coefficients.z);
}

// e_q = Σ_j Ê_j a_qj over j < basisCount.
PRISM_INLINE float prtNodeIrradiance(IN(PrtBasisIrradiance) irradiance, int basisCount, IN(PrtMediumNode) node) {
  float e = 0.0f;
  for (int j = 0; j < basisCount; ++j) e += irradiance.e[j] * prtNodeBasis(node, j);
  return e;
}

// A textured material's ρ_q: its projection, Σ_k R̂_k a_qk over k < basisCount.
PRISM_INLINE vec3 prtNodeReflectance(IN(PrtReflectance) reflectance, int basisCount, IN(PrtMediumNode) node) {
  vec3 r = vec3(0.0f);
  for (int k = 0; k < basisCount; ++k) r += reflectance.r[k] * prtNodeBasis(node, k);
  return r;
}

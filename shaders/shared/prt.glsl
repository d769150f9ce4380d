// Requires: spherical_harmonics.glsl
// Spectral precomputed radiance transfer at run time (Schwenk, Kuijper & Bockholt, "Spectral
// precomputed radiance transfer", Fraunhofer IGD): two orthonormal bases turn the shading
// integral XYZ = ∫∫ L(ω, λ) T(ω) f_r(λ) c̄(λ) dω dλ into two sums of products.
//
//  - light transport: T(ω) = V(ω)·max(cos θ, 0) projected on 25 real SH (spherical_harmonics.glsl);
//  - wavelength: basis functions φ_j(λ), j < m, from the SVD of the scene's spectra (Peercy 1993,
//    "Linear color representations for full spectral rendering"); the environment is
//    L(ω, λ) ≈ Σ_j Σ_k L̃_jk φ_j(λ) ψ_k(ω), and each reflectance premultiplied by a colour-matching
//    function is projected, R̂_j,c = ∫ φ_j f_r c̄ dλ.
//
// Per vertex Ê_j = Σ_k L̃_jk T̃_k (the vertex's irradiance spectrum in the basis); per fragment
// XYZ = Σ_j Ê_j R̂_j. Both sums are here, once, for the GPU and for the CPU twin in
// techniques/prt, which also runs its two baselines through them: RGB-PRT (m = 3 "basis
// functions", the three display primaries, R̂_c = ρ_c · the primary's XYZ) and the 5 nm point
// sampling reference (a basis of 81 deltas, in chunks of kPrtMaxBasis).

const int kPrtMaxBasis = 16;

// L̃: the environment's SH coefficients per spectral basis function (basis[j].c[k] = L̃_jk).
struct PrtEnvironment {
  Sh25 basis[16];
};

// Ê: a vertex's irradiance per spectral basis function.
struct PrtBasisIrradiance {
  float e[16];
};

// R̂: a reflectance × (x̄, ȳ, z̄) per spectral basis function (one vec3 per j).
struct PrtReflectance {
  vec3 r[16];
};

// Ê_j = Σ_k L̃_jk T̃_k for j < basisCount (≤ kPrtMaxBasis); the rest are 0.
PRISM_INLINE PrtBasisIrradiance prtVertexIrradiance(IN(PrtEnvironment) environment, IN(Sh25) transfer,
                                                    int basisCount) {
  PrtBasisIrradiance irradiance;
  for (int j = 0; j < kPrtMaxBasis; ++j) {
    irradiance.e[j] = j < basisCount ? shDot(environment.basis[j], transfer) : 0.0f;
  }
  return irradiance;
}

// XYZ = Σ_j Ê_j R̂_j over j < basisCount.
PRISM_INLINE vec3 prtXyz(IN(PrtBasisIrradiance) irradiance, IN(PrtReflectance) reflectance, int basisCount) {
  vec3 xyz = vec3(0.0f);
  for (int j = 0; j < basisCount; ++j) xyz += irradiance.e[j] * reflectance.r[j];
  return xyz;
}

// What a PRT fragment adds: its XYZ with each channel clamped at 0. A 25-term SH environment rings
// below zero beside a small bright source (a sun in a map: order 5 holds no lobe narrower than
// about 40°), and a vertex turned away from it gets negative irradiance; light is never negative
// and a real spectrum's tristimulus is ≥ 0 in every channel (x̄, ȳ, z̄ and a camera's curves are),
// so a negative channel shows as 0. The reference mode's chunks of 16 wavelengths are drawn, and
// so clamped, each on its own: under an environment of one colour that is the total's clamp (its
// ringing is negative at every wavelength or at none), but where the ringing's colour varies (a
// warm sun in a blue sky) a chunk's positive light is kept beside another's negative, so there,
// and only there, the reference shows more light than a clamp of its whole sum would.
PRISM_INLINE vec3 prtShownXyz(vec3 xyz) { return max(xyz, vec3(0.0f)); }

// The renderer's PRT forward pass (techniques/prt/gpu/prt_pass.cpp, shaders/passes/prt.*): three
// std430 storage buffers, laid out here for both sides — per vertex its Sh25 transfer (100 bytes,
// std430's float-array stride is 4 as in C++), the PrtEnvironment (1600 bytes) and per material
// a PrtGpuMaterial: R̂ with each vec3 in a vec4, since std430 strides a vec3 array by 16 bytes
// and C++ by 12 (prt_layout.h checks the sizes).
const int kPrtTransferBinding = 7;
const int kPrtEnvironmentBinding = 8;
const int kPrtMaterialsBinding = 9;
// A textured material's R̂ (techniques/prt/prt_texture.h): a sampler2DArray of RGBA16F, layer j
// holding R̂_j in .rgb, sampled at the fragment's uv in place of the material's PrtGpuMaterial.
const int kPrtReflectanceTextureUnit = 0;

struct PrtGpuMaterial {
  vec4 r[16];  // .xyz = R̂_j, .w = 0
};

PRISM_INLINE PrtGpuMaterial prtGpuMaterial(IN(PrtReflectance) reflectance) {
  PrtGpuMaterial m;
  for (int j = 0; j < kPrtMaxBasis; ++j) m.r[j] = vec4(reflectance.r[j], 0.0f);
  return m;
}

PRISM_INLINE PrtReflectance prtReflectance(IN(PrtGpuMaterial) material) {
  PrtReflectance r;
  for (int j = 0; j < kPrtMaxBasis; ++j) r.r[j] = vec3(material.r[j]);
  return r;
}

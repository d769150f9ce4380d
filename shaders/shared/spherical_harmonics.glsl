// Real spherical harmonics, the first five bands (l = 0..4, 25 functions), for precomputed
// radiance transfer: the transfer of a vertex, the environment per spectral basis function and
// the clamped-cosine lobe are all vectors of 25 coefficients, and light transport is their dot
// product (Sloan, Kautz & Snyder 2002, "Precomputed Radiance Transfer for Real-Time Rendering in
// Dynamic, Low-Frequency Lighting Environments", §4).
//
// Basis: the orthonormal real harmonics in Cartesian form of a unit vector (x, y, z), z the polar
// axis, without the Condon–Shortley phase; index k = l(l + 1) + m, m = −l..l (Sloan 2008, "Stupid
// Spherical Harmonics (SH) Tricks", Appendix A2, whose constants are these). Constants are
// N_lm = sqrt((2l+1)/(4π) · (l−|m|)!/(l+|m|)!) (×√2 for m ≠ 0) folded with the polynomial's
// leading factor; sh_test checks orthonormality by quadrature, so a typo cannot hide.

const int kShBands = 5;
const int kShCoefficients = 25;

struct Sh25 {
  float c[25];
};

PRISM_INLINE Sh25 shZero() {
  Sh25 s;
  for (int k = 0; k < kShCoefficients; ++k) s.c[k] = 0.0f;
  return s;
}

// The 25 basis functions at a unit direction.
PRISM_INLINE Sh25 shEvaluate(IN(vec3) dir) {
  float x = dir.x;
  float y = dir.y;
  float z = dir.z;
  float x2 = x * x;
  float y2 = y * y;
  float z2 = z * z;
  Sh25 s;
  // l = 0
  s.c[0] = 0.28209479177387814f;
  // l = 1
  s.c[1] = 0.4886025119029199f * y;
  s.c[2] = 0.4886025119029199f * z;
  s.c[3] = 0.4886025119029199f * x;
  // l = 2
  s.c[4] = 1.0925484305920792f * x * y;
  s.c[5] = 1.0925484305920792f * y * z;
  s.c[6] = 0.31539156525252005f * (3.0f * z2 - 1.0f);
  s.c[7] = 1.0925484305920792f * x * z;
  s.c[8] = 0.5462742152960396f * (x2 - y2);
  // l = 3
  s.c[9] = 0.5900435899266435f * y * (3.0f * x2 - y2);
  s.c[10] = 2.890611442640554f * x * y * z;
  s.c[11] = 0.4570457994644658f * y * (5.0f * z2 - 1.0f);
  s.c[12] = 0.3731763325901154f * z * (5.0f * z2 - 3.0f);
  s.c[13] = 0.4570457994644658f * x * (5.0f * z2 - 1.0f);
  s.c[14] = 1.445305721320277f * z * (x2 - y2);
  s.c[15] = 0.5900435899266435f * x * (x2 - 3.0f * y2);
  // l = 4
  s.c[16] = 2.5033429417967046f * x * y * (x2 - y2);
  s.c[17] = 1.7701307697799304f * y * z * (3.0f * x2 - y2);
  s.c[18] = 0.9461746957575601f * x * y * (7.0f * z2 - 1.0f);
  s.c[19] = 0.6690465435572892f * y * z * (7.0f * z2 - 3.0f);
  s.c[20] = 0.10578554691520431f * (35.0f * z2 * z2 - 30.0f * z2 + 3.0f);
  s.c[21] = 0.6690465435572892f * x * z * (7.0f * z2 - 3.0f);
  s.c[22] = 0.47308734787878004f * (x2 - y2) * (7.0f * z2 - 1.0f);
  s.c[23] = 1.7701307697799304f * x * z * (x2 - 3.0f * y2);
  s.c[24] = 0.6258357354491761f * (x2 * (x2 - 3.0f * y2) - y2 * (3.0f * x2 - y2));
  return s;
}

// Σ_k a_k b_k: the integral over the sphere of the product of two band-limited functions
// (orthonormality). With a = the environment's radiance and b = a vertex's transfer, it is the
// vertex's (shadowed) irradiance (Sloan et al. 2002, Eq. 7).
PRISM_INLINE float shDot(IN(Sh25) a, IN(Sh25) b) {
  float sum = 0.0f;
  for (int k = 0; k < kShCoefficients; ++k) sum += a.c[k] * b.c[k];
  return sum;
}

// The band l (0..4) of coefficient k.
PRISM_INLINE int shBand(int k) {
  if (k < 1) return 0;
  if (k < 4) return 1;
  if (k < 9) return 2;
  if (k < 16) return 3;
  return 4;
}

// The convolution weight of the clamped cosine max(cos θ, 0) per band: Â_l = 2π ∫₀¹ t P_l(t) dt
// (Funk–Hecke), i.e. π, 2π/3, π/4, 0, −π/24 (Ramamoorthi & Hanrahan 2001, "An Efficient
// Representation for Irradiance Environment Maps", Eq. 8).
PRISM_INLINE float shClampedCosineBandWeight(int band) {
  if (band == 0) return kPi;
  if (band == 1) return 2.0f * kPi / 3.0f;
  if (band == 2) return kPi / 4.0f;
  if (band == 3) return 0.0f;
  return -kPi / 24.0f;
}

// The unshadowed transfer of a surface with unit normal n: the SH projection of max(n·ω, 0),
// Â_l Y_lm(n) (Funk–Hecke). Dotted with an environment it is Ramamoorthi & Hanrahan's irradiance.
PRISM_INLINE Sh25 shClampedCosine(IN(vec3) normal) {
  Sh25 s = shEvaluate(normal);
  for (int k = 0; k < kShCoefficients; ++k) s.c[k] *= shClampedCosineBandWeight(shBand(k));
  return s;
}

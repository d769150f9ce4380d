// Reflection models evaluated per wavelength, four at a time (a vec4 batch), or per RGB channel
// in RGB mode: the same code either way.
//
// Cook–Torrance as in UE4 (Karis 2013, "Real Shading in Unreal Engine 4"):
//   f(l, v) = (1 − F(v, h))·(1 − metallic)·albedo/π + D(h)·G(l, v)·F(v, h) / (4·(n·l)·(n·v))
//   (the diffuse lobe gets the light the specular one does not reflect, as in Pérez García 2024
//   and sRAT-RT; UE4 itself drops the (1 − F))
//   D  GGX / Trowbridge–Reitz with α = roughness² (perceptual roughness squared)
//   G  Smith with Schlick's approximation, k = (roughness + 1)²/8 (Karis's remapping for
//      analytic lights; the issue's "(α+1)²/8" with α read as the perceptual roughness)
//   F  Schlick, F0 = mix(0.04, albedo, metallic)
// Conductors replace F by the exact unpolarised Fresnel reflectance of a complex index n + ik
// (measured per wavelength) and have no diffuse lobe.
//
// D·G/(4·n·l·n·v) does not depend on the wavelength, so it is computed once per pixel and light
// (MicrofacetTerms); only F and the albedo are evaluated per batch.

// GGX in Filament's form: 1 − (n·h)² given as |n × h|², which keeps its precision near the
// highlight's peak (n·h → 1), where a2·(n·h)² + 1 − (n·h)² cancels for smooth surfaces.
PRISM_INLINE float ggxDistribution(float nDotH, float oneMinusNDotHSquared, float alpha) {
  PRISM_PRECISE float a = nDotH * alpha;
  PRISM_PRECISE float k = alpha / (oneMinusNDotHSquared + a * a);
  return k * k * (1.0f / kPi);
}

PRISM_INLINE float smithSchlickK(float roughness) {
  float r1 = roughness + 1.0f;
  return r1 * r1 / 8.0f;
}

PRISM_INLINE float smithSchlickG1(float nDotX, float k) { return nDotX / (nDotX * (1.0f - k) + k); }

// Schlick's Fresnel per wavelength: F0 + (1 − F0)·(1 − cos)⁵.
PRISM_INLINE vec4 schlickFresnel(IN(vec4) f0, float cosTheta) {
  float m = clamp(1.0f - cosTheta, 0.0f, 1.0f);
  float m2 = m * m;
  return f0 + (vec4(1.0f) - f0) * (m2 * m2 * m);
}

// Unpolarised Fresnel reflectance at a conductor of complex index n + ik seen from a medium of
// index 1 (pbrt-v3 FrConductor, Lazányi & Szirmay-Kalos's closed form of Rs and Rp).
PRISM_INLINE vec4 conductorFresnel(IN(vec4) n, IN(vec4) k, float cosTheta) {
  float c = clamp(cosTheta, 0.0f, 1.0f);
  float cos2 = c * c;
  float sin2 = 1.0f - cos2;
  vec4 n2 = n * n;
  vec4 k2 = k * k;
  vec4 t0 = n2 - k2 - vec4(sin2);
  vec4 a2PlusB2 = sqrt(t0 * t0 + 4.0f * n2 * k2);
  vec4 t1 = a2PlusB2 + vec4(cos2);
  vec4 a = sqrt(max(0.5f * (a2PlusB2 + t0), vec4(0.0f)));
  vec4 t2 = 2.0f * c * a;
  vec4 rs = (t1 - t2) / (t1 + t2);
  vec4 t3 = cos2 * a2PlusB2 + vec4(sin2 * sin2);
  vec4 t4 = t2 * sin2;
  vec4 rp = rs * (t3 - t4) / (t3 + t4);
  return 0.5f * (rp + rs);
}

// The wavelength-independent part of one light's reflection at one pixel.
struct MicrofacetTerms {
  float cosLight;        // n·l, clamped to 0 (0: the light is behind the surface)
  float specular;        // D·G / (4·n·l·n·v), the factor F multiplies
  float cosHalf;         // v·h, Fresnel's angle
  float diffuseFresnel;  // 1: the diffuse lobe keeps (1 − F) of the light; 0: all of it
};

// n, v, l unit vectors (v towards the viewer, l towards the light).
PRISM_INLINE MicrofacetTerms microfacetTerms(IN(vec3) n, IN(vec3) v, IN(vec3) l, float roughness) {
  MicrofacetTerms t;
  float nDotL = dot(n, l);
  float nDotV = max(dot(n, v), 1e-4f);
  t.cosLight = max(nDotL, 0.0f);
  t.specular = 0.0f;
  t.cosHalf = 1.0f;
  t.diffuseFresnel = 1.0f;
  if (nDotL <= 0.0f) return t;
  PRISM_PRECISE vec3 h = normalize(v + l);
  PRISM_PRECISE vec3 nCrossH = cross(n, h);
  PRISM_PRECISE float nDotH = max(dot(n, h), 0.0f);
  PRISM_PRECISE float oneMinusNDotHSquared = dot(nCrossH, nCrossH);
  t.cosHalf = max(dot(v, h), 0.0f);
  float r = max(roughness, 0.02f);  // a perfect mirror has no analytic-light highlight
  float k = smithSchlickK(r);
  float g = smithSchlickG1(nDotL, k) * smithSchlickG1(nDotV, k);
  t.specular = ggxDistribution(nDotH, oneMinusNDotHSquared, r * r) * g / (4.0f * nDotL * nDotV);
  return t;
}

// The terms of a Lambertian surface (the thesis's test spheres): the diffuse lobe alone, all of
// the light, no specular lobe to share it with.
PRISM_INLINE MicrofacetTerms lambertianTerms(IN(MicrofacetTerms) t) {
  MicrofacetTerms l = t;
  l.specular = 0.0f;
  l.diffuseFresnel = 0.0f;
  return l;
}

// BRDF·cos of the metallic–roughness model for four wavelengths of albedo.
PRISM_INLINE vec4 metallicRoughnessReflection(IN(MicrofacetTerms) t, IN(vec4) albedo,
                                               float metallic) {
  vec4 f0 = mix(vec4(0.04f), albedo, metallic);
  vec4 f = schlickFresnel(f0, t.cosHalf);
  vec4 diffuse = (1.0f - metallic) * albedo * (1.0f / kPi) * (vec4(1.0f) - f * t.diffuseFresnel);
  return (diffuse + t.specular * f) * t.cosLight;
}

// BRDF·cos of a conductor for four wavelengths of n and k.
PRISM_INLINE vec4 conductorReflection(IN(MicrofacetTerms) t, IN(vec4) n, IN(vec4) k) {
  return t.specular * conductorFresnel(n, k, t.cosHalf) * t.cosLight;
}

// BRDF·cos of a surface: a conductor (albedoOrN holds n, conductorK holds k) or the
// metallic–roughness model (albedoOrN holds the albedo). The rasteriser and the reference both
// choose through here.
PRISM_INLINE vec4 surfaceReflection(IN(MicrofacetTerms) t, bool conductor, IN(vec4) albedoOrN,
                                    IN(vec4) conductorK, float metallic) {
  if (conductor) return conductorReflection(t, albedoOrN, conductorK);
  return metallicRoughnessReflection(t, albedoOrN, metallic);
}

// Hillaire 2020's sky, per batch of four wavelengths, on the medium of atmosphere_model.glsl:
// the transmittance table (optical depth to the top of the atmosphere per radius and zenith
// cosine), the multiple-scattering table Ψ_ms (per sun zenith cosine and radius), the sky-view
// table (in-scattered radiance seen from the camera per zenith angle and azimuth from the sun)
// and the aerial-perspective volume (in-scattering and transmittance per froxel), plus the
// lookups the lighting pass makes into them.
//
// The tables hold optical depth, not transmittance: bilinear interpolation of a smooth exponent
// is far more accurate than of its exponential near the horizon. Lookups are bilinear on texel
// centres, written out here so that both sides agree (GPU filtering has 8-bit weights).
//
// Integration along a view ray (integrateView): the ray is split where it enters and leaves
// the planet's shadow (the sun's term is 0 there, multiple scattering is not) and at its lowest
// point; each piece is integrated with Hillaire's per-step form ∫ T·S = T·S·(1 − e^(−σt·Δt))/σt.
// Radiance comes out per unit solar irradiance (the caller multiplies it in), so Ψ_ms is
// independent of the solar spectrum.
//
// Each side defines, before including this file (batch b's tables):
//   vec4 transmittanceLutTexel(int b, int x, int y);        optical depth
//   vec4 multipleScatteringLutTexel(int b, int x, int y);   Ψ_ms (never called while the table is
//                                                           being built: its rays have
//                                                           multipleScattering off)
// Requires: atmosphere_model.glsl atmosphere_luts_accessors.glsl

PRISM_INLINE float texelCentreCoordinate(float unit, int size, OUT(int) i0) {
  float f = clamp(unit, 0.0f, 1.0f) * float(size - 1);
  i0 = min(int(floor(f)), size - 2);
  return f - float(i0);
}

PRISM_INLINE vec4 transmittanceOpticalDepth(IN(GpuAtmosphere) a, int b, float r, float mu) {
  vec2 unit = transmittanceLutCoordinates(a, r, mu);
  int x0, y0;
  float fx = texelCentreCoordinate(unit.x, kTransmittanceLutWidth, x0);
  float fy = texelCentreCoordinate(unit.y, kTransmittanceLutHeight, y0);
  vec4 bottom = mix(transmittanceLutTexel(b, x0, y0), transmittanceLutTexel(b, x0 + 1, y0), fx);
  vec4 top = mix(transmittanceLutTexel(b, x0, y0 + 1), transmittanceLutTexel(b, x0 + 1, y0 + 1), fx);
  return mix(bottom, top, fy);
}

// Transmittance from a point at radius r towards a direction of zenith cosine μ, to space;
// zero when the ground is in the way.
PRISM_INLINE vec4 transmittanceToSpace(IN(GpuAtmosphere) a, int b, float r, float mu) {
  if (rayIntersectsGround(a, r, mu)) return vec4(0.0f);
  return exp(-transmittanceOpticalDepth(a, b, r, mu));
}

PRISM_INLINE vec4 multipleScatteringAt(IN(GpuAtmosphere) a, int b, float r, float muSun) {
  int x0, y0;
  float fx = texelCentreCoordinate((muSun + 1.0f) * 0.5f, kMultipleScatteringLutSize, x0);
  float fy = texelCentreCoordinate((r - a.shape.x) / (a.shape.y - a.shape.x),
                                   kMultipleScatteringLutSize, y0);
  vec4 bottom = mix(multipleScatteringLutTexel(b, x0, y0), multipleScatteringLutTexel(b, x0 + 1, y0), fx);
  vec4 top = mix(multipleScatteringLutTexel(b, x0, y0 + 1),
                 multipleScatteringLutTexel(b, x0 + 1, y0 + 1), fx);
  return mix(bottom, top, fy);
}

// (1 − e^(−x·Δt))/x per wavelength, exact as x·Δt → 0.
PRISM_INLINE float stepIntegral1(float x, float dt) {
  float xt = x * dt;
  if (xt < 1e-3f) return dt * (1.0f - xt * 0.5f + xt * xt / 6.0f);
  return (1.0f - exp(-xt)) / x;
}
PRISM_INLINE vec4 stepIntegral(IN(vec4) x, float dt) {
  return vec4(stepIntegral1(x.x, dt), stepIntegral1(x.y, dt), stepIntegral1(x.z, dt),
              stepIntegral1(x.w, dt));
}

struct ScatteringIntegral {
  vec4 radiance;       // in-scattered, per unit solar irradiance
  vec4 transmittance;  // of the path integrated so far
  vec4 scattering;     // ∫ T·(σs_R + σs_M) dt: Hillaire's f_ms before its isotropic phase
};

PRISM_INLINE ScatteringIntegral emptyScatteringIntegral() {
  ScatteringIntegral s;
  s.radiance = vec4(0.0f);
  s.transmittance = vec4(1.0f);
  s.scattering = vec4(0.0f);
  return s;
}

// What one ray integrates: where it starts (planet frame), where it looks, the sun, and the
// phase values (constant along the ray: the sun's rays are parallel).
struct ViewRay {
  vec3 origin;
  vec3 direction;
  vec3 sun;
  float phaseRayleigh;
  float phaseMie;
  bool multipleScattering;
};

// [t0, t1], all lit or all shadowed, crowded towards one end, added to acc in order of t.
PRISM_INLINE void integratePiece(IN(GpuAtmosphere) a, int b, IN(ViewRay) ray, float t0, float t1,
                                 bool lit, bool towardsStart, int steps,
                                 INOUT(ScatteringIntegral) acc) {
  if (t1 <= t0) return;
  for (int k = 0; k < steps; ++k) {
    RaySample s = crowdedSample(t0, t1, towardsStart ? k : steps - 1 - k, steps, towardsStart);
    vec3 p = ray.origin + ray.direction * s.t;
    float r = length(p);
    float muSun = dot(p, ray.sun) / r;
    AtmosphereDensity d = atmosphereDensity(a, r - a.shape.x);
    vec4 rayleigh = rayleighScatteringAt(a, d);
    vec4 mie = mieScatteringAt(a, d);
    vec4 extinction = atmosphereExtinction(a, d);
    vec4 source = vec4(0.0f);
    if (lit) {
      source = exp(-transmittanceOpticalDepth(a, b, r, muSun)) *
               (rayleigh * ray.phaseRayleigh + mie * ray.phaseMie);
    }
    if (ray.multipleScattering) source += multipleScatteringAt(a, b, r, muSun) * (rayleigh + mie);
    vec4 integral = stepIntegral(extinction, s.dt);
    acc.radiance += acc.transmittance * source * integral;
    acc.scattering += acc.transmittance * (rayleigh + mie) * integral;
    acc.transmittance *= exp(-extinction * s.dt);
  }
}

// [t0, t1] of one light state, split at the ray's lowest point tLow so samples crowd there.
PRISM_INLINE void integrateRange(IN(GpuAtmosphere) a, int b, IN(ViewRay) ray, float t0, float t1,
                                 bool lit, float tLow, int steps, INOUT(ScatteringIntegral) acc) {
  if (tLow > t0 && tLow < t1) {
    integratePiece(a, b, ray, t0, tLow, lit, false, steps, acc);
    integratePiece(a, b, ray, tLow, t1, lit, true, steps, acc);
  } else {
    integratePiece(a, b, ray, t0, t1, lit, tLow <= t0, steps, acc);
  }
}

// The ray from t0 to t1: lit, shadowed, lit again (any of them possibly empty).
PRISM_INLINE void integrateView(IN(GpuAtmosphere) a, int b, IN(ViewRay) ray, float t0, float t1,
                                int steps, INOUT(ScatteringIntegral) acc) {
  ShadowInterval shadow = planetShadowInterval(a, ray.origin, ray.direction, ray.sun);
  float r = length(ray.origin);
  float tLow = max(-dot(ray.origin, ray.direction), 0.0f);
  if (r <= 0.0f) tLow = 0.0f;
  float s0 = clamp(shadow.t0, t0, t1), s1 = clamp(shadow.t1, t0, t1);
  if (s1 <= s0) {
    integrateRange(a, b, ray, t0, t1, true, tLow, steps, acc);
    return;
  }
  integrateRange(a, b, ray, t0, s0, true, tLow, steps, acc);
  integrateRange(a, b, ray, s0, s1, false, tLow, steps, acc);
  integrateRange(a, b, ray, s1, t1, true, tLow, steps, acc);
}

// Radiance (per unit solar irradiance) that a lit ground point sends up: Lambertian albedo.
PRISM_INLINE vec4 groundRadiance(IN(GpuAtmosphere) a, int b, IN(vec3) groundPoint, IN(vec3) sun) {
  float r = length(groundPoint);
  float muSun = dot(groundPoint, sun) / r;
  if (muSun <= 0.0f) return vec4(0.0f);
  return transmittanceToSpace(a, b, r, muSun) * (muSun * a.ozoneMie.w / kPi);
}

// --- Transmittance table texel -------------------------------------------------------------
PRISM_INLINE vec4 transmittanceLutValue(IN(GpuAtmosphere) a, int x, int y) {
  vec2 unit = vec2(float(x) / float(kTransmittanceLutWidth - 1),
                   float(y) / float(kTransmittanceLutHeight - 1));
  RadiusCosine rc = transmittanceLutParameters(a, unit);
  return opticalDepthToTop(a, rc.r, rc.mu);
}

// The transmittance table without its wavelengths: `a` with unit coefficients, one constituent
// per channel (x Rayleigh, y Mie extinction, z ozone, w none), whose table holds each
// constituent's optical depth. Optical depth is linear in the coefficients, so every batch of an
// atmosphere of that shape combines its table from that one (transmittanceFromDensities): one
// integration for any number of batches, equal to each batch's own up to float reassociation.
PRISM_INLINE GpuAtmosphere unitCoefficientAtmosphere(IN(GpuAtmosphere) a) {
  GpuAtmosphere u = a;
  u.rayleighScattering = vec4(1.0f, 0.0f, 0.0f, 0.0f);
  u.mieExtinction = vec4(0.0f, 1.0f, 0.0f, 0.0f);
  u.ozoneAbsorption = vec4(0.0f, 0.0f, 1.0f, 0.0f);
  return u;
}
PRISM_INLINE vec4 transmittanceFromDensities(IN(GpuAtmosphere) a, IN(vec4) densities) {
  return a.rayleighScattering * densities.x + a.mieExtinction * densities.y + a.ozoneAbsorption * densities.z;
}

// --- Multiple-scattering table texel (Hillaire 2020, §5.5) ---------------------------------
// Second-order radiance L₂ and transfer f_ms over 64 directions (a spherical Fibonacci set),
// isotropic phase, from a point at radius r under a sun of zenith cosine μ_s:
// Ψ_ms = L₂ / (1 − f_ms), the infinite series of higher orders.
PRISM_INLINE vec3 sphericalFibonacci(int i, int n) {
  float z = 1.0f - (2.0f * float(i) + 1.0f) / float(n);
  float radius = sqrt(max(1.0f - z * z, 0.0f));
  float phi = float(i) * 2.39996322972865f;  // the golden angle
  return vec3(radius * cos(phi), z, radius * sin(phi));
}

PRISM_INLINE vec4 multipleScatteringLutValue(IN(GpuAtmosphere) a, int b, int x, int y) {
  float muSun = float(x) / float(kMultipleScatteringLutSize - 1) * 2.0f - 1.0f;
  float height = float(y) / float(kMultipleScatteringLutSize - 1) * (a.shape.y - a.shape.x);
  float r = a.shape.x + max(height, 1e-3f);
  ViewRay ray;
  ray.origin = vec3(0.0f, r, 0.0f);
  ray.sun = vec3(sqrt(max(1.0f - muSun * muSun, 0.0f)), muSun, 0.0f);
  ray.phaseRayleigh = 1.0f / (4.0f * kPi);
  ray.phaseMie = ray.phaseRayleigh;
  ray.multipleScattering = false;
  vec4 secondOrder = vec4(0.0f), transfer = vec4(0.0f);
  for (int i = 0; i < kMultipleScatteringDirections; ++i) {
    ray.direction = sphericalFibonacci(i, kMultipleScatteringDirections);
    float mu = ray.direction.y;
    float tMax = distanceToAtmosphereExit(a, r, mu);
    ScatteringIntegral acc = emptyScatteringIntegral();
    integrateView(a, b, ray, 0.0f, tMax, kMultipleScatteringSteps, acc);
    if (rayIntersectsGround(a, r, mu)) {
      acc.radiance += acc.transmittance * groundRadiance(a, b, ray.origin + ray.direction * tMax, ray.sun);
    }
    secondOrder += acc.radiance;
    transfer += acc.scattering;
  }
  // L₂ = ∫ L·(1/4π) dω and f_ms = ∫ (∫ T·σs dt)·(1/4π) dω: over directions uniform on the
  // sphere, both are plain means.
  secondOrder /= float(kMultipleScatteringDirections);
  transfer /= float(kMultipleScatteringDirections);
  return secondOrder / (vec4(1.0f) - min(transfer, vec4(0.999f)));
}

// --- Sky-view table ------------------------------------------------------------------------
// Seen from radius r, in cosines (no trigonometry: the lookups must agree on every driver):
// v ∈ [0, 0.5) covers zenith → horizon and (0.5, 1] horizon → nadir, with the zenith cosine
// c = c_h + (1 − c_h)·(1 − 2v)² above and c_h − (1 + c_h)·(2v − 1)² below the horizon cosine
// c_h of a camera at r (crowded towards the horizon); u covers the azimuth from the sun's
// vertical plane with cos φ = 1 − 2u² (φ from 0 to π; the sky is symmetric about that plane,
// and the aureole round the sun is sharp).
PRISM_INLINE float horizonCosine(IN(GpuAtmosphere) a, float r) {
  return -sqrt(max(squaredDifference(r, a.shape.x), 0.0f)) / r;
}

// The zenith cosine at coordinate v, for a horizon cosine ch.
PRISM_INLINE float skyViewZenithCosine(float ch, float v) {
  if (v < 0.5f) {
    float s = 1.0f - 2.0f * v;
    return ch + (1.0f - ch) * s * s;
  }
  float s = 2.0f * v - 1.0f;
  return ch - (1.0f + ch) * s * s;
}

// The direction of sky-view coordinates, in the table's frame: y up, the sun in the xy plane
// towards +x.
PRISM_INLINE vec3 skyViewDirection(IN(GpuAtmosphere) a, float r, vec2 unit) {
  float c = skyViewZenithCosine(horizonCosine(a, r), unit.y);
  float cosPhi = 1.0f - 2.0f * unit.x * unit.x;
  float sinTheta = sqrt(max(1.0f - c * c, 0.0f));
  float sinPhi = sqrt(max(1.0f - cosPhi * cosPhi, 0.0f));
  return vec3(sinTheta * cosPhi, c, sinTheta * sinPhi);
}

PRISM_INLINE vec2 skyViewCoordinates(IN(GpuAtmosphere) a, float r, float cosZenith, float cosAzimuth) {
  float ch = horizonCosine(a, r);
  float v = cosZenith > ch ? 0.5f * (1.0f - sqrt(max((cosZenith - ch) / (1.0f - ch), 0.0f)))
                           : 0.5f * (1.0f + sqrt(max((ch - cosZenith) / (1.0f + ch), 0.0f)));
  float u = sqrt(clamp((1.0f - cosAzimuth) * 0.5f, 0.0f, 1.0f));
  return vec2(u, v);
}

// Radiance (W·m⁻²·sr⁻¹·nm⁻¹, solar irradiance applied) arriving at the camera at radius r from
// the unit direction d of the table's frame, sun at zenith cosine μ_s. withGround adds the
// ground's reflection where the ray meets it.
PRISM_INLINE vec4 skyRadiance(IN(GpuAtmosphere) a, int b, float r, float muSun, IN(vec3) d,
                              bool withGround) {
  ViewRay ray;
  ray.origin = vec3(0.0f, r, 0.0f);
  ray.sun = vec3(sqrt(max(1.0f - muSun * muSun, 0.0f)), muSun, 0.0f);
  ray.direction = d;
  float nu = dot(ray.direction, ray.sun);
  ray.phaseRayleigh = rayleighPhase(nu);
  ray.phaseMie = miePhase(a.ozoneMie.z, nu);
  ray.multipleScattering = a.options.x > 0.5f;
  float mu = ray.direction.y;
  float tMax = distanceToAtmosphereExit(a, r, mu);
  ScatteringIntegral acc = emptyScatteringIntegral();
  integrateView(a, b, ray, 0.0f, tMax, kSkySteps, acc);
  if (withGround && rayIntersectsGround(a, r, mu)) {
    acc.radiance += acc.transmittance * groundRadiance(a, b, ray.origin + ray.direction * tMax, ray.sun);
  }
  return acc.radiance * a.solarIrradiance;
}

PRISM_INLINE vec4 skyViewLutValue(IN(GpuAtmosphere) a, int b, float r, float muSun, int x, int y) {
  vec2 unit = vec2(float(x) / float(kSkyViewLutWidth - 1), float(y) / float(kSkyViewLutHeight - 1));
  return skyRadiance(a, b, r, muSun, skyViewDirection(a, r, unit), true);
}

// --- Aerial perspective --------------------------------------------------------------------
// Slice k ends at distance D_k = D_max·((k + 1)/S)²: fine slices near the camera.
PRISM_INLINE float aerialSliceDistanceKm(int k) {
  float s = float(k + 1) / float(kAerialPerspectiveSlices);
  return kAerialPerspectiveMaxKm * s * s;
}

// Slice k of one froxel column: in-scattering (solar irradiance applied) and transmittance from
// the camera to D_k, carried on from slice k − 1 in acc (start with emptyScatteringIntegral()).
PRISM_INLINE void aerialPerspectiveSlice(IN(GpuAtmosphere) a, int b, IN(vec3) cameraKm,
                                         IN(vec3) direction, IN(vec3) sun, int k,
                                         INOUT(ScatteringIntegral) acc) {
  ViewRay ray;
  ray.origin = cameraKm;
  ray.direction = direction;
  ray.sun = sun;
  float nu = dot(direction, sun);
  ray.phaseRayleigh = rayleighPhase(nu);
  ray.phaseMie = miePhase(a.ozoneMie.z, nu);
  ray.multipleScattering = a.options.x > 0.5f;
  float t0 = k == 0 ? 0.0f : aerialSliceDistanceKm(k - 1);
  float t1 = aerialSliceDistanceKm(k);
  float r = length(cameraKm);
  float tExit = distanceToAtmosphereExit(a, r, dot(cameraKm, direction) / r);
  integrateView(a, b, ray, min(t0, tExit), min(t1, tExit), 4, acc);
}

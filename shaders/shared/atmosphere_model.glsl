// The Earth's atmosphere as a participating medium, for one batch of four wavelengths: the
// optical coefficients, the geometry of a spherical planet, the phase functions and the
// numerical integration of optical depth (techniques/atmosphere builds the GpuAtmosphere from
// measured spectra; atmosphere_luts.glsl builds Hillaire 2020's tables on top of this).
//
// Medium. Three constituents whose density depends on altitude h above the ground only:
//   air molecules (Rayleigh scattering, ∝ λ⁻⁴, phase 3/16π·(1 + ν²)), density e^(−h/H_R);
//   aerosols (Mie scattering and absorption, Ångström extinction ∝ λ^−α, Cornette–Shanks
//   phase with asymmetry g), density e^(−h/H_M);
//   ozone (absorption only, measured cross-section), a tent of density 1 at its peak altitude
//   falling linearly to 0 half a width below and above.
// Lengths are in km, coefficients in 1/km (at density 1), so optical depth is their product.
// The planet's centre is the origin; "up" at a point is the point's direction.
//
// Quadrature. Every integral along a ray is the midpoint rule over segments whose samples
// crowd towards the segment's denser end (t = s², s uniform): the density falls exponentially
// away from the ground, and uniform steps long enough to cross 60 km with 40 samples would
// miss the 1.2 km aerosol layer by percents. A ray that dips towards the ground before rising
// (μ < 0 without hitting it) is split at its lowest point, and each half crowds its samples
// there.


// Sizes of the tables (texels): transmittance (r, μ), multiple scattering (μ_s, r), sky view
// (azimuth from the sun, zenith angle), aerial perspective (screen x, y, depth slice).
const int kTransmittanceLutWidth = 512;
const int kTransmittanceLutHeight = 256;
const int kMultipleScatteringLutSize = 32;
const int kSkyViewLutWidth = 192;
const int kSkyViewLutHeight = 108;
const int kAerialPerspectiveSize = 32;
const int kAerialPerspectiveSlices = 32;
const float kAerialPerspectiveMaxKm = 32.0f;

const int kTransmittanceSteps = 160;  // per half ray
const int kSkySteps = 128;           // per lit or shadowed segment of a view ray
const int kMultipleScatteringSteps = 20;
const int kMultipleScatteringDirections = 64;

struct GpuAtmosphere {
  vec4 shape;     // x bottom (ground) radius, y top radius, z Rayleigh and w Mie scale heights (km)
  vec4 ozoneMie;  // x ozone peak altitude, y ozone half-width (km), z Mie phase g, w ground albedo
  vec4 rayleighScattering;  // per wavelength of the batch, 1/km at density 1
  vec4 mieScattering;
  vec4 mieExtinction;       // scattering + absorption
  vec4 ozoneAbsorption;     // at the ozone peak
  vec4 solarIrradiance;     // at the top of the atmosphere, W·m⁻²·nm⁻¹
  vec4 options;             // x 1: multiple scattering on; y sun angular radius (rad); zw unused
};

// The sky's block of the lighting pass (techniques/atmosphere/atmosphere_section.h packs it): its
// constants in a std140 uniform block, one GpuAtmosphere per batch in a storage buffer (which
// the tables' compute passes read as well).
const int kSkyConstantsBinding = 2;
const int kSkyAtmospheresBinding = 6;
struct SkyConstants {
  float originKm;  // distance of the world's origin from the planet's centre
  int sunLight;    // index of the light that is the sun
  float pad0;
  float pad1;
};

struct AtmosphereDensity {
  float rayleigh;
  float mie;
  float ozone;
};

PRISM_INLINE AtmosphereDensity atmosphereDensity(IN(GpuAtmosphere) a, float altitudeKm) {
  AtmosphereDensity d;
  float h = max(altitudeKm, 0.0f);
  d.rayleigh = exp(-h / a.shape.z);
  d.mie = exp(-h / a.shape.w);
  d.ozone = max(0.0f, 1.0f - abs(h - a.ozoneMie.x) / a.ozoneMie.y);
  return d;
}

PRISM_INLINE vec4 atmosphereExtinction(IN(GpuAtmosphere) a, IN(AtmosphereDensity) d) {
  return a.rayleighScattering * d.rayleigh + a.mieExtinction * d.mie + a.ozoneAbsorption * d.ozone;
}

// Rayleigh and Mie scattering at a point, before the phase function.
PRISM_INLINE vec4 rayleighScatteringAt(IN(GpuAtmosphere) a, IN(AtmosphereDensity) d) {
  return a.rayleighScattering * d.rayleigh;
}
PRISM_INLINE vec4 mieScatteringAt(IN(GpuAtmosphere) a, IN(AtmosphereDensity) d) {
  return a.mieScattering * d.mie;
}

// ν: cosine of the angle between the view direction and the direction towards the sun.
PRISM_INLINE float rayleighPhase(float nu) {
  return 3.0f / (16.0f * kPi) * (1.0f + nu * nu);
}
PRISM_INLINE float miePhase(float g, float nu) {
  float k = 3.0f / (8.0f * kPi) * (1.0f - g * g) / (2.0f + g * g);
  return k * (1.0f + nu * nu) / pow(max(1.0f + g * g - 2.0f * g * nu, 1e-6f), 1.5f);
}

// r² − R², written so that it keeps its precision near the ground (r ≈ R: r² alone rounds to
// 4 km² at 6360 km, the whole difference at a few metres of altitude).
PRISM_INLINE float squaredDifference(float r, float radius) { return (r - radius) * (r + radius); }

// A ray from radius r whose direction makes cosine μ with the local up.
PRISM_INLINE float distanceToTopBoundary(IN(GpuAtmosphere) a, float r, float mu) {
  float discriminant = r * r * mu * mu - squaredDifference(r, a.shape.y);
  return max(-r * mu + sqrt(max(discriminant, 0.0f)), 0.0f);
}
PRISM_INLINE float distanceToBottomBoundary(IN(GpuAtmosphere) a, float r, float mu) {
  float discriminant = r * r * mu * mu - squaredDifference(r, a.shape.x);
  return max(-r * mu - sqrt(max(discriminant, 0.0f)), 0.0f);
}
PRISM_INLINE bool rayIntersectsGround(IN(GpuAtmosphere) a, float r, float mu) {
  return mu < 0.0f && r * r * mu * mu - squaredDifference(r, a.shape.x) >= 0.0f;
}
// The distance along the ray to the ground, or to the top of the atmosphere when it misses.
PRISM_INLINE float distanceToAtmosphereExit(IN(GpuAtmosphere) a, float r, float mu) {
  return rayIntersectsGround(a, r, mu) ? distanceToBottomBoundary(a, r, mu)
                                       : distanceToTopBoundary(a, r, mu);
}

// Radius after travelling t along a ray leaving radius r with cosine μ.
PRISM_INLINE float radiusAlongRay(float r, float mu, float t) {
  return sqrt(max(t * t + 2.0f * r * mu * t + r * r, 0.0f));
}

// Sample i of n on [t0, t1], crowded towards t0 (towardsStart) or t1: its position and length.
struct RaySample {
  float t;
  float dt;
};
PRISM_INLINE RaySample crowdedSample(float t0, float t1, int i, int n, bool towardsStart) {
  float s0 = float(i) / float(n);
  float s1 = float(i + 1) / float(n);
  float u0 = s0 * s0, u1 = s1 * s1;
  float um = (u0 + u1) * 0.5f;
  RaySample s;
  s.dt = (u1 - u0) * (t1 - t0);
  s.t = towardsStart ? t0 + um * (t1 - t0) : t1 - um * (t1 - t0);
  return s;
}

// Optical depth of [t0, t1] along a ray from radius r with cosine μ, crowded towards one end.
PRISM_INLINE vec4 opticalDepthOfSegment(IN(GpuAtmosphere) a, float r, float mu, float t0, float t1,
                                        bool towardsStart, int steps) {
  vec4 depth = vec4(0.0f);
  for (int i = 0; i < steps; ++i) {
    RaySample s = crowdedSample(t0, t1, i, steps, towardsStart);
    float h = radiusAlongRay(r, mu, s.t) - a.shape.x;
    depth += atmosphereExtinction(a, atmosphereDensity(a, h)) * s.dt;
  }
  return depth;
}

// Optical depth from radius r along μ to the top of the atmosphere (a ray that misses the
// ground): split at its lowest point when it dips.
PRISM_INLINE vec4 opticalDepthToTop(IN(GpuAtmosphere) a, float r, float mu) {
  float tEnd = distanceToTopBoundary(a, r, mu);
  float tLowest = mu < 0.0f ? min(-r * mu, tEnd) : 0.0f;
  vec4 depth = opticalDepthOfSegment(a, r, mu, tLowest, tEnd, true, kTransmittanceSteps);
  if (tLowest > 0.0f) {
    depth += opticalDepthOfSegment(a, r, mu, 0.0f, tLowest, false, kTransmittanceSteps);
  }
  return depth;
}

// Transmittance table parameterisation (Bruneton 2017, §4.1): x_r = ρ/H, x_μ = (d − d_min)/(d_max
// − d_min), with ρ the distance to the horizon, H its value at the top, d the distance to the top
// boundary. Texel centres span [0, 1] exactly (a texel's coordinate is its index / (size − 1)).
struct RadiusCosine {
  float r;
  float mu;
};

PRISM_INLINE vec2 transmittanceLutCoordinates(IN(GpuAtmosphere) a, float r, float mu) {
  float bottom = a.shape.x, top = a.shape.y;
  float horizonTop = sqrt(top * top - bottom * bottom);
  float rho = sqrt(max(squaredDifference(r, bottom), 0.0f));
  float d = distanceToTopBoundary(a, r, mu);
  float dMin = top - r, dMax = rho + horizonTop;
  float xMu = dMax > dMin ? (d - dMin) / (dMax - dMin) : 0.0f;
  return vec2(clamp(xMu, 0.0f, 1.0f), clamp(rho / horizonTop, 0.0f, 1.0f));
}

PRISM_INLINE RadiusCosine transmittanceLutParameters(IN(GpuAtmosphere) a, vec2 unit) {
  float bottom = a.shape.x, top = a.shape.y;
  float horizonTop = sqrt(top * top - bottom * bottom);
  float rho = horizonTop * unit.y;
  RadiusCosine rc;
  rc.r = sqrt(rho * rho + bottom * bottom);
  float dMin = top - rc.r, dMax = rho + horizonTop;
  float d = dMin + unit.x * (dMax - dMin);
  rc.mu = d == 0.0f ? 1.0f : (horizonTop * horizonTop - rho * rho - d * d) / (2.0f * rc.r * d);
  rc.mu = clamp(rc.mu, -1.0f, 1.0f);
  return rc;
}

// The part [t0, t1] of a ray (origin o, unit direction d; planet frame) that lies in the
// planet's shadow: the half-cylinder of the ground's radius behind the planet, seen along the
// unit sun direction s. Empty (t0 ≥ t1) when the ray stays lit.
struct ShadowInterval {
  float t0;
  float t1;
};

PRISM_INLINE ShadowInterval planetShadowInterval(IN(GpuAtmosphere) a, IN(vec3) o, IN(vec3) d,
                                                 IN(vec3) s) {
  ShadowInterval none;
  none.t0 = 0.0f;
  none.t1 = 0.0f;
  vec3 oPerp = o - s * dot(o, s);
  vec3 dPerp = d - s * dot(d, s);
  float qa = dot(dPerp, dPerp);
  float qb = 2.0f * dot(oPerp, dPerp);
  float qc = dot(oPerp, oPerp) - a.shape.x * a.shape.x;
  if (qa < 1e-12f) {
    if (qc >= 0.0f) return none;  // parallel to the axis, outside the cylinder
    none.t1 = 1e30f;
  } else {
    float discriminant = qb * qb - 4.0f * qa * qc;
    if (discriminant <= 0.0f) return none;
    float root = sqrt(discriminant);
    none.t0 = (-qb - root) / (2.0f * qa);
    none.t1 = (-qb + root) / (2.0f * qa);
  }
  // Only behind the planet: o·s + t·d·s < 0.
  float os = dot(o, s), ds = dot(d, s);
  if (abs(ds) < 1e-12f) {
    if (os >= 0.0f) none.t1 = none.t0;
  } else if (ds > 0.0f) {
    none.t1 = min(none.t1, -os / ds);
  } else {
    none.t0 = max(none.t0, -os / ds);
  }
  none.t0 = max(none.t0, 0.0f);
  return none;
}

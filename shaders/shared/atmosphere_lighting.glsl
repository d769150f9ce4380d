// What the sky gives a surface scene, per batch, from the tables of atmosphere_luts.glsl: the
// background (the sky-view table, and the sun's disc), the sun's transmittance to a point (the
// directional light that is the sun is the solar spectrum at the top of the atmosphere), the
// sky's irradiance on a surface (the sky-view table projected on spherical harmonics of order 1,
// Ramamoorthi & Hanrahan's clamped-cosine convolution), and the aerial-perspective volume
// (in-scattering and transmittance per froxel: 32 × 32 screen columns × 32 slices crowded
// towards the camera, D_k = 32 km·((k + 1)/32)²).
//
// Frames. The world's y is up and its origin lies `originKm` from the planet's centre (the
// planet's radius plus the ground's altitude), so a world point p (metres) is
// (p.x, originKm·1000 + p.y, p.z)/1000 in the planet's frame; the scene is small beside the
// planet, so "up" is the world's y everywhere in it.
//
// Each side defines, besides the accessors of atmosphere_luts.glsl:
//   vec4 skyViewLutTexel(int b, int x, int y);
//   vec4 aerialPerspectiveTexel(int b, int x, int y, int slice, int j);  j 0: in-scattering, 1: transmittance
//   vec4 skyIrradianceCoefficient(int b, int k);                          k = 0..3 (see below)
// Requires: atmosphere_model.glsl atmosphere_luts_accessors.glsl atmosphere_luts.glsl atmosphere_lighting_accessors.glsl

PRISM_INLINE vec3 planetPosition(float originKm, IN(vec3) worldM) {
  return vec3(worldM.x * 1e-3f, originKm + worldM.y * 1e-3f, worldM.z * 1e-3f);
}

// The sky-view table at coordinates unit ∈ [0, 1]² (bilinear on texel centres).
PRISM_INLINE vec4 skyViewAt(int b, IN(vec2) unit) {
  int x0, y0;
  float fx = texelCentreCoordinate(unit.x, kSkyViewLutWidth, x0);
  float fy = texelCentreCoordinate(unit.y, kSkyViewLutHeight, y0);
  vec4 bottom = mix(skyViewLutTexel(b, x0, y0), skyViewLutTexel(b, x0 + 1, y0), fx);
  vec4 top = mix(skyViewLutTexel(b, x0, y0 + 1), skyViewLutTexel(b, x0 + 1, y0 + 1), fx);
  return mix(bottom, top, fy);
}

// The sky-view table seen along a unit world direction d, for a viewer whose up is y.
PRISM_INLINE vec4 skyViewLookup(IN(GpuAtmosphere) a, int b, float r, IN(vec3) d, IN(vec3) sun) {
  vec2 dh = vec2(d.x, d.z);
  vec2 sh = vec2(sun.x, sun.z);
  float dl = length(dh), sl = length(sh);
  float cosAzimuth = dl > 1e-6f && sl > 1e-6f ? dot(dh, sh) / (dl * sl) : 1.0f;
  return skyViewAt(b, skyViewCoordinates(a, r, d.y, cosAzimuth));
}

// The sun's transmittance from space to a planet-frame point.
PRISM_INLINE vec4 sunTransmittanceTo(IN(GpuAtmosphere) a, int b, IN(vec3) p, IN(vec3) sun) {
  float r = length(p);
  return transmittanceToSpace(a, b, r, dot(p, sun) / r);
}

// Whether direction d from planet-frame radius r sees the sun's disc (not the ground).
PRISM_INLINE bool seesSunDisc(IN(GpuAtmosphere) a, float r, IN(vec3) d, IN(vec3) sun) {
  return dot(d, sun) > cos(a.options.y) && !rayIntersectsGround(a, r, d.y);
}

// Radiance of the sky seen from planet-frame point `camera` along d: the sky-view table, plus
// the sun's disc (its irradiance spread evenly over its solid angle, transmitted to the camera)
// times `sunCover`, the share of the pixel's solid angle the disc covers (pixel_shading.glsl's
// sunDiscCover; 1 or 0 for a single direction).
PRISM_INLINE vec4 skyBackground(IN(GpuAtmosphere) a, int b, IN(vec3) camera, IN(vec3) d, IN(vec3) sun, float sunCover) {
  vec4 radiance = skyViewLookup(a, b, length(camera), d, sun);
  if (sunCover > 0.0f) {
    float angularRadius = a.options.y;
    float solidAngle = kPi * angularRadius * angularRadius;
    radiance += a.solarIrradiance * sunTransmittanceTo(a, b, camera, sun) * (sunCover / solidAngle);
  }
  return radiance;
}

// Coefficient k of the sky's radiance on the real spherical harmonics of order ≤ 1 (k = 0: Y₀₀;
// 1, 2, 3: Y₁₋₁, Y₁₀, Y₁₁ ∝ y, z, x), integrated in the sky-view table's own coordinates, so that
// samples crowd where its texels do (the horizon, the sun's azimuth): 192 × 216 (u, v) cells,
// each seen on both sides of the sun's vertical plane, the value at the cell's centre times the
// cell's exact solid angle Δc·Δφ (c = cos zenith(v), φ = acos(1 − 2u²): the cell's own edges,
// not a midpoint Jacobian, whose 1/√(1 − u²) at φ → π loses 3 % of the sphere). A grid in zenith
// and azimuth instead missed the last degree above the horizon: 5 % of the red sky's constant
// term at 32 × 64, still 1.5 % at 64 × 128; 96 × 108 cells here are 2.3e-3 off a ten times
// finer integral, 192 × 216 are 8.1e-4 (the aureole's last few texels).
PRISM_INLINE vec4 skyIrradianceCoefficientValue(IN(GpuAtmosphere) a, int b, float r, IN(vec3) sun, int k) {
  const int cellsU = 192, cellsV = 216;
  float ch = horizonCosine(a, r);
  float sl = length(vec2(sun.x, sun.z));
  vec3 toward = sl > 1e-6f ? vec3(sun.x / sl, 0.0f, sun.z / sl) : vec3(1.0f, 0.0f, 0.0f);
  vec3 side = vec3(-toward.z, 0.0f, toward.x);
  vec4 sum = vec4(0.0f);
  for (int iv = 0; iv < cellsV; ++iv) {
    float v = (float(iv) + 0.5f) / float(cellsV);
    float dc = skyViewZenithCosine(ch, float(iv) / float(cellsV)) - skyViewZenithCosine(ch, float(iv + 1) / float(cellsV));
    for (int iu = 0; iu < cellsU; ++iu) {
      float u = (float(iu) + 0.5f) / float(cellsU);
      float u0 = float(iu) / float(cellsU), u1 = float(iu + 1) / float(cellsU);
      float dPhi = acos(clamp(1.0f - 2.0f * u1 * u1, -1.0f, 1.0f)) - acos(clamp(1.0f - 2.0f * u0 * u0, -1.0f, 1.0f));
      float solidAngle = dc * dPhi;
      vec2 unit = vec2(u, v);
      vec4 radiance = skyViewAt(b, unit) * solidAngle;
      vec3 local = skyViewDirection(a, r, unit);  // x towards the sun's azimuth, y up
      for (int mirror = 0; mirror < 2; ++mirror) {
        float z = mirror == 0 ? local.z : -local.z;
        vec3 d = toward * local.x + vec3(0.0f, local.y, 0.0f) + side * z;
        float basis = k == 0 ? 0.282095f : 0.488603f * (k == 1 ? d.y : (k == 2 ? d.z : d.x));
        sum += radiance * basis;
      }
    }
  }
  return sum;
}

// Irradiance on a surface of unit normal n from the whole sky (sun excluded: it is a light).
PRISM_INLINE vec4 skyIrradiance(int b, IN(vec3) n) {
  vec4 e = skyIrradianceCoefficient(b, 0) * (kPi * 0.282095f) +
           (skyIrradianceCoefficient(b, 1) * n.y + skyIrradianceCoefficient(b, 2) * n.z +
            skyIrradianceCoefficient(b, 3) * n.x) *
               (2.0f * kPi / 3.0f * 0.488603f);
  return max(e, vec4(0.0f));
}

// --- The aerial-perspective volume -----------------------------------------------------------
struct AerialPerspective {
  vec4 inScattering;   // radiance added between the camera and the point
  vec4 transmittance;  // of the point's radiance
};

// The volume is built by aerialPerspectiveSlice (atmosphere_luts.glsl), column x of the screen
// at u = x/31 (texel centres span [0, 1], as every table here).
// The volume at screen position uv ∈ [0, 1]² and distance distanceKm from the camera: trilinear
// on texel centres in x, y; in depth, between slices (and towards nothing at distance 0).
PRISM_INLINE AerialPerspective aerialPerspectiveAt(int b, IN(vec2) uv, float distanceKm) {
  int x0, y0;
  float fx = texelCentreCoordinate(uv.x, kAerialPerspectiveSize, x0);
  float fy = texelCentreCoordinate(uv.y, kAerialPerspectiveSize, y0);
  float w = sqrt(max(distanceKm, 0.0f) / kAerialPerspectiveMaxKm) * float(kAerialPerspectiveSlices);
  w = min(w, float(kAerialPerspectiveSlices));
  int s1 = min(int(floor(w)), kAerialPerspectiveSlices - 1);  // slice whose end is past w
  float fs = w - float(s1);
  AerialPerspective ap;
  vec4 v[2];
  for (int j = 0; j < 2; ++j) {
    vec4 far = mix(mix(aerialPerspectiveTexel(b, x0, y0, s1, j), aerialPerspectiveTexel(b, x0 + 1, y0, s1, j), fx),
                   mix(aerialPerspectiveTexel(b, x0, y0 + 1, s1, j), aerialPerspectiveTexel(b, x0 + 1, y0 + 1, s1, j), fx),
                   fy);
    vec4 near = vec4(j == 0 ? 0.0f : 1.0f);
    if (s1 > 0) {
      int s0 = s1 - 1;
      near = mix(mix(aerialPerspectiveTexel(b, x0, y0, s0, j), aerialPerspectiveTexel(b, x0 + 1, y0, s0, j), fx),
                 mix(aerialPerspectiveTexel(b, x0, y0 + 1, s0, j), aerialPerspectiveTexel(b, x0 + 1, y0 + 1, s0, j), fx),
                 fy);
    }
    v[j] = mix(near, far, fs);
  }
  ap.inScattering = v[0];
  ap.transmittance = v[1];
  return ap;
}

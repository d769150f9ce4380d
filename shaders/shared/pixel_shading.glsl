// The lighting pass for one pixel: a G-buffer sample in, tristimulus (XYZ, or camera RGB) out.
// This is the whole per-pixel computation of the spectral rasteriser, written once; the GPU runs
// it in shaders/passes/lighting.frag and the CPU twin (render/cpu_shading.h) in tests.
//
// Data comes through accessors that each side defines before including this file:
//   GpuBatch frameBatch(int b);           GpuLight frameLight(int l);
//   GpuMaterial frameMaterial(int id);    vec4 frameLightSpectrum(int l, int b);
//   vec4 frameMaterialSpectrum(int s, int b, int j);
//   float shadowDepthAt(int layer, int x, int y);    (x, y already clamped to the map)
//   vec3 upsamplingCoefficients(vec3 rgb);           (the albedo's Jakob–Hanika coefficients:
//     the table's, or the G-buffer's when it stores them)
//   vec3 emissionCoefficients(vec3 rgb);             (a light colour's: the table's exact lookup,
//     never the filtered one, whose 8-bit weights miss the CPU's by up to 4e-3 in reflectance)
//   WaterConstants frameWater();  vec4 frameWaterSpectrum(int b, int j);   (variants with water:
//     its block, underwater.glsl)
//   SkyConstants frameSky();  GpuAtmosphere frameAtmosphere(int b);        (variants with a sky:
//     its block, atmosphere_model.glsl), and the tables' accessors of atmosphere_luts.glsl and
//     atmosphere_lighting.glsl
//   float nebulaOpticalDepthAt(vec2 uv);  NebulaLightConstants frameNebula();
//     vec4 nebulaStarData(int i);  float nebulaStarDepthAt(int star, vec3 pCube);
//     (variants with a nebula: its march's textures and block, nebula_lighting.glsl)
//
// Techniques specialise the file at compile time, never by a run-time test per pixel: the
// includer defines PRISM_TECHNIQUE_<NAME> for each technique of the scene (the renderer compiles
// and caches one lighting program per combination; the CPU twin compiles every combination).
// Variants: PRISM_TECHNIQUE_WATER PRISM_TECHNIQUE_ATMOSPHERE PRISM_TECHNIQUE_NEBULA PRISM_RGB_EMISSION
//
// Under water (PRISM_TECHNIQUE_WATER, underwater.glsl) a directional light is the sun above the
// surface: its irradiance at a point is attenuated by e^(−Kd·depth), and it single-scatters into
// every view ray; point and spot lights lose e^(−σt·r) over the part r of their path under the
// surface, and scatter into the view ray too (underwater_lamps.glsl: a torch's glow and beam). A
// distant environment (PRT's) in-scatters too, as the sun does, with its radiance over the sky in
// place of the sun's irradiance. What the camera sees at distance S is then surface radiance ·
// e^(−σt·S) + the in-scattering over S of the sun, the environment and the lamps.
//
// With a sky (PRISM_TECHNIQUE_ATMOSPHERE, atmosphere_lighting.glsl) the background is the sky-view
// table and the sun's disc; the light that is the sun is attenuated by the sun's transmittance
// to the shaded point; the sky adds its irradiance through the diffuse part of the surface
// ((1 − metallic)·albedo/π, conductors none; no occlusion: the sky is not shadowed); and the
// aerial-perspective volume fogs what the camera sees: L·T + S.
//
// With a nebula (PRISM_TECHNIQUE_NEBULA, nebula_lighting.glsl) what the camera sees of a surface
// or of the background is dimmed by e^(−g/λ) per wavelength, g the optical depth of the nebula in
// front of it (nebulaOpticalDepthAt(uv), from the nebula's march); the nebula's own light its
// pass adds after this one. Its stars light surfaces as point lights of their own, dimmed by the
// dust between (nebulaStarsReflected).
//
// A glTF material's emission (SurfaceSample::emission, a light's colour) is upsampled once per
// pixel as an illuminant, times the material's luminance, in the variant PRISM_RGB_EMISSION
// (a scene with such a material; the CPU twin always); a scene material's own emitted spectrum
// comes per batch from the material spectra.
//
// Loop order: per light, the wavelength-independent terms (incidence, shadow, D·G) once; then
// per batch the albedo spectrum once and every light's contribution, accumulated straight into
// tristimulus through the batch's integration matrix (integration is linear, so the order of
// lights and batches does not matter). A nebula's stars, of any number, keep only their dimming
// grid lookup (the costly part) for the first kMaxLights of them; each batch takes every star's
// incidence and D·G again, and a further star's lookup too.
// Requires: brdf.glsl lights.glsl shadow_filter.glsl frame_layout.glsl sigmoid.glsl box_upsampling.glsl underwater.glsl underwater_lamps.glsl atmosphere_model.glsl pixel_shading_accessors.glsl atmosphere_luts_accessors.glsl atmosphere_luts.glsl atmosphere_lighting_accessors.glsl atmosphere_lighting.glsl nebula_march.glsl nebula_lighting.glsl nebula_lighting_accessors.glsl

// m·(p, 1), summed column by column in this order on both sides: a built-in mat4 × vec4 is
// free to sum in another order (and to fuse), and shadow-map weights amplify the difference.
PRISM_INLINE vec4 transformPoint(IN(mat4) m, IN(vec3) p) {
  PRISM_PRECISE vec4 r = m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3];
  return r;
}

// A depth-buffer value at texture coordinate uv → world position, through the inverse view-projection.
PRISM_INLINE vec3 worldFromDepth(IN(mat4) inverseViewProjection, IN(vec2) uv, float depth) {
  PRISM_PRECISE vec3 ndc = vec3(uv.x * 2.0f - 1.0f, uv.y * 2.0f - 1.0f, depth * 2.0f - 1.0f);
  vec4 p = transformPoint(inverseViewProjection, ndc);
  return vec3(p.x, p.y, p.z) / p.w;
}

// The cascade a point is looked up in: a directional light's finest whose window holds the
// point with five of its texels to spare, the PCF footprint's 2.5 and the normal offset's 1.5
// and one more (the last, the whole scene's, when none does); 0 for other lights. The normal
// offset and depth bias are the whole map's scaled by its texel, 1 / window.z.
PRISM_INLINE int shadowCascade(IN(GpuLight) light, IN(vec3) position, int size) {
  if (light.type != kLightDirectional) return 0;
  PRISM_PRECISE vec4 clip = transformPoint(light.shadowFromWorld, position);
  float reach = 1.0f - 10.0f / float(size);
  int last = light.shadowCascadeCount - 1;
  for (int c = 0; c < last; ++c) {
    vec4 window = light.shadowCascades[c];
    if (abs(clip.x - window.x) * window.z <= reach && abs(clip.y - window.y) * window.z <= reach) return c;
  }
  return last;
}

// Where a point is looked up in a light's shadow map: its layer (a point light's face, a
// directional light's cascade) and the point in that layer's clip space.
struct ShadowLookup {
  int layer;
  vec4 clip;
};
PRISM_INLINE ShadowLookup shadowLookup(IN(GpuLight) light, IN(vec3) position, int cascade) {
  ShadowLookup lookup;
  lookup.layer = light.shadowLayer;
  mat4 fromWorld = light.shadowFromWorld;
  if (light.type == kLightPoint) {
    int face = pointShadowFace(position - light.positionW);
    lookup.layer += face;
    fromWorld = pointShadowFromWorld(light.positionW, face,
                                     vec3(light.shadowFaceScale, light.shadowDepthA, light.shadowDepthB));
  } else if (light.type == kLightDirectional) {
    lookup.layer += cascade;
    fromWorld = shadowCascadeFromWorld(fromWorld, light.shadowCascades[cascade]);
  }
  lookup.clip = transformPoint(fromWorld, position);
  return lookup;
}

// Fraction of the PCF footprint that sees the light (1 for lights without a shadow map).
PRISM_INLINE float shadowVisibility(IN(GpuLight) light, IN(vec3) position, IN(vec3) normal,
                                    int size) {
  if (light.shadowLayer < 0) return 1.0f;
  int cascade = shadowCascade(light, position, size);
  float texelScale = 1.0f / light.shadowCascades[cascade].z;
  PRISM_PRECISE vec3 offsetPosition = position + normal * (light.shadowNormalOffsetM * texelScale);
  ShadowLookup lookup = shadowLookup(light, offsetPosition, cascade);
  ShadowFootprint f = shadowFootprint(lookup.clip, size);
  if (!f.inside) return 1.0f;
  float visible = 0.0f;
  for (int j = 0; j < 4; ++j) {
    int y = clamp(f.y0 + j, 0, size - 1);
    float wy = shadowTapWeight(j, f.frac.y);
    for (int i = 0; i < 4; ++i) {
      int x = clamp(f.x0 + i, 0, size - 1);
      visible += wy * shadowTapWeight(i, f.frac.x) *
                 shadowTest(shadowDepthAt(lookup.layer, x, y), f.depth, light.shadowDepthBias * texelScale);
    }
  }
  return visible;
}

// The same for a point in a medium (no surface, so no normal offset), by one bilinear comparison
// of the 2 × 2 texels around it: a lamp's in-scattering looks up 16 points along each view ray,
// where the surfaces' 4 × 4 footprint would take 256 fetches. A point beyond the map's far plane
// (which the scene's bounds set) is behind whatever the map holds there: compared just before that
// plane, not taken as lit (a torch's beam went on behind a wall). Just before: 1e-6 of clip w,
// 16 float steps below 1, which a GPU's division, 2.5 steps off, cannot round past.
PRISM_INLINE float shadowVisibilityInMedium(IN(GpuLight) light, IN(vec3) position, int size) {
  if (light.shadowLayer < 0) return 1.0f;
  int cascade = shadowCascade(light, position, size);
  float texelScale = 1.0f / light.shadowCascades[cascade].z;
  ShadowLookup lookup = shadowLookup(light, position, cascade);
  lookup.clip.z = min(lookup.clip.z, (1.0f - 1e-6f) * lookup.clip.w);
  ShadowFootprint f = shadowFootprint(lookup.clip, size);
  if (!f.inside) return 1.0f;
  float visible = 0.0f;
  for (int j = 1; j < 3; ++j) {
    int y = clamp(f.y0 + j, 0, size - 1);
    float wy = j == 1 ? 1.0f - f.frac.y : f.frac.y;
    for (int i = 1; i < 3; ++i) {
      int x = clamp(f.x0 + i, 0, size - 1);
      visible += wy * (i == 1 ? 1.0f - f.frac.x : f.frac.x) *
                 shadowTest(shadowDepthAt(lookup.layer, x, y), f.depth, light.shadowDepthBias * texelScale);
    }
  }
  return visible;
}

PRISM_INLINE vec3 integrateBatch(IN(GpuBatch) batch, IN(vec4) radiance) {
  return vec3(dot(batch.toX, radiance), dot(batch.toY, radiance), dot(batch.toZ, radiance));
}

#ifdef PRISM_TECHNIQUE_WATER
// The light arriving at the water surface from above, per wavelength of batch b: E(0) of
// underwater.glsl, the directional lights' irradiance and the distant environment's radiance
// over the sky (a scalar irradiance, as a collimated sun's is its irradiance).
PRISM_INLINE vec4 irradianceAtSurface(IN(FrameConstants) fc, int b) {
  vec4 e = frameWaterSpectrum(b, 3);
  for (int l = 0; l < fc.lightCount; ++l) {
    GpuLight light = frameLight(l);
    if (light.type == kLightDirectional && light.direction.y < 0.0f) {
      e += frameLightSpectrum(l, b) * light.intensity;
    }
  }
  return e;
}

// The part under water of a view ray from the camera along the unit viewDir, distanceM long: it
// begins enterM metres from the camera and is lengthM long. A ray that looks up leaves the water
// after depth / viewDir.y; from a camera above the water, which the viewer's can fly to, a ray
// enters it at the surface looking down and never otherwise: the air is clear.
struct WaterSpan {
  float enterM;
  float lengthM;
};
PRISM_INLINE WaterSpan waterSpan(IN(vec3) cameraPosition, IN(vec3) viewDir, float distanceM) {
  float heightM = cameraPosition.y - frameWater().surfaceY;  // > 0: the camera is above the water
  float enterM = heightM <= 0.0f ? 0.0f : viewDir.y < 0.0f ? min(heightM / -viewDir.y, distanceM) : distanceM;
  float leaveM = viewDir.y > 0.0f ? min(distanceM, frameWater().depthM / viewDir.y) : distanceM;
  WaterSpan span;
  span.enterM = enterM;
  span.lengthM = max(leaveM - enterM, 0.0f);
  return span;
}

// What the water does at batch b to radiance reaching the camera along a view ray (viewDirY: its
// direction's y): transmittance, then the in-scattering of the light from above, over the ray's
// part under water.
PRISM_INLINE vec4 throughWater(IN(FrameConstants) fc, int b, IN(vec4) radiance, IN(WaterSpan) span, float viewDirY) {
  vec4 sigmaT = frameWaterSpectrum(b, 1);
  return radiance * waterTransmittance(sigmaT, span.lengthM) +
         waterInScattering(frameWaterSpectrum(b, 0), sigmaT, frameWaterSpectrum(b, 2), frameWater().depthM, -viewDirY,
                           span.lengthM) *
             irradianceAtSurface(fc, b);
}

// The tristimulus of a lamp's in-scattering at batch b, from its nodes' sum Σ weight·e^(−σt·path)
// there (times LampRay::scale): the water's σs, the lamp's spectrum and a nebula's dimming in front
// (nebulaDepthUm: its optical depth there), as the rest of the pixel is dimmed.
PRISM_INLINE vec3 lampBatch(IN(FrameConstants) fc, int l, int b, IN(vec4) nodeSum, float nebulaDepthUm) {
  vec4 radiance = frameWaterSpectrum(b, 0) * frameLightSpectrum(l, b) * nodeSum;
#ifdef PRISM_TECHNIQUE_NEBULA
  radiance *= nebulaTransmittance4(nebulaDepthUm, fc.mode == kModeRgb ? kNebulaRgbStandInNm : frameBatch(b).lambdaNm);
#else
  PRISM_UNUSED(fc);
  PRISM_UNUSED(nebulaDepthUm);
#endif
  return integrateBatch(frameBatch(b), radiance);
}

// Node n of a lamp's ray from `entry` along viewDir: its weight, dimmed by the lamp's shadow there
// (x), and its light's path in the water (y).
PRISM_INLINE vec2 lampNodeSeen(IN(FrameConstants) fc, IN(GpuLight) light, IN(LampRay) r, int n, IN(vec3) entry,
                               IN(vec3) viewDir) {
  LampNode node = lampNode(r, n, entry, viewDir, light.type, light.positionW, light.direction, light.cosInner,
                           light.cosOuter, frameWater().surfaceY);
  return vec2(node.weight * shadowVisibilityInMedium(light, node.position, fc.shadowMapSize), node.pathM);
}

// The light the lamps (point and spot) scatter into a view ray's part under water, integrated
// over the frame's wavelengths. A node's geometry and shadow do not depend on the wavelength:
// they are worked out once for four batches at a time, whose σt stay in registers, and once per
// batch for the rest (an array of the nodes per pixel, which llvmpipe keeps in memory, or
// branches per batch inside the nodes' loop made RGB frames there 25 % slower). A nebula in front
// dims it at the pixel's centre uv, as it dims the rest of the pixel.
PRISM_INLINE vec3 lampsInWater(IN(FrameConstants) fc, IN(vec3) cameraPosition, IN(vec3) viewDir, IN(WaterSpan) span,
                               IN(vec2) uv) {
  vec3 tristimulus = vec3(0.0f);
  // (A ray looking up from above the water enters none: its entry, 1e30 m off, is no point.)
  if (!(span.lengthM > 0.0f) || frameWater().lampScattering == 0.0f) return tristimulus;
#ifdef PRISM_TECHNIQUE_NEBULA
  float nebulaDepthUm = nebulaOpticalDepthAt(uv);
#else
  PRISM_UNUSED(uv);
  float nebulaDepthUm = 0.0f;
#endif
  PRISM_PRECISE vec3 entry = cameraPosition + viewDir * span.enterM;
  for (int l = 0; l < fc.lightCount; ++l) {
    GpuLight light = frameLight(l);
    if (light.type == kLightDirectional) continue;
    LampRay r = lampRay(entry, viewDir, span.lengthM, light.type, light.positionW, light.direction, light.intensity,
                        light.cosOuter);
    if (r.scale == 0.0f) continue;
    vec3 lamp = vec3(0.0f);
    int first = 0;
    for (; first + 4 <= fc.batchCount; first += 4) {
      vec4 t0 = frameWaterSpectrum(first, 1);
      vec4 t1 = frameWaterSpectrum(first + 1, 1);
      vec4 t2 = frameWaterSpectrum(first + 2, 1);
      vec4 t3 = frameWaterSpectrum(first + 3, 1);
      vec4 sum0 = vec4(0.0f);
      vec4 sum1 = vec4(0.0f);
      vec4 sum2 = vec4(0.0f);
      vec4 sum3 = vec4(0.0f);
      for (int n = 0; n < kLampNodeCount; ++n) {
        vec2 node = lampNodeSeen(fc, light, r, n, entry, viewDir);
        sum0 += node.x * exp(-t0 * node.y);
        sum1 += node.x * exp(-t1 * node.y);
        sum2 += node.x * exp(-t2 * node.y);
        sum3 += node.x * exp(-t3 * node.y);
      }
      lamp += lampBatch(fc, l, first, sum0, nebulaDepthUm) + lampBatch(fc, l, first + 1, sum1, nebulaDepthUm) +
              lampBatch(fc, l, first + 2, sum2, nebulaDepthUm) + lampBatch(fc, l, first + 3, sum3, nebulaDepthUm);
    }
    for (; first < fc.batchCount; ++first) {
      vec4 t = frameWaterSpectrum(first, 1);
      vec4 sum = vec4(0.0f);
      for (int n = 0; n < kLampNodeCount; ++n) {
        vec2 node = lampNodeSeen(fc, light, r, n, entry, viewDir);
        sum += node.x * exp(-t * node.y);
      }
      lamp += lampBatch(fc, l, first, sum, nebulaDepthUm);
    }
    tristimulus += r.scale * lamp;
  }
  return tristimulus;
}
#endif

#ifdef PRISM_TECHNIQUE_ATMOSPHERE
// Unit direction towards the atmosphere's sun.
PRISM_INLINE vec3 atmosphereSun() { return -frameLight(frameSky().sunLight).direction; }
#endif

#ifdef PRISM_TECHNIQUE_ATMOSPHERE
// The share of the pixel around uv (its centre, in [0, 1]²) that the sun's disc covers: 32 × 32
// directions spread over it, where the pixel reaches the disc at all (a few pixels). The disc's
// radiance times this is the pixel's mean, so the sun's light in the image no longer depends on
// the image's size: seen through the pixel's centre alone, a sun smaller than a pixel showed at
// some sizes and not at others (sunset: Σ Y·Ω 140 468, 2 105 and 39 395 cd/m²·sr at 96×54,
// 160×90 and 320×180; now 27 836, 27 935, 27 833). 8 × 8 directions left 16 % at 96×54, where
// the disc covers about a quarter of one pixel.
PRISM_INLINE float sunDiscCover(IN(FrameConstants) fc, IN(GpuAtmosphere) a, float rKm, IN(vec3) cameraPosition,
                                IN(vec2) uv, IN(vec3) viewDir, IN(vec3) sun) {
  vec2 texel = vec2(1.0f / fc.viewportSize.x, 1.0f / fc.viewportSize.y);
  PRISM_PRECISE vec3 toCorner = worldFromDepth(fc.inverseViewProjection, uv + 0.5f * texel, 1.0f) - cameraPosition;
  float halfDiagonal = acos(clamp(dot(normalize(toCorner), viewDir), -1.0f, 1.0f));
  if (dot(viewDir, sun) < cos(min(a.options.y + 1.5f * halfDiagonal, kPi))) return 0.0f;  // 1.5: perspective's skew
  int inside = 0;
  for (int j = 0; j < 32; ++j) {
    for (int i = 0; i < 32; ++i) {
      vec2 at = uv + vec2((float(i) + 0.5f) / 32.0f - 0.5f, (float(j) + 0.5f) / 32.0f - 0.5f) * texel;
      PRISM_PRECISE vec3 toFar = worldFromDepth(fc.inverseViewProjection, at, 1.0f) - cameraPosition;
      if (seesSunDisc(a, rKm, normalize(toFar), sun)) ++inside;
    }
  }
  return float(inside) * (1.0f / 1024.0f);
}
#endif

// Tristimulus of the background (pixels where no geometry is), seen towards farPoint (a point
// on the far plane, which gives the view direction). Under water the view ray crosses the water
// to where it leaves it at the surface (looking up) and the background shows through what is
// left; level or down it never leaves the open ocean (1e30 m: the closed form's limit
// σs·E(0)·e^(−Kd·z)/(4π·x), nothing transmitted). Cutting it at the far plane instead would drop
// e^(−σt·far) of the in-scattering: 11 % at 440 nm looking level in Jerlov I (σt = 0.022 m⁻¹)
// with a 100 m far plane.
// uv: the pixel's centre in [0, 1]² (the nebula's optical depth is read there).
PRISM_INLINE vec3 shadeBackground(IN(FrameConstants) fc, IN(vec3) farPoint, IN(vec3) cameraPosition, IN(vec2) uv) {
#if defined(PRISM_TECHNIQUE_WATER) || defined(PRISM_TECHNIQUE_ATMOSPHERE)
  PRISM_PRECISE vec3 toFar = farPoint - cameraPosition;
  vec3 viewDir = normalize(toFar);
#else
  PRISM_UNUSED(farPoint);
  PRISM_UNUSED(cameraPosition);
#endif
#ifdef PRISM_TECHNIQUE_WATER
  WaterSpan water = waterSpan(cameraPosition, viewDir, 1e30f);  // stopped at the surface when it looks up
#endif
#ifdef PRISM_TECHNIQUE_ATMOSPHERE
  vec3 cameraKm = planetPosition(frameSky().originKm, cameraPosition);
  vec3 toSun = atmosphereSun();
  float sunCover = sunDiscCover(fc, frameAtmosphere(0), length(cameraKm), cameraPosition, uv, viewDir, toSun);
#endif
#ifdef PRISM_TECHNIQUE_NEBULA
  float nebulaDepthUm = nebulaOpticalDepthAt(uv);
#elif !defined(PRISM_TECHNIQUE_ATMOSPHERE)
  PRISM_UNUSED(uv);
#endif
  vec3 tristimulus = vec3(0.0f);
  for (int b = 0; b < fc.batchCount; ++b) {
    vec4 radiance = frameLightSpectrum(fc.lightCount, b);
#ifdef PRISM_TECHNIQUE_WATER
    radiance = throughWater(fc, b, radiance, water, viewDir.y);
#endif
#ifdef PRISM_TECHNIQUE_ATMOSPHERE
    radiance = skyBackground(frameAtmosphere(b), b, cameraKm, viewDir, toSun, sunCover);
#endif
#ifdef PRISM_TECHNIQUE_NEBULA
    radiance *= nebulaTransmittance4(nebulaDepthUm, fc.mode == kModeRgb ? kNebulaRgbStandInNm : frameBatch(b).lambdaNm);
#endif
    tristimulus += integrateBatch(frameBatch(b), radiance);
  }
#ifdef PRISM_TECHNIQUE_WATER
  tristimulus += lampsInWater(fc, cameraPosition, viewDir, water, uv);
#endif
  return tristimulus;
}

#ifdef PRISM_TECHNIQUE_NEBULA
// Where star `star` is (world) and its optical depth (µm) to the surface point p, 0 where its
// light cannot reach the surface's front (it then adds nothing): the grid lookup, the costly part
// of a star's light.
PRISM_INLINE vec3 nebulaStarPositionW(IN(FrameConstants) fc, int star) {
  vec4 position = nebulaStarData(nebulaStarPositionIndex(star, fc.batchCount));
  return vec3(position.x, position.y, position.z);
}
PRISM_INLINE float nebulaStarDepthTo(IN(FrameConstants) fc, IN(NebulaLightConstants) nebula, IN(SurfaceSample) s,
                                     int star) {
  vec3 positionW = nebulaStarPositionW(fc, star);
  if (dot(s.normal, positionW - s.position) <= 0.0f) return 0.0f;
  vec3 boxMin = vec3(nebula.boxMinSize.x, nebula.boxMinSize.y, nebula.boxMinSize.z);
  vec3 at;
  return nebulaStarDepthPoint((s.position - boxMin) / nebula.boxMinSize.w, (positionW - boxMin) / nebula.boxMinSize.w, at)
             ? nebulaStarDepthAt(star, at)
             : 0.0f;
}

// The light of the nebula's stars that the surface reflects towards v at batch b (lambdaNm: the
// wavelengths its dimming is taken at): each star a point light of the block's radiant intensity,
// dimmed by e^(−g_s/λ) (shared/nebula_lighting.glsl). `depthsUm`: the first kMaxLights stars'
// nebulaStarDepthTo, looked up once for every batch; further stars look theirs up per batch.
PRISM_INLINE vec4 nebulaStarsReflected(IN(FrameConstants) fc, IN(NebulaLightConstants) nebula, IN(SurfaceSample) s,
                                       IN(vec3) v, bool lambertian, int b, IN(vec4) lambdaNm, IN(vec4) albedo, bool spectralConductor,
                                       IN(vec4) conductorK, float metallic, float depthsUm[kMaxLights]) {
  vec4 radiance = vec4(0.0f);
  for (int star = 0; star < nebula.starCount; ++star) {
    LightIncidence li = lightIncidence(kLightPoint, nebulaStarPositionW(fc, star), vec3(0.0f, -1.0f, 0.0f), 1.0f, 1.0f,
                                       0.0f, s.position);
    MicrofacetTerms terms = microfacetTerms(s.normal, v, li.toLight, s.roughness);
    if (lambertian) terms = lambertianTerms(terms);
    if (terms.cosLight <= 0.0f) continue;
    float depthUm = star < kMaxLights ? depthsUm[star] : nebulaStarDepthTo(fc, nebula, s, star);
    vec4 arriving = nebulaStarData(nebulaStarSpectrumIndex(star, b, fc.batchCount)) * li.irradiance *
                    nebulaTransmittance4(depthUm, lambdaNm);
    radiance += surfaceReflection(terms, spectralConductor, albedo, conductorK, metallic) * arriving;
  }
  return radiance;
}
#endif

// uv: the pixel's centre in [0, 1]² (the aerial-perspective volume's screen coordinates).
PRISM_INLINE vec3 shadeSurface(IN(FrameConstants) fc, IN(SurfaceSample) s,
                               IN(vec3) cameraPosition, IN(vec2) uv) {
  PRISM_PRECISE vec3 v = normalize(cameraPosition - s.position);
  PRISM_UNUSED(uv);  // the sky's aerial perspective and the nebula read it
  GpuMaterial material = frameMaterial(s.material);
  int kind = material.kind;
  int spectra = material.spectra;
  bool lambertian = material.lambertian != 0 || s.techniqueShaded;

  MicrofacetTerms terms[kMaxLights];
  float irradiance[kMaxLights];
#ifdef PRISM_TECHNIQUE_WATER
  float waterPathM[kMaxLights];  // depth (directional) or distance under water (point, spot)
#endif
  for (int l = 0; l < fc.lightCount; ++l) {
    GpuLight light = frameLight(l);
    LightIncidence li = lightIncidence(light.type, light.positionW, light.direction, light.intensity,
                                       light.cosInner, light.cosOuter, s.position);
    terms[l] = microfacetTerms(s.normal, v, li.toLight, s.roughness);
    if (lambertian) terms[l] = lambertianTerms(terms[l]);
    irradiance[l] = terms[l].cosLight > 0.0f
                        ? li.irradiance * shadowVisibility(light, s.position, s.normal,
                                                           fc.shadowMapSize)
                        : 0.0f;
#ifdef PRISM_TECHNIQUE_WATER
    waterPathM[l] = light.type == kLightDirectional
                        ? frameWater().surfaceY - s.position.y
                        : li.distance * shareBelowSurface(s.position.y, light.positionW.y, frameWater().surfaceY);
#endif
  }

#ifdef PRISM_TECHNIQUE_WATER
  PRISM_PRECISE vec3 fromCamera = s.position - cameraPosition;
  float distanceM = length(fromCamera);
  vec3 viewDir = fromCamera / distanceM;
  WaterSpan water = waterSpan(cameraPosition, viewDir, distanceM);
#endif

  vec3 coefficients = vec3(0.0f);
  if (fc.mode == kModeJakobHanika && kind == kMaterialBaseColour) {
    coefficients = upsamplingCoefficients(s.albedo);  // once per pixel, not per wavelength
  }
#ifdef PRISM_RGB_EMISSION
  // glTF's emission, a light's colour upsampled as RgbIlluminantSpectrum does: its scale times the
  // reflectance of colour / scale, times the colour space's white.
  float emissionScale = unboundedScale(s.emission);
  bool rgbEmits = material.rgbEmissionWhite != kNoEmission && emissionScale > 0.0f;
  vec3 emissionAlbedo = rgbEmits ? s.emission / emissionScale : vec3(0.0f);
  vec3 emissionCoeffs = vec3(0.0f);
  if (rgbEmits && fc.mode == kModeJakobHanika) emissionCoeffs = emissionCoefficients(emissionAlbedo);
#endif

#ifdef PRISM_TECHNIQUE_ATMOSPHERE
  // The sky's per-pixel geometry, once for every batch.
  vec3 pointKm = planetPosition(frameSky().originKm, s.position);
  vec3 toSun = atmosphereSun();
  float distanceKm = length(s.position - cameraPosition) * 1e-3f;
#endif

#ifdef PRISM_TECHNIQUE_NEBULA
  float nebulaDepthUm = nebulaOpticalDepthAt(uv);
  NebulaLightConstants nebula = frameNebula();
  float nebulaStarDepthsUm[kMaxLights];
  for (int star = 0; star < kMaxLights; ++star) {
    nebulaStarDepthsUm[star] = star < nebula.starCount ? nebulaStarDepthTo(fc, nebula, s, star) : 0.0f;
  }
#endif
  vec3 tristimulus = vec3(0.0f);
  for (int b = 0; b < fc.batchCount; ++b) {
    GpuBatch batch = frameBatch(b);
    vec4 albedo;
    if (kind != kMaterialBaseColour) {
      albedo = frameMaterialSpectrum(spectra, b, 0);
    } else if (fc.mode == kModeRgb) {
      albedo = vec4(s.albedo.x, s.albedo.y, s.albedo.z, 0.0f);
    } else if (fc.mode == kModeNaive) {
      albedo = boxReflectance4(s.albedo, batch.lambdaNm);
    } else {
      albedo = upsampledReflectance4(coefficients, batch.lambdaNm);
    }
    vec4 conductorK = kind == kMaterialConductor ? frameMaterialSpectrum(spectra, b, 1)
                                                 : vec4(0.0f);
    // In RGB mode a conductor is Schlick's Fresnel on its normal-incidence colour (metallic 1).
    bool spectralConductor = kind == kMaterialConductor && fc.mode != kModeRgb;
    float metallic = kind == kMaterialConductor ? 1.0f : s.metallic;
    vec4 radiance = vec4(0.0f);
    for (int l = 0; l < fc.lightCount; ++l) {
      vec4 reflection = surfaceReflection(terms[l], spectralConductor, albedo, conductorK, metallic);
      vec4 arriving = frameLightSpectrum(l, b) * irradiance[l];
#ifdef PRISM_TECHNIQUE_ATMOSPHERE
      if (l == frameSky().sunLight && irradiance[l] > 0.0f) {
        arriving *= sunTransmittanceTo(frameAtmosphere(b), b, pointKm, toSun);
      }
#endif
#ifdef PRISM_TECHNIQUE_WATER
      bool sun = frameLight(l).type == kLightDirectional;
      arriving *= sun ? downwellingAttenuation(frameWaterSpectrum(b, 2), waterPathM[l])
                      : waterTransmittance(frameWaterSpectrum(b, 1), waterPathM[l]);
#endif
      radiance += reflection * arriving;
    }
    if (material.emission != kNoEmission) radiance += frameMaterialSpectrum(material.emission, b, 0);
#ifdef PRISM_RGB_EMISSION
    if (rgbEmits) {
      vec4 colour;
      if (fc.mode == kModeRgb) {
        colour = vec4(s.emission.x, s.emission.y, s.emission.z, 0.0f);
      } else if (fc.mode == kModeNaive) {
        colour = boxReflectance4(emissionAlbedo, batch.lambdaNm) * emissionScale;
      } else {
        colour = upsampledReflectance4(emissionCoeffs, batch.lambdaNm) * emissionScale;
      }
      radiance += colour * (frameMaterialSpectrum(material.rgbEmissionWhite, b, 0) * material.rgbEmissionLuminance);
    }
#endif
#ifdef PRISM_TECHNIQUE_NEBULA
    vec4 nebulaLambdaNm = fc.mode == kModeRgb ? kNebulaRgbStandInNm : batch.lambdaNm;
    radiance += nebulaStarsReflected(fc, nebula, s, v, lambertian, b, nebulaLambdaNm, albedo, spectralConductor,
                                     conductorK, metallic, nebulaStarDepthsUm);
#endif
#ifdef PRISM_TECHNIQUE_WATER
    radiance = throughWater(fc, b, radiance, water, viewDir.y);
#endif
#ifdef PRISM_TECHNIQUE_ATMOSPHERE
    if (kind != kMaterialConductor && !s.techniqueShaded) {  // a technique brings its own sky
      radiance += albedo * (1.0f - metallic) * skyIrradiance(b, s.normal) * (1.0f / kPi);
    }
    AerialPerspective ap = aerialPerspectiveAt(b, uv, distanceKm);
    radiance = radiance * ap.transmittance + ap.inScattering;
#endif
#ifdef PRISM_TECHNIQUE_NEBULA
    radiance *= nebulaTransmittance4(nebulaDepthUm, nebulaLambdaNm);
#endif
    tristimulus += integrateBatch(batch, radiance);
  }
#ifdef PRISM_TECHNIQUE_WATER
  tristimulus += lampsInWater(fc, cameraPosition, viewDir, water, uv);
#endif
  // RGB mode multiplies albedos by lights channel by channel; with a light outside the gamut
  // (negative channels) some albedos come out with a negative tristimulus, which no light has: a
  // green albedo under a 450 nm LED measured Y −8 166 cd/m² (the reference 126). Each component
  // stops at 0; a colour any light could have is left as it is. (Compressing the light into the
  // gamut instead kept Y but made RGB mode 4–5× further from the reference under both LED scenes.)
  if (fc.mode == kModeRgb) tristimulus = max(tristimulus, vec3(0.0f));
  return tristimulus;
}

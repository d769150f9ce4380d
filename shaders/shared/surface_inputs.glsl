// A material's inputs at a surface point: glTF 2.0 metallic–roughness (Khronos glTF 2.0 §3.9.2):
// base colour = factor × texture (sRGB-decoded), roughness = factor × texture G, metallic =
// factor × texture B, and a tangent-space normal map (§3.9.3) applied on the TBN frame built from
// the interpolated normal and the vertex tangent (w: bitangent sign, MikkTSpace convention);
// emission = emissiveFactor × emissive texture (sRGB-decoded; §3.9.5), a light's colour whose
// luminance the material gives (scene/scene.h's Material::emissiveLuminance).
// The G-buffer pass evaluates it per pixel, the reference path tracer per ray hit; each side
// fetches the texels (no texture built-ins here) and passes them in.

const int kTextureBaseColour = 1;         // bits of the `textures` mask
const int kTextureMetallicRoughness = 2;
const int kTextureNormal = 4;
const int kTextureEmission = 8;

struct SurfaceInputs {
  vec3 albedo;      // linear RGB in [0, 1]
  float metallic;   // [0, 1]
  float roughness;  // perceptual, [0, 1]
  vec3 normal;      // world, unit, on the viewer's side
  vec3 emission;    // linear RGB, ≥ 0: a light's colour, (1, 1, 1) the colour space's white
};

// n: the interpolated normal, unit and already turned towards the viewer. Texels: base colour
// and emission decoded from sRGB to linear, metallic–roughness and normal as stored (linear, [0, 1]); those
// whose bit is not set in `textures` are ignored. A tangent parallel to n (or absent) leaves the
// normal map unused, and a mapped normal of zero length keeps n.
PRISM_INLINE SurfaceInputs surfaceInputs(IN(vec3) baseColour, float metallic, float roughness,
                                         IN(vec3) n, IN(vec4) tangent, int textures,
                                         IN(vec3) baseColourTexel, IN(vec4) metallicRoughnessTexel,
                                         IN(vec3) normalTexel, IN(vec3) emissiveFactor, IN(vec3) emissiveTexel) {
  SurfaceInputs s;
  vec3 albedo = baseColour;
  s.normal = n;
  if ((textures & kTextureBaseColour) != 0) albedo *= baseColourTexel;
  if ((textures & kTextureMetallicRoughness) != 0) {
    roughness *= metallicRoughnessTexel.y;
    metallic *= metallicRoughnessTexel.z;
  }
  vec3 t = vec3(tangent.x, tangent.y, tangent.z);
  t = t - n * dot(n, t);
  if ((textures & kTextureNormal) != 0 && dot(t, t) > 1e-12f) {
    t = normalize(t);
    vec3 b = cross(n, t) * tangent.w;
    vec3 m = normalTexel * 2.0f - vec3(1.0f);
    vec3 mapped = t * m.x + b * m.y + n * m.z;
    if (dot(mapped, mapped) > 1e-12f) s.normal = normalize(mapped);
  }
  s.albedo = clamp(albedo, vec3(0.0f), vec3(1.0f));
  s.metallic = clamp(metallic, 0.0f, 1.0f);
  s.roughness = clamp(roughness, 0.0f, 1.0f);
  s.emission = max(emissiveFactor * ((textures & kTextureEmission) != 0 ? emissiveTexel : vec3(1.0f)), vec3(0.0f));
  return s;
}

#version 450
// G-buffer pass: the material's inputs at each visible point, as RGB (the albedo stays RGB here
// and is upsampled once per pixel in the lighting pass). Base colour textures are sRGB-format
// textures, decoded by the sampler with the sRGB transfer function.
in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;
in vec4 vTangent;

layout(binding = 0) uniform sampler2D uBaseColourTexture;
layout(binding = 1) uniform sampler2D uMetallicRoughnessTexture;
layout(binding = 2) uniform sampler2D uNormalTexture;
uniform vec3 uBaseColour;
uniform float uMetallic;
uniform float uRoughness;
uniform uint uMaterialId;  // material index + 1
uniform int uTextures;     // bit 0 base colour, bit 1 metallic-roughness, bit 2 normal

layout(location = 0) out vec4 gAlbedoMetallic;
layout(location = 1) out vec4 gNormalRoughness;
layout(location = 2) out uint gMaterialId;

void main() {
  vec3 albedo = uBaseColour;
  float metallic = uMetallic;
  float roughness = uRoughness;
  // A zero interpolated normal (degenerate mesh) would normalise to NaN, and a NaN in the
  // accumulation would stay until it restarts: fall back to the face's own normal.
  vec3 n = dot(vNormal, vNormal) > 1e-20 ? normalize(vNormal)
                                        : normalize(cross(dFdx(vPosition), dFdy(vPosition)));
  if (!gl_FrontFacing) n = -n;
  if ((uTextures & 1) != 0) albedo *= texture(uBaseColourTexture, vUv).rgb;
  if ((uTextures & 2) != 0) {
    vec4 mr = texture(uMetallicRoughnessTexture, vUv);
    roughness *= mr.g;
    metallic *= mr.b;
  }
  vec3 t = vTangent.xyz - n * dot(n, vTangent.xyz);
  if ((uTextures & 4) != 0 && dot(t, t) > 1e-12) {  // no usable tangent: no normal map
    t = normalize(t);
    vec3 b = cross(n, t) * vTangent.w;
    vec3 m = texture(uNormalTexture, vUv).xyz * 2.0 - 1.0;
    vec3 mapped = t * m.x + b * m.y + n * m.z;
    if (dot(mapped, mapped) > 1e-12) n = normalize(mapped);
  }
  gAlbedoMetallic = vec4(clamp(albedo, 0.0, 1.0), clamp(metallic, 0.0, 1.0));
  gNormalRoughness = vec4(n, clamp(roughness, 0.0, 1.0));
  gMaterialId = uMaterialId;
}

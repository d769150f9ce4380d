#version 450
// G-buffer pass: the material's inputs at each visible point, as RGB (the albedo stays RGB here
// and is upsampled once per pixel in the lighting pass). Base colour textures are sRGB-format
// textures, decoded by the sampler with the sRGB transfer function.
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
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;
  if ((uTextures & 1) != 0) albedo *= texture(uBaseColourTexture, vUv).rgb;
  if ((uTextures & 2) != 0) {
    vec4 mr = texture(uMetallicRoughnessTexture, vUv);
    roughness *= mr.g;
    metallic *= mr.b;
  }
  if ((uTextures & 4) != 0) {
    vec3 t = normalize(vTangent.xyz - n * dot(n, vTangent.xyz));
    vec3 b = cross(n, t) * vTangent.w;
    vec3 m = texture(uNormalTexture, vUv).xyz * 2.0 - 1.0;
    n = normalize(t * m.x + b * m.y + n * m.z);
  }
  gAlbedoMetallic = vec4(clamp(albedo, 0.0, 1.0), clamp(metallic, 0.0, 1.0));
  gNormalRoughness = vec4(n, clamp(roughness, 0.0, 1.0));
  gMaterialId = uMaterialId;
}

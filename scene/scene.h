// A scene as the renderer and the reference consume it: a camera, lights with spectral power
// distributions and physical intensities, materials, triangle meshes in world space and the
// textures they sample. Plain CPU data, no OpenGL: loaded and validated by scene_loader.h,
// uploaded by the renderer, traced by the reference.
//
// Units. Every light's SPD is normalised photometrically, 683 lm/W · ∫ S(λ) ȳ(λ) dλ = 1, so
// `intensity` carries the physical amount: illuminance in lux for a directional light (on a
// surface facing it), luminous intensity in candela for point and spot lights. Rendered XYZ is
// then absolute: Y is luminance in cd/m², and the camera's exposure (EV100) maps it to display.
// Colours are linear RGB in the scene's colour space (sRGB primaries unless stated).
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "spectral/spectral_texture.h"
#include "spectral/spectrum.h"
#include "techniques/technique_section.h"

namespace prism {

// How far an exposure may go either way (EV100): 1.2 · 2^±50 cd/m² of display white is past
// any scene, and float's 2^ev100 overflows at 128 (a display white of ∞ or 0 in the EXR).
inline constexpr float kEv100Limit = 50.0f;

// How far the far plane may lie beyond the near one. The G-buffer's float depth (not reversed)
// resolves a surface at distance z only to about z²/near·2⁻²⁴, and the lighting reconstructs
// positions from it: spheres_d65 (far 50) at 320×180 against its own near of 0.1 measured mean
// ΔE00 0.025 at near 0.001 (far/near 50 000), 0.046 at 0.0005, 0.20 at 0.00025 (200 000), 0.42
// at 0.0002, 1.46 at 0.0001, 38.9 at 1e-5 (mostly black below). sunset's sky needs 120 000.
inline constexpr float kMaxFarOverNear = 2e5f;

// A camera's vertical field of view in degrees lies in [kMinCameraFovDeg, kMaxCameraFovDeg): a
// vanishing one made a singular projection.
inline constexpr double kMinCameraFovDeg = 1e-3, kMaxCameraFovDeg = 180.0;

struct Camera {
  glm::vec3 position{0.0f, 1.0f, 5.0f};
  glm::vec3 target{0.0f, 1.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float verticalFovDeg = 45.0f;
  float nearPlane = 0.05f;
  float farPlane = 200.0f;
  float ev100 = 0.0f;  // exposure value at ISO 100: display white = 1.2 · 2^ev100 cd/m²
};

enum class LightType { Directional, Point, Spot };

struct Light {
  LightType type = LightType::Directional;
  glm::vec3 position{0.0f};                     // point, spot
  glm::vec3 direction{0.0f, -1.0f, 0.0f};       // directional, spot: the way the light travels (unit)
  float innerConeDeg = 30.0f;                   // spot: full intensity inside this half-angle
  float outerConeDeg = 40.0f;                   // spot: zero outside this half-angle
  Spectrum spd;                                 // photometrically normalised (see above)
  std::string spdLabel;                         // what the file said, e.g. "D65", "blackbody:2700"
  float intensity = 1.0f;                       // lux (directional) or candela (point, spot)
  bool castsShadows = true;                     // a point light six shadow maps, the others one
  // The technique that put it in the scene (the sky's sun: "atmosphere"; techniques/
  // technique_section.h), kept in step with its section by applyTechniqueLights; empty for the
  // scene file's own lights.
  std::string technique;
};

// Spectral complex index of refraction of a conductor, relative to air.
struct ConductorIor {
  std::string name;  // e.g. "Au"
  Spectrum n;
  Spectrum k;
};

// A surface's emitted radiance: its spectrum's shape, normalised photometrically as a light's
// (683 lm/W · ∫ S ȳ dλ = 1), and its luminance in cd/m², kept apart so that an edit of the
// luminance leaves the shape, and what is fitted to it, bit for bit.
struct Emission {
  Spectrum spd;
  float luminance = 0.0f;
  Spectrum radiance() const { return spd * static_cast<double>(luminance); }
};

struct Material {
  std::string name;
  glm::vec3 baseColour{0.8f};  // linear RGB albedo in [0, 1] (multiplies the texture)
  float metallic = 0.0f;       // [0, 1]: F0 = mix(0.04, base colour, metallic) (UE4)
  float roughness = 0.5f;      // perceptual roughness in [0, 1]: α = roughness²
  bool lambertian = false;     // diffuse lobe only (albedo/π): the thesis's test spheres
  // Optional measured spectral reflectance: replaces the upsampled base colour in spectral
  // modes (its RGB under the colour space's white is used in RGB mode).
  std::optional<Spectrum> reflectance;
  // Optional conductor: specular-only, Fresnel from n and k per wavelength. Never upsampled.
  std::optional<ConductorIor> conductor;
  // Optional spectral texture (docs/spectral-texture.md): the reflectance per texel, in place of
  // base colour, texture and reflectance. Only PRT objects shade it (the loader refuses others),
  // and only by their environment (kSpectralTextureUnderLights).
  std::shared_ptr<const SpectralTexture> spectralTexture;
  // Optional emitted radiance, the same from both faces and every direction (see Emission). The
  // rasteriser shows it where the surface is seen; it lights nothing else (the path tracer's
  // global transport lets it light the scene).
  std::optional<Emission> emission;
  // glTF's emission (glTF 2.0 §3.9.5): emissiveFactor × emissiveTexture, a light's colour in the
  // scene's colour space ((1, 1, 1) its white illuminant, upsampled per pixel as an illuminant),
  // emitted from both faces at emissiveLuminance cd/m² for (1, 1, 1): the scene object's
  // "emission_luminance" times KHR_materials_emissive_strength (glTF gives emission no unit).
  // Shown and gathered as `emission` is; a material has one or the other.
  glm::vec3 emissiveFactor{0.0f};  // linear, [0, 1]
  float emissiveLuminance = 0.0f;
  int emissiveTexture = -1;  // index into Scene::textures, sRGB-encoded
  bool emitsRgb() const {
    return emissiveLuminance > 0.0f && std::max({emissiveFactor.r, emissiveFactor.g, emissiveFactor.b}) > 0.0f;
  }
  int baseColourTexture = -1;         // index into Scene::textures, sRGB-encoded
  int metallicRoughnessTexture = -1;  // glTF: metallic in B, roughness in G, linear
  int normalTexture = -1;             // tangent-space normal map, linear
};

// Why a material with a spectral texture is refused under any light of the scene, by the loader
// and by PRT's pass after an edit: such an object came out flat grey, without a word.
inline constexpr std::string_view kSpectralTextureUnderLights =
    "has a spectral texture, which the scene's lights cannot read (the lighting pass lights PRT objects by their "
    "base colour): it takes the PRT environment's light alone";

// An 8-bit RGBA image as decoded from a file (row 0 at the top). `srgb` says whether the RGB
// channels are sRGB-encoded colour (decoded with the sRGB transfer function when sampled).
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
  bool srgb = false;
  std::string source;  // file it came from, for messages
};

struct Vertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  glm::vec2 uv{0.0f};
  glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // xyz tangent, w handedness (glTF convention)
};

// Triangles in world space (transforms are applied at load time).
struct Mesh {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;  // three per triangle
  int material = 0;                    // index into Scene::materials
  // The technique that shades it itself (its forward pass: PRT objects), by key; empty for the
  // deferred pipeline. Its depth still goes through the G-buffer and it still casts shadows.
  std::string technique;
};

// Axis-aligned bounds (min, max).
struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
};

// A homogeneous participating medium (water, fog): absorption σa and scattering σs per
// wavelength in 1/m, extinction σt = σa + σs, and a Henyey–Greenstein phase function of
// asymmetry g. It fills the whole scene, or only the box `region` (a body of water under its
// surface). Surfaces inside it are lit and seen through it.
struct HomogeneousMedium {
  Spectrum sigmaA;
  Spectrum sigmaS;
  float g = 0.0f;                // in (−1, 1); 0: isotropic
  std::optional<Bounds> region;  // none: everywhere
};

struct Scene {
  std::filesystem::path file;      // the scene file it was loaded from
  // The other files the loader read: spectral CSVs, glTF models and their buffers and images
  // (a technique's own: TechniqueSection::inputFiles; an output is none of them: requireNotSceneInput).
  std::vector<std::filesystem::path> files;
  std::string colourSpace = "srgb";  // of every RGB value in the scene (spectral/colour_space.h)
  Camera camera;
  std::vector<Light> lights;
  std::vector<Material> materials;
  std::vector<Mesh> meshes;
  std::vector<Image> textures;
  glm::vec3 background{0.0f};  // linear RGB radiance-like colour where no geometry is, as a light colour
  float backgroundLuminance = 0.0f;  // cd/m² of a white background
  // The techniques' sections (water, the sky, …), each owned and typed by its technique.
  TechniqueSections techniques;
  // A participating medium other than water, traced by the reference (reference/path_tracer.h)
  // only; not in scene files. With water, the reference traces the water as its medium.
  std::optional<HomogeneousMedium> medium;
};

// The bounds of all mesh vertices; both corners zero for an empty scene.
Bounds sceneBounds(const Scene& scene);

// Error "OUTPUT: is also a file the scene reads; …" (core/atomic_file.h's requireOtherFile) when
// Whether some material emits glTF's way (Material::emitsRgb): the renderer draws and reads its
// emission then alone.
inline bool anyMaterialEmitsRgb(const Scene& scene) {
  return std::ranges::any_of(scene.materials, [](const Material& m) { return m.emitsRgb(); });
}

// `output` is the scene file, one of `files` or a section's inputFiles(): `render -o
// models/tiles_base_colour.png` replaced the scene's texture with the render.
void requireNotSceneInput(const std::filesystem::path& output, const Scene& scene);

}  // namespace prism

// glTF 2.0 files (.gltf with its buffers and images, or .glb) into a Scene, through tinygltf.
//
// What is read: every mesh primitive of the default scene's node tree (mode TRIANGLES only),
// placed by the nodes' transforms (matrix or TRS) and then by the caller's; POSITION, NORMAL,
// TANGENT and TEXCOORD_0; indices of any component type; metallic-roughness materials
// (baseColorFactor, metallicFactor, roughnessFactor and their three textures) and emission
// (emissiveFactor, emissiveTexture, KHR_materials_emissive_strength; Material::emissiveFactor). Normals missing
// from a primitive are made flat (glTF 2.0 §3.7.2.1: "client implementations MUST calculate
// flat normals", provided tangents then ignored); missing tangents are computed
// (procedural_mesh.h, computeTangents). Ignored: cameras, lights, animation, skins, morph
// targets, COLOR_0, occlusion, baseColorFactor's alpha, samplers, the normal
// texture's scale. Files that require an extension are refused.
//
// Confinement: a buffer or image URI must be a data: URI or a relative path without ".." that
// stays inside `root` (the scene's folder) once symbolic links are resolved; absolute paths and
// other schemes are refused. Each URI is checked against the file's JSON before tinygltf runs,
// and tinygltf's file-system callbacks refuse every other path before a byte is read. Images
// must be PNG or JPEG (8 or 16 bits per channel, stored as 8-bit RGBA).
//
// Errors: prism::Error "<gltf file>: <JSON pointer in the glTF>: <what>", e.g.
// "model.gltf: /materials/0/pbrMetallicRoughness/metallicFactor: expected a number in [0, 1],
// got 2".
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism {

struct GltfPlacement {
  glm::mat4 transform{1.0f};  // model → world, applied after the file's own node transforms
  int materialOverride = -1;  // index into Scene::materials for every primitive; -1: the file's
  // cd/m² of glTF's emissive (1, 1, 1) (Material::emissiveLuminance); a file whose materials emit
  // is refused without it.
  std::optional<float> emissionLuminance;
};

// Appends the file's meshes, materials (named "<file name>/<material name or index>") and
// textures to `scene`, with indices offset to fit.
void appendGltf(const std::filesystem::path& file, const std::filesystem::path& root,
                const GltfPlacement& placement, Scene& scene);

// A PNG or JPEG image decoded to 8-bit RGBA (16-bit channels rounded to 8). Error(what)
// without a location otherwise, e.g. for OpenEXR or Radiance HDR files.
Image decodeImage(std::span<const std::uint8_t> bytes, bool srgb, std::string source);

}  // namespace prism

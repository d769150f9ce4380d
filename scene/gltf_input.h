// Reading what a glTF 2.0 file is (internal to prism::scene): the JSON or GLB checked by our own
// reading first (every URI inside the scene's folder, no scheme but data:, no required
// extension), then tinygltf's model with every file it reads confined to that folder and every
// image sniffed before stb decodes it; images as the scene holds them. gltf_loader.cpp turns the
// model into the scene's meshes and materials.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

// Debian's libtinygltf-dev is a shared library built with stb_image and nlohmann json: the
// header is included without TINYGLTF_IMPLEMENTATION and every symbol comes from it.
#include <tiny_gltf.h>

#include "scene/scene.h"

namespace prism {

// The model of a .gltf or .glb file, every file it names inside `root`, which it appends to
// `filesRead` after `file`. Error naming the file and the JSON pointer (or what was refused)
// otherwise.
tinygltf::Model loadGltfModel(const std::filesystem::path& file, const std::filesystem::path& root,
                              std::vector<std::filesystem::path>& filesRead);

// A decoded glTF image as the scene holds it (8-bit RGBA; 16-bit channels are rounded).
Image toImage(const tinygltf::Image& src, bool srgb, std::string source);

}  // namespace prism

// A precomputed Jakob–Hanika table: RGB (in one gamut) → sigmoid coefficients, looked up by
// the formulas of shaders/shared/upsampling.glsl, saved in Prism's own binary format.
//
// File format (little-endian, version 1):
//   offset  size          field
//   0       8             magic "PRISMLUT"
//   8       4  u32        version (1)
//   12      4  u32        resolution n (2–256)
//   16      16 char[16]   gamut name, zero-padded (e.g. "srgb")
//   32      4  u32        node layout: 1 = brightness smoothstep(smoothstep(k/(n−1))),
//                         ratios smoothstep(i/(n−1)) (shaders/shared/upsampling.glsl)
//   36      4  u32        inputs hash: the cache's key of what shaped the table (optimiser,
//                         gamut, resolution, observer, white; rgb_to_spectrum_cache.h), so
//                         that the checksum covers it; 0 when unrecorded (`prism lut`)
//   40      4n f32[n]     brightness node values
//   ...     36n³ f32[]    coefficients [block 0–2][z][y][x][c0 c1 c2], λ in nm
//   end−4   4  u32        CRC-32 (zlib) of every byte before it
// The loader checks each field and the size before reading, then the checksum, and names the
// file and the field that is wrong.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace prism {

class RgbToSpectrumTable {
 public:
  RgbToSpectrumTable(std::string gamut, int resolution);

  const std::string& gamut() const { return mGamut; }
  int resolution() const { return mResolution; }
  // The hash of the inputs that shaped it, saved in the header (0: unrecorded).
  std::uint32_t inputsHash() const { return mInputsHash; }
  void setInputsHash(std::uint32_t hash) { mInputsHash = hash; }
  // Brightness of node k, from the shared formula.
  float brightnessNode(int k) const;
  glm::vec3 coefficients(int block, int zi, int yi, int xi) const;
  void setCoefficients(int block, int zi, int yi, int xi, const glm::vec3& c);
  // The node's colour: rgb[block] = z, rgb[block+1] = x·z, rgb[block+2] = y·z.
  glm::vec3 nodeRgb(int block, int zi, int yi, int xi) const;
  std::span<const float> data() const { return mData; }

  // Albedo lookups (channels clamped to [0, 1], NaN read as 0): the manual eight-corner blend
  // (the reference), and a CPU model of the single hardware-filtered fetch, with exact weights
  // or with weights rounded to weightBits fractional bits as GPUs do (8 on NVIDIA and AMD).
  glm::vec3 lookup(const glm::vec3& rgb) const;
  glm::vec3 lookupFiltered(const glm::vec3& rgb, int weightBits = 0) const;

  void save(const std::filesystem::path& path) const;
  static RgbToSpectrumTable load(const std::filesystem::path& path);

 private:
  std::size_t index(int block, int zi, int yi, int xi) const;

  std::string mGamut;
  int mResolution;
  std::uint32_t mInputsHash = 0;
  std::vector<float> mData;
};

// Error "WHERE: the upsampling table is for G, the scene is in S" unless `table` is for the colour
// space `colourSpaceName` names (by any of its names): a scene's albedos upsampled by another
// space's table come out other colours (the path tracer aborted on it, the renderer said so).
void requireTableForColourSpace(const RgbToSpectrumTable& table, std::string_view colourSpaceName,
                                std::string_view where);

}  // namespace prism

// Textures through the driver: uploads come back unchanged, sRGB texels decode in shaders, mip
// chains have the right sizes, images are writable from compute, and a depth array's layers
// are separate and compare in a shadow sampler; storage the driver cannot make is one error.
#include "gpu/texture.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "gpu/error.h"
#include "gpu/gpu_test_support.h"
#include "gpu/object_counter.h"

namespace prism::gpu {
namespace {

using testing::GpuTest;

template <class T>
TextureData texels(GLenum format, GLenum type, const std::vector<T>& values) {
  return {format, type, std::as_bytes(std::span<const T>(values))};
}

// sRGB EOTF, IEC 61966-2-1:1999 §5.2 (what GL's sRGB decode implements).
double srgbToLinear(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

TEST_F(GpuTest, Texture2DRgba32fRoundTripsExactly) {
  const GLsizei w = 5, h = 3;  // odd width: rows must not be padded
  std::vector<float> values(w * h * 4);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = 0.1f * static_cast<float>(i) - 3.0f;
  Texture2D texture({w, h, GL_RGBA32F, 1, texels(GL_RGBA, GL_FLOAT, values), {}, "rgba32f"});
  EXPECT_EQ(texture.width(), w);
  EXPECT_EQ(texture.height(), h);
  EXPECT_EQ(readTexture2DFloat(texture, 4), values);
  std::vector<float> red = readTexture2DFloat(texture, 1);
  ASSERT_EQ(red.size(), static_cast<std::size_t>(w * h));
  EXPECT_EQ(red[7], values[7 * 4]);
}

TEST_F(GpuTest, Texture2DR32uiRoundTripsThroughTheUintReader) {
  std::vector<std::uint32_t> values{0u, 1u, 0xffffffffu, 123456789u, 42u, 7u};
  Texture2D texture({3, 2, GL_R32UI, 1, texels(GL_RED_INTEGER, GL_UNSIGNED_INT, values), {}, {}});
  EXPECT_EQ(readTexture2DUint(texture), values);
  EXPECT_THROW(readTexture2DFloat(texture, 1), std::invalid_argument);  // GL would refuse
}

// An sRGB8 texel of 188 is 0.50289 in linear light when a shader reads it, while alpha is
// stored linearly; glGetTextureImage returns the stored (encoded) value. llvmpipe approximates
// the decode (up to 8e-4 off on these texels); 1e-3 is still under a fifth of the step to the
// neighbouring 8-bit code (0.0060 at 188), so a wrong or missing decode cannot pass.
TEST_F(GpuTest, SrgbTexelsDecodeToLinearInShaders) {
  std::vector<std::uint8_t> bytes{188, 188, 0, 188, 255, 1, 128, 64};
  Texture2D texture(
      {2, 1, GL_SRGB8_ALPHA8, 1, texels(GL_RGBA, GL_UNSIGNED_BYTE, bytes), {}, "srgb"});
  texture.bind(0);
  Program kernel = testing::parityKernel("texel_fetch.comp");
  Buffer out({2 * 4 * sizeof(float), nullptr, GL_DYNAMIC_STORAGE_BIT, "texels"});
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 2);
  runCompute(kernel, {2, 1, 1});
  std::vector<float> seen = out.read<float>();
  EXPECT_NEAR(seen[0], 0.50289, 1e-3);
  for (std::size_t i : {0, 1, 2, 4, 5, 6})
    EXPECT_NEAR(seen[i], srgbToLinear(bytes[i] / 255.0), 1e-3) << "channel " << i;
  EXPECT_NEAR(seen[3], 188.0 / 255.0, 1e-6);  // alpha: not decoded
  EXPECT_NEAR(seen[7], 64.0 / 255.0, 1e-6);

  std::vector<float> stored = readTexture2DFloat(texture, 4);
  EXPECT_NEAR(stored[0], 188.0 / 255.0, 1e-6);
}

TEST_F(GpuTest, Texture2DFullMipChainAndGeneratedLevels) {
  const GLsizei w = 8, h = 3;
  std::vector<float> values(w * h * 4, 0.625f);
  Texture2D texture({w, h, GL_RGBA16F, 0, texels(GL_RGBA, GL_FLOAT, values), {}, "mips"});
  EXPECT_EQ(texture.levels(), 4);  // 8x3, 4x1, 2x1, 1x1
  EXPECT_EQ(texture.width(1), 4);
  EXPECT_EQ(texture.height(1), 1);
  EXPECT_EQ(texture.width(3), 1);
  texture.generateMipmaps();
  EXPECT_EQ(readTexture2DFloat(texture, 4, 3), std::vector<float>(4, 0.625f));  // exact in half
  EXPECT_EQ(readTexture2DFloat(texture, 2, 1).size(), 4u * 1u * 2u);
  EXPECT_THROW(readTexture2DFloat(texture, 4, 4), std::out_of_range);
  EXPECT_THROW(Texture2D({w, h, GL_RGBA8, 5, {}, {}, {}}), std::invalid_argument);
}

TEST_F(GpuTest, SizeBytesCountsEveryLevelLayerAndTexel) {
  EXPECT_EQ(Texture2D().sizeBytes(), 0u);
  // 8×4 then 4×2, 2×1, 1×1: 32 + 8 + 2 + 1 texels of 4 bytes.
  EXPECT_EQ(Texture2D({8, 4, GL_RGBA8, 0, {}, {}, "mips"}).sizeBytes(), 43u * 4u);
  EXPECT_EQ(Texture2DArray({16, 16, 3, GL_DEPTH_COMPONENT32F, 1, false, {}, "layers"}).sizeBytes(),
            16u * 16u * 3u * 4u);
  std::vector<float> table(2 * 3 * 4 * 3, 0.5f);
  Texture3D volume({2, 3, 4, GL_RGB32F, GL_RGB, table, "volume"});
  EXPECT_EQ(volume.sizeBytes(), 2u * 3u * 4u * 12u);
  Texture3D moved = std::move(volume);
  EXPECT_EQ(moved.sizeBytes(), 2u * 3u * 4u * 12u);
  EXPECT_EQ(texelBytes(GL_RGBA16F), 8u);
  EXPECT_THROW(texelBytes(GL_RGBA), std::invalid_argument);  // unsized: no size to give
}

TEST_F(GpuTest, Texture2DUploadChecksTheByteCount) {
  Texture2D texture({4, 4, GL_RGBA8, 1, {}, {}, {}});
  std::vector<std::uint8_t> tooFew(4 * 4 * 4 - 1);
  EXPECT_THROW(texture.upload(texels(GL_RGBA, GL_UNSIGNED_BYTE, tooFew)), std::invalid_argument);
  std::vector<std::uint8_t> three(4 * 4 * 3, 51);  // RGB rows of 12 bytes
  texture.upload(texels(GL_RGB, GL_UNSIGNED_BYTE, three));
  std::vector<float> back = readTexture2DFloat(texture, 4);
  EXPECT_FLOAT_EQ(back[0], 0.2f);
  EXPECT_FLOAT_EQ(back[3], 1.0f);  // alpha filled in
}

TEST_F(GpuTest, Texture2DImageIsWritableFromCompute) {
  Texture2D image({3, 2, GL_RGBA32F, 1, {}, {}, "image"});
  image.bindImage(0, GL_WRITE_ONLY);
  runCompute(testing::parityKernel("image_store.comp"), {3, 2, 1}, GL_TEXTURE_UPDATE_BARRIER_BIT);
  std::vector<float> back = readTexture2DFloat(image, 4);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) {
      std::size_t i = static_cast<std::size_t>(y * 3 + x) * 4;
      EXPECT_EQ(back[i], static_cast<float>(x));
      EXPECT_EQ(back[i + 1], static_cast<float>(y));
      EXPECT_EQ(back[i + 3], 2.0f);
    }
}

TEST_F(GpuTest, DepthArrayLayersReadBackSeparately) {
  Texture2DArray shadow({6, 4, 3, GL_DEPTH_COMPONENT32F, 1, false, {}, "cascades"});
  EXPECT_EQ(shadow.layers(), 3);
  for (GLint layer = 0; layer < 3; ++layer) {
    float depth = 0.25f * static_cast<float>(layer + 1);
    glClearTexSubImage(shadow.id(), 0, 0, 0, layer, 6, 4, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  }
  for (GLint layer = 0; layer < 3; ++layer)
    EXPECT_EQ(readTextureLayerFloat(shadow, layer),
              std::vector<float>(6 * 4, 0.25f * static_cast<float>(layer + 1)))
        << "layer " << layer;
  EXPECT_THROW(readTextureLayerFloat(shadow, 3), std::out_of_range);
  EXPECT_THROW(readTextureLayerFloat(shadow, 0, 4), std::invalid_argument);
}

TEST_F(GpuTest, DepthArrayWithCompareModeSamplesAsAShadowMap) {
  Texture2DArray shadow({4, 4, 2, GL_DEPTH_COMPONENT32F, 1, true, {}, "shadow"});
  const float depths[2] = {0.5f, 0.25f};
  for (GLint layer = 0; layer < 2; ++layer)
    glClearTexSubImage(shadow.id(), 0, 0, 0, layer, 4, 4, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                       &depths[layer]);
  shadow.bind(0);
  std::array<float, 2> references{0.4f, 0.3f};  // lit in layer 0, shadowed in layer 1
  std::vector<float> lit = testing::runParityKernel<float>(
      testing::parityKernel("shadow_compare.comp"), std::span<const float>(references));
  EXPECT_EQ(lit, (std::vector<float>{1.0f, 0.0f}));
  EXPECT_THROW(Texture2DArray({4, 4, 1, GL_RGBA8, 1, true, {}, {}}), std::invalid_argument);
}

TEST_F(GpuTest, TexturesAreMoveOnlyAndFreeTheirNames) {
  Texture2D a({2, 2, GL_RGBA8, 1, {}, {}, {}});
  GLuint name = a.id();
  Texture2D b(std::move(a));
  EXPECT_EQ(a.id(), 0u);  // NOLINT(bugprone-use-after-move): the moved-from state is specified
  EXPECT_EQ(b.width(), 2);
  EXPECT_TRUE(glIsTexture(name));
  b = Texture2D();
  EXPECT_FALSE(glIsTexture(name));
  Texture2DArray array({2, 2, 2, GL_DEPTH_COMPONENT32F, 1, false, {}, {}});
  name = array.id();
  Texture2DArray other;
  other = std::move(array);
  EXPECT_EQ(other.layers(), 2);
  other = Texture2DArray();
  EXPECT_FALSE(glIsTexture(name));
  static_assert(!std::is_copy_constructible_v<Texture2D>);
  static_assert(!std::is_copy_constructible_v<Texture2DArray>);
}

// A texture no GPU holds (the largest array of RGBA32F layers: terabytes) is one GpuError naming
// it, with no driver message before it and no GL object left behind: out of memory, the driver's
// KHR_debug line came first, then an incomplete framebuffer's, then the error.
TEST_F(GpuTest, StorageNoGpuHoldsIsOneErrorNamingTheTexture) {
  GLint side = 0, layers = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &side);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &layers);
  const GlObjectCounts start = liveGlObjects();
  try {
    Texture2DArray huge({side, side, layers, GL_RGBA32F, 1, false, {}, "huge"});
    ADD_FAILURE() << "a texture of " << side << "² × " << layers << " RGBA32F texels was made";
  } catch (const GpuError& e) {
    EXPECT_EQ(e.id(), Diagnostic::TextureStorageFailed);
    EXPECT_EQ(std::string(e.what()).rfind("prism::gpu::Texture2DArray 'huge' of ", 0), 0u) << e.what();
  }
  EXPECT_EQ(liveGlObjects(), start);
}

}  // namespace
}  // namespace prism::gpu

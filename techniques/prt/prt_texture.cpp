#include "techniques/prt/prt_texture.h"

#include <algorithm>
#include <unordered_map>

#include <glm/gtc/packing.hpp>

#include "core/error.h"
#include "core/parallel_for.h"
#include "spectral/rgb_intent.h"
#include "techniques/prt/prt_shared.h"

namespace prism::shared {
#include "transfer.glsl"
}

namespace prism::prt {
namespace {

shared::PrtReflectance reflectanceOf(const Eigen::VectorXd& rows, int basisCount) {  // 3·basisCount values
  shared::PrtReflectance r{};
  for (int j = 0; j < basisCount; ++j)
    for (int c = 0; c < 3; ++c) r.r[j][c] = halfRounded(static_cast<float>(rows[3 * j + c]));
  return r;
}

}  // namespace

PrtTextureSource::PrtTextureSource(std::shared_ptr<const SpectralTexture> spectral)
    : mSpectral(std::move(spectral)) {
  PRISM_CHECK(mSpectral != nullptr);
  mGridBasis = basisAt(*mSpectral, gridWavelengthsNm());
}

PrtTextureSource::PrtTextureSource(PrtRgbTexels rgb, const RgbToSpectrumTable& table)
    : mRgb(std::move(rgb)), mTable(&table) {
  PRISM_CHECK(mRgb.width >= 1 && mRgb.height >= 1 &&
              mRgb.rgba.size() == 4 * static_cast<std::size_t>(mRgb.width) * static_cast<std::size_t>(mRgb.height));
}

int PrtTextureSource::width() const { return mSpectral ? mSpectral->width : mRgb.width; }
int PrtTextureSource::height() const { return mSpectral ? mSpectral->height : mRgb.height; }

Eigen::VectorXd PrtTextureSource::gridReflectance(int x, int y) const {
  if (mSpectral) return mGridBasis * mSpectral->texel(x, y).cast<double>();
  const std::uint8_t* p = &mRgb.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(mRgb.width) +
                                      static_cast<std::size_t>(x)) * 4];
  glm::vec3 texel(p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f);
  if (mRgb.srgb) texel = shared::srgbDecode3(texel);
  return sampleOnGrid(RgbAlbedoSpectrum(*mTable, mRgb.baseColour * texel).toDense());
}

std::uint32_t PrtTextureSource::rgbKey(int x, int y) const {
  const std::uint8_t* p = &mRgb.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(mRgb.width) +
                                      static_cast<std::size_t>(x)) * 4];
  return static_cast<std::uint32_t>(p[0]) << 16 | static_cast<std::uint32_t>(p[1]) << 8 | p[2];
}

std::vector<Eigen::VectorXd> PrtTextureSource::representativeSpectra() const {
  constexpr int kLattice = 16;
  std::vector<Eigen::VectorXd> spectra;
  const int nx = std::min(kLattice, width()), ny = std::min(kLattice, height());
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      Eigen::VectorXd s = gridReflectance((2 * i + 1) * width() / (2 * nx), (2 * j + 1) * height() / (2 * ny));
      if (std::none_of(spectra.begin(), spectra.end(), [&s](const Eigen::VectorXd& t) { return t == s; }))
        spectra.push_back(std::move(s));
    }
  }
  return spectra;
}

std::vector<Eigen::MatrixXd> gridReflectanceMaps(
    const std::function<std::vector<PrtProjection>(const std::vector<Spectrum>&)>& project) {
  std::vector<Spectrum> hats;
  for (int i = 0; i < kGridWavelengths; ++i) {
    std::vector<double> values(kGridWavelengths, 0.0);
    values[static_cast<std::size_t>(i)] = 1.0;
    hats.push_back(TabulatedSpectrum(gridWavelengthsNm(), values, Extrapolation::Clamp).toDense());
  }
  std::vector<Eigen::MatrixXd> maps;
  for (const PrtProjection& p : project(hats)) {
    Eigen::MatrixXd w(3 * p.basisCount, kGridWavelengths);
    for (int i = 0; i < kGridWavelengths; ++i)
      for (int j = 0; j < p.basisCount; ++j)
        for (int c = 0; c < 3; ++c) w(3 * j + c, i) = p.reflectances[static_cast<std::size_t>(i)].r[j][c];
    maps.push_back(std::move(w));
  }
  return maps;
}

float halfRounded(float value) { return glm::unpackHalf1x16(glm::packHalf1x16(value)); }

PrtTexelProjector::PrtTexelProjector(const PrtTextureSource& source, const Eigen::MatrixXd& map)
    : mSource(source), mBasisCount(static_cast<int>(map.rows() / 3)) {
  PRISM_CHECK(map.rows() % 3 == 0 && mBasisCount >= 1 && mBasisCount <= shared::kPrtMaxBasis &&
              map.cols() == kGridWavelengths);
  // A spectral texture's texel is k values: W·(G·B) once, then per texel a 3m × k product.
  mMap = source.spectral() ? Eigen::MatrixXd(map * basisAt(*source.spectral(), gridWavelengthsNm())) : map;
}

shared::PrtReflectance PrtTexelProjector::texel(int x, int y) const {
  if (const SpectralTexture* s = mSource.spectral()) return reflectanceOf(mMap * s->texel(x, y).cast<double>(), mBasisCount);
  return reflectanceOf(mMap * mSource.gridReflectance(x, y), mBasisCount);
}

std::vector<std::uint16_t> PrtTexelProjector::layers(unsigned threads) const {
  const int w = mSource.width(), h = mSource.height();
  const std::size_t layerTexels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  std::vector<std::uint16_t> out(layerTexels * static_cast<std::size_t>(mBasisCount) * 4, 0);
  auto store = [&](std::size_t texel, const shared::PrtReflectance& r) {
    for (int j = 0; j < mBasisCount; ++j)
      for (int c = 0; c < 3; ++c)
        out[(static_cast<std::size_t>(j) * layerTexels + texel) * 4 + static_cast<std::size_t>(c)] = glm::packHalf1x16(r.r[j][c]);
  };
  if (mSource.spectral()) {
    parallelFor(static_cast<std::size_t>(h), threads, [&](std::size_t y) {
      for (int x = 0; x < w; ++x) store(y * static_cast<std::size_t>(w) + static_cast<std::size_t>(x), texel(x, static_cast<int>(y)));
    });
    return out;
  }
  // An RGB texture: each distinct texel once (upsampling is the cost), in first-seen order.
  std::unordered_map<std::uint32_t, std::size_t> distinct;
  std::vector<std::pair<int, int>> firstAt;
  std::vector<std::size_t> texelColour(layerTexels);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::size_t texel = static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
      auto [it, added] = distinct.try_emplace(mSource.rgbKey(x, y), firstAt.size());
      if (added) firstAt.emplace_back(x, y);
      texelColour[texel] = it->second;
    }
  }
  std::vector<shared::PrtReflectance> colours(firstAt.size());
  parallelFor(firstAt.size(), threads, [&](std::size_t i) { colours[i] = texel(firstAt[i].first, firstAt[i].second); });
  for (std::size_t texel = 0; texel < layerTexels; ++texel) store(texel, colours[texelColour[texel]]);
  return out;
}

}  // namespace prism::prt

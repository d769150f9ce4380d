#include "imaging/spectral_texture_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "imaging/exr_band.h"
#include "spectral/spectrum.h"

namespace prism::imaging {
namespace {

constexpr std::string_view kSampleChannelPrefix = "T.";
constexpr std::string_view kCoefficientChannelPrefix = "coefficient.";
constexpr const char* kBasisWavelengthsAttribute = "prism:basisWavelengthsNm";
constexpr std::string_view kBasisAttributePrefix = "prism:basis.";
constexpr std::uint64_t kMaxValues = std::uint64_t{1} << 28;
constexpr double kBasisSlack = 0.01;  // how far a coefficients form's reflectance may leave [0, 1]

std::optional<double> parseNumber(std::string_view text) {
  double value = 0.0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// "T.552,5nm" → 552.5 (the layout's comma for the decimal point); nullopt when it is not one.
std::optional<double> sampleWavelengthNm(std::string_view channel) {
  if (!channel.starts_with(kSampleChannelPrefix) || !channel.ends_with("nm")) return std::nullopt;
  std::string number(channel.substr(kSampleChannelPrefix.size(), channel.size() - kSampleChannelPrefix.size() - 2));
  if (number.find('.') != std::string::npos) return std::nullopt;
  std::replace(number.begin(), number.end(), ',', '.');
  std::optional<double> value = parseNumber(number);
  return value && *value > 0.0 ? value : std::nullopt;
}

std::optional<int> coefficientIndex(std::string_view channel) {
  std::string_view digits = channel.substr(kCoefficientChannelPrefix.size());
  int value = 0;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || value < 0) return std::nullopt;
  return value;
}

std::string channelName(double lambdaNm) {
  std::string number = fmt::format("{}", lambdaNm);
  std::replace(number.begin(), number.end(), '.', ',');
  return fmt::format("{}{}nm", kSampleChannelPrefix, number);
}

std::vector<double> numberList(const std::filesystem::path& path, const ExrBand& band, const std::string& name) {
  auto it = band.attributes.find(name);
  if (it == band.attributes.end()) throw Error(fmt::format("{}: no string attribute {}", path.string(), name));
  std::vector<double> values;
  std::string_view text = it->second;
  while (!text.empty()) {
    const std::size_t start = text.find_first_not_of(" \t\n");
    if (start == std::string_view::npos) break;
    text.remove_prefix(start);
    const std::size_t end = std::min(text.find_first_of(" \t\n"), text.size());
    std::optional<double> value = parseNumber(text.substr(0, end));
    if (!value)
      throw Error(fmt::format("{}: attribute {}: '{}' is not a finite number", path.string(), name,
                              excerpt(std::string(text.substr(0, end)), 40)));
    values.push_back(*value);
    text.remove_prefix(end);
  }
  return values;
}

std::string numberText(const Eigen::VectorXd& values) {
  std::string text;
  for (Eigen::Index i = 0; i < values.size(); ++i) text += fmt::format("{}{:.9g}", i == 0 ? "" : " ", values[i]);
  return text;
}

}  // namespace

SpectralTexture readSpectralTexture(const std::filesystem::path& path) {
  const std::string file = path.string();
  ExrBand header = readExrBand(path, false);
  if (header.rowBegin != 0 || header.rows != header.height)
    throw Error(fmt::format("{}: holds rows {}–{} of a {}-row image, not all of it", file, header.rowBegin,
                            header.rowBegin + header.rows - 1, header.height));
  std::vector<std::pair<double, std::string>> samples;
  std::map<int, std::string> coefficients;
  for (const std::string& channel : header.channels) {
    if (channel.starts_with(kSampleChannelPrefix)) {
      std::optional<double> lambda = sampleWavelengthNm(channel);
      if (!lambda)
        throw Error(fmt::format("{}: channel '{}' is not a wavelength T.<λ>nm (a comma for the decimal point)", file,
                                excerpt(channel, 40)));
      samples.emplace_back(*lambda, channel);
    } else if (channel.starts_with(kCoefficientChannelPrefix)) {
      std::optional<int> j = coefficientIndex(channel);
      if (!j) throw Error(fmt::format("{}: channel '{}' is not coefficient.<j>", file, excerpt(channel, 40)));
      coefficients[*j] = channel;
    }
  }
  if (samples.empty() == coefficients.empty())
    throw Error(fmt::format("{}: {}", file, samples.empty() ? "no spectral channels (T.<λ>nm or coefficient.<j>)"
                                                            : "both T.<λ>nm and coefficient.<j> channels: one form only"));
  SpectralTexture t;
  t.source = file;
  t.width = header.width;
  t.height = header.height;
  std::vector<std::string> order;  // channel names, in basis order
  if (!samples.empty()) {
    std::sort(samples.begin(), samples.end());
    for (std::size_t i = 1; i < samples.size(); ++i)
      if (samples[i].first == samples[i - 1].first)
        throw Error(fmt::format("{}: channels '{}' and '{}' are the same wavelength", file, samples[i - 1].second,
                                samples[i].second));
    for (const auto& [lambda, channel] : samples) {
      t.wavelengthsNm.push_back(lambda);
      order.push_back(channel);
    }
    t.sampled = true;
    t.basis = Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(samples.size()), static_cast<Eigen::Index>(samples.size()));
  } else {
    const int k = static_cast<int>(coefficients.size());
    if (coefficients.rbegin()->first != k - 1)
      throw Error(fmt::format("{}: coefficient channels are not coefficient.0 to coefficient.{}", file, k - 1));
    t.wavelengthsNm = numberList(path, header, kBasisWavelengthsAttribute);
    if (t.wavelengthsNm.empty()) throw Error(fmt::format("{}: attribute {} is empty", file, kBasisWavelengthsAttribute));
    for (std::size_t i = 0; i < t.wavelengthsNm.size(); ++i) {
      if (t.wavelengthsNm[i] <= 0.0 || (i > 0 && t.wavelengthsNm[i] <= t.wavelengthsNm[i - 1]))
        throw Error(fmt::format("{}: attribute {}: wavelengths must be positive and strictly increasing ({} at {})",
                                file, kBasisWavelengthsAttribute, t.wavelengthsNm[i], i));
    }
    t.sampled = false;
    t.basis.resize(static_cast<Eigen::Index>(t.wavelengthsNm.size()), k);
    for (int j = 0; j < k; ++j) {
      const std::string name = fmt::format("{}{}", kBasisAttributePrefix, j);
      std::vector<double> b = numberList(path, header, name);
      if (b.size() != t.wavelengthsNm.size())
        throw Error(fmt::format("{}: attribute {}: {} values, expected {} (one per wavelength of {})", file, name,
                                b.size(), t.wavelengthsNm.size(), kBasisWavelengthsAttribute));
      for (std::size_t i = 0; i < b.size(); ++i) t.basis(static_cast<Eigen::Index>(i), j) = b[i];
      order.push_back(coefficients[j]);
    }
  }
  // As a spectrum's CSV must: two wavelengths at least, not all outside the range Prism renders
  // (the texels would be their end values extrapolated).
  if (t.wavelengthsNm.size() < 2)
    throw Error(fmt::format("{}: a spectrum needs at least two wavelengths, the texture has {} ({:g} nm)", file,
                            t.wavelengthsNm.size(), t.wavelengthsNm.front()));
  if (t.wavelengthsNm.back() < kLambdaMinNm || t.wavelengthsNm.front() > kLambdaMaxNm)
    throw Error(fmt::format("{}: its wavelengths ({:g}–{:g} nm) lie outside {}–{} nm, the range Prism renders", file,
                            t.wavelengthsNm.front(), t.wavelengthsNm.back(), kLambdaMinNm, kLambdaMaxNm));
  const std::uint64_t texels = static_cast<std::uint64_t>(t.width) * static_cast<std::uint64_t>(t.height);
  if (texels * static_cast<std::uint64_t>(header.channels.size()) > kMaxValues)
    throw Error(fmt::format("{}: {} × {} texels × {} channels is more than 2²⁸ values", file, t.width, t.height,
                            header.channels.size()));

  ExrBand band = readExrBand(path, true);
  const int k = t.channels();
  t.coefficients.resize(texels * static_cast<std::size_t>(k));
  for (int j = 0; j < k; ++j) {
    const std::size_t c = static_cast<std::size_t>(std::find(band.channels.begin(), band.channels.end(), order[static_cast<std::size_t>(j)]) - band.channels.begin());
    const std::vector<float>& plane = band.planes[c];
    for (std::size_t texel = 0; texel < texels; ++texel) t.coefficients[texel * static_cast<std::size_t>(k) + static_cast<std::size_t>(j)] = plane[texel];
  }
  const double slack = t.sampled ? 0.0 : kBasisSlack;
  for (int y = 0; y < t.height; ++y) {
    for (int x = 0; x < t.width; ++x) {
      Eigen::VectorXd c = t.texel(x, y).cast<double>();
      for (int j = 0; j < k; ++j) {
        if (!std::isfinite(c[j]))
          throw Error(fmt::format("{}: texel ({}, {}), channel {}: {} is not finite", file, x, y, order[static_cast<std::size_t>(j)], c[j]));
      }
      Eigen::VectorXd r = t.basis * c;
      for (Eigen::Index i = 0; i < r.size(); ++i) {
        if (r[i] < -slack || r[i] > 1.0 + slack)
          throw Error(fmt::format("{}: texel ({}, {}): reflectance {:.4g} at {} nm is outside [0, 1]", file, x, y, r[i],
                                  t.wavelengthsNm[static_cast<std::size_t>(i)]));
      }
    }
  }
  return t;
}

void writeSpectralTexture(const std::filesystem::path& path, const SpectralTexture& t) {
  checkSpectralTexture(t);
  ExrBand band;
  band.width = t.width;
  band.height = t.height;
  band.rowBegin = 0;
  band.rows = t.height;
  const std::size_t texels = static_cast<std::size_t>(t.width) * static_cast<std::size_t>(t.height);
  const int k = t.channels();
  if (t.sampled) {
    band.attributes["spectralLayoutVersion"] = "1.0";  // Fichet et al.'s layout
    for (double lambda : t.wavelengthsNm) band.channels.push_back(channelName(lambda));
  } else {
    band.attributes[kBasisWavelengthsAttribute] =
        numberText(Eigen::Map<const Eigen::VectorXd>(t.wavelengthsNm.data(), static_cast<Eigen::Index>(t.wavelengthsNm.size())));
    for (int j = 0; j < k; ++j) {
      band.attributes[fmt::format("{}{}", kBasisAttributePrefix, j)] = numberText(t.basis.col(j));
      band.channels.push_back(fmt::format("{}{}", kCoefficientChannelPrefix, j));
    }
  }
  band.planes.assign(static_cast<std::size_t>(k), std::vector<float>(texels));
  for (std::size_t texel = 0; texel < texels; ++texel)
    for (int j = 0; j < k; ++j)
      band.planes[static_cast<std::size_t>(j)][texel] = t.coefficients[texel * static_cast<std::size_t>(k) + static_cast<std::size_t>(j)];
  writeExrBand(path, band);
}

}  // namespace prism::imaging

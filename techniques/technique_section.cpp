#include "techniques/technique_section.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace prism {

Spectrum TechniqueEnvironment::scalarIrradianceFromAbove() const {
  constexpr int kCosines = 32, kAzimuths = 64;
  constexpr double kCellSolidAngle = 2.0 * std::numbers::pi / (kCosines * kAzimuths);
  constexpr double kStepNm = 5.0;
  std::vector<glm::vec3> directions;
  directions.reserve(kCosines * kAzimuths);
  for (int i = 0; i < kCosines; ++i) {
    const double cosine = (i + 0.5) / kCosines, sine = std::sqrt(1.0 - cosine * cosine);
    for (int j = 0; j < kAzimuths; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j + 0.5) / kAzimuths;
      directions.emplace_back(static_cast<float>(sine * std::cos(phi)), static_cast<float>(cosine),
                              static_cast<float>(sine * std::sin(phi)));
    }
  }
  std::vector<double> lambdasNm, sums;
  for (double lambdaNm = kLambdaMinNm; lambdaNm <= kLambdaMaxNm; lambdaNm += kStepNm) {
    double sum = 0.0;
    for (const glm::vec3& d : directions) sum += radiance(d, lambdaNm);
    lambdasNm.push_back(lambdaNm);
    sums.push_back(sum * kCellSolidAngle);
  }
  return TabulatedSpectrum(std::move(lambdasNm), std::move(sums), Extrapolation::Clamp).toDense();
}

TechniqueSections::TechniqueSections(const TechniqueSections& other) { *this = other; }

TechniqueSections& TechniqueSections::operator=(const TechniqueSections& other) {
  if (this == &other) return *this;
  std::vector<std::unique_ptr<TechniqueSection>> copies;
  copies.reserve(other.mSections.size());
  for (const auto& s : other.mSections) copies.push_back(s->clone());
  mSections = std::move(copies);
  return *this;
}

void TechniqueSections::add(std::unique_ptr<TechniqueSection> section) {
  for (auto& s : mSections) {
    if (s->key() == section->key()) {
      s = std::move(section);
      return;
    }
  }
  mSections.push_back(std::move(section));
}

void TechniqueSections::remove(std::string_view key) {
  std::erase_if(mSections, [&](const auto& s) { return s->key() == key; });
}

const TechniqueSection* TechniqueSections::find(std::string_view key) const {
  auto it = std::find_if(mSections.begin(), mSections.end(), [&](const auto& s) { return s->key() == key; });
  return it == mSections.end() ? nullptr : it->get();
}

TechniqueSection* TechniqueSections::find(std::string_view key) {
  return const_cast<TechniqueSection*>(std::as_const(*this).find(key));
}

}  // namespace prism

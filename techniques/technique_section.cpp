#include "techniques/technique_section.h"

#include <algorithm>

namespace prism {

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

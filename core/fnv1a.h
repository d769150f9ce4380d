// FNV-1a, 64 bits (Fowler, Noll, Vo): the hash Prism's caches and batch parts name their inputs
// and check their bytes with. Not cryptographic: it catches damage and mix-ups, not forgery.
// Chained calls hash a concatenation: fnv1a(b, n, fnv1a(a, m)) is the hash of a then b.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace prism {

inline constexpr std::uint64_t kFnv1aOffsetBasis = 14695981039346656037ull;

inline std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash = kFnv1aOffsetBasis) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= bytes[i];
    hash *= 1099511628211ull;
  }
  return hash;
}

inline std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash = kFnv1aOffsetBasis) {
  return fnv1a(bytes.data(), bytes.size(), hash);
}

}  // namespace prism

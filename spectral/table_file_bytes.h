// The byte-level pieces of Prism's upsampling table files (rgb_to_spectrum_table.cpp: whole
// tables; rgb_to_spectrum_part.cpp: a split build's parts): values appended and read in the
// machine's byte order (little-endian on every platform Prism builds for), and the CRC-32 that
// closes each file.
#pragma once

#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <string>

namespace prism::table_bytes {

template <typename T>
void append(std::string& bytes, const T& value) {
  bytes.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

// The caller has checked that `bytes` holds offset + sizeof(T) bytes.
template <typename T>
T readAt(const std::string& bytes, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

inline std::uint32_t crc(const char* data, std::size_t size) {
  return static_cast<std::uint32_t>(crc32(0L, reinterpret_cast<const Bytef*>(data), static_cast<uInt>(size)));
}

}  // namespace prism::table_bytes

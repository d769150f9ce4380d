// The byte-level pieces of Prism's upsampling table files (rgb_to_spectrum_table.cpp: whole
// tables; rgb_to_spectrum_part.cpp: a split build's parts): values appended and read in the
// machine's byte order (core/binary_fields.h), and the CRC-32 that closes each file.
#pragma once

#include <zlib.h>

#include <cstdint>

#include "core/binary_fields.h"

namespace prism::table_bytes {

using binary::append;
using binary::readAt;

inline std::uint32_t crc(const char* data, std::size_t size) {
  return static_cast<std::uint32_t>(crc32(0L, reinterpret_cast<const Bytef*>(data), static_cast<uInt>(size)));
}

}  // namespace prism::table_bytes

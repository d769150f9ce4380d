// Fixed-size values in Prism's binary files (cache entries, batch parts): appended to and read
// from a file's bytes in the machine's byte order, which is little-endian on every platform Prism
// builds for, as the files' formats say.
#pragma once

#include <cstddef>
#include <cstring>
#include <string>

namespace prism::binary {

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

}  // namespace prism::binary

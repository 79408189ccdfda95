// A file's bytes read and written whole, for tests that write a file, damage it and read it
// back.
#pragma once

#include <fstream>
#include <iterator>
#include <string>

namespace tracked_vehicle_dynamics {

/// Every byte of `path` ("" when it cannot be read).
inline std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Replaces `path` with `bytes`.
inline void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

}  // namespace tracked_vehicle_dynamics

// FNV-1a, 64 bit (Fowler, Noll, Vo): h = (h xor byte) * 1099511628211, from 14695981039346656037.
// Not cryptographic, but any changed, missing or reordered byte changes it: the description hash,
// the reduced-model file's checksum and the cache names of non-default reduction options.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace tracked_vehicle_dynamics {
namespace io {

constexpr std::uint64_t kFnv1aOffset = 14695981039346656037ull;
constexpr std::uint64_t kFnv1aPrime = 1099511628211ull;

/// Continues `hash` over `bytes` bytes at `data` (start from kFnv1aOffset).
inline std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t hash = kFnv1aOffset) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i)
    hash = (hash ^ p[i]) * kFnv1aPrime;
  return hash;
}

/// The same over the bytes of `text`.
inline std::uint64_t fnv1a(std::string_view text, std::uint64_t hash = kFnv1aOffset) {
  return fnv1a(text.data(), text.size(), hash);
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics

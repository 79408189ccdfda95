#include "tracked_vehicle_dynamics/types.h"

#include <array>
#include <cctype>

namespace tracked_vehicle_dynamics {

// The one alignment symbol the library defines: its own build's (types.h).
const int abi::TVD_ABI_ALIGNMENT_SYMBOL = EIGEN_MAX_ALIGN_BYTES;

namespace {

constexpr std::array<const char*, kDofsPerNode> kDirectionNames = {"ux", "uy", "uz",
                                                                   "rx", "ry", "rz"};

}  // namespace

const char* directionName(int direction) {
  if (direction < 0 || direction >= kDofsPerNode) {
    return "?";  // labels stay printable for a corrupt index; validate() reports the cause
  }
  return kDirectionNames[static_cast<std::size_t>(direction)];
}

int parseDirection(const std::string& name) {
  if (name.size() != 2) {
    return -1;
  }
  std::string lower;
  for (const char c : name) {
    lower.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  for (int direction = 0; direction < kDofsPerNode; ++direction) {
    if (lower == kDirectionNames[static_cast<std::size_t>(direction)]) {
      return direction;
    }
  }
  return -1;
}

}  // namespace tracked_vehicle_dynamics

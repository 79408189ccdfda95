#include "tracked_vehicle_dynamics/io/message_text.h"

#include <cstdio>

namespace tracked_vehicle_dynamics {
namespace io {

std::string printable(const std::string& text, std::size_t shown) {
  const bool cut = text.size() > shown;
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < shown; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof(hex), "\\x%02x", c);
      out += hex;
    } else {
      out += text[i];
    }
  }
  if (cut)
    out += "... (" + std::to_string(text.size()) + " characters)";
  return out;
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics

// Text from an input file as an error message shows it. A message is one line on a terminal: a
// stray CR from a file would send the cursor back over its start, a newline split it, an escape
// sequence recolour the terminal, and a NUL end the message there.
#pragma once

#include <cstddef>
#include <string>

namespace tracked_vehicle_dynamics {
namespace io {

/// `text` with every control byte (below 0x20, and 0x7f) written as \xNN; longer than `shown`
/// bytes, cut there and followed by "... (N characters)" (a 500,000-digit cell would otherwise
/// be a 500 kB line).
std::string printable(const std::string& text, std::size_t shown = std::string::npos);

}  // namespace io
}  // namespace tracked_vehicle_dynamics

// Reading an enum value back from its name: the inverse of a `const char* name(Enum)` function
// (dynamics::methodName, dynamics::holdName, reduction::modeRuleName, ...), so that each enum has
// one name table, the switch in its name function.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>

namespace tracked_vehicle_dynamics {

/// The value among `all` whose name(value) is `text` exactly; nullopt for any other text.
template <class Enum>
std::optional<Enum> enumFromName(const std::string& text, std::initializer_list<Enum> all,
                                 const char* (*name)(Enum)) {
  for (const Enum value : all)
    if (text == name(value))
      return value;
  return std::nullopt;
}

}  // namespace tracked_vehicle_dynamics

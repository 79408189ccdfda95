// Row layout of the stacked outputs of a time simulation or FRF: for each requested quantity
// (displacement, velocity, acceleration) one block with one row per row of H, in the order the
// quantities were requested. Row names carry a suffix: "hull uz/disp", "hull uz/vel",
// "hull uz/acc".
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// Which time derivative of the physical outputs y = H q is reported.
enum class OutputQuantity {
  Displacement,  ///< H q   [m, rad]
  Velocity,      ///< H q'  [m/s, rad/s]
  Acceleration,  ///< H q'' [m/s^2, rad/s^2]
};

/// "disp", "vel" or "acc".
const char* outputSuffix(OutputQuantity quantity);

class OutputLayout {
 public:
  /// base_names: one per row of H (e.g. SecondOrderSystem::output_names); quantities: the blocks
  /// in row order. Throws InputError for an empty or repeated quantity list.
  OutputLayout(std::vector<std::string> base_names, std::vector<OutputQuantity> quantities);

  /// Total number of rows: baseCount() * quantities().size().
  DofIndex size() const { return static_cast<DofIndex>(names_.size()); }
  /// Number of rows of H.
  DofIndex baseCount() const { return static_cast<DofIndex>(base_names_.size()); }
  const std::vector<OutputQuantity>& quantities() const { return quantities_; }
  /// Suffixed row names, e.g. "hull uz/acc".
  const std::vector<std::string>& names() const { return names_; }

  /// True when the quantity has a block.
  bool has(OutputQuantity quantity) const;
  /// First row of the block of `quantity`. Throws InputError when it was not requested.
  DofIndex offset(OutputQuantity quantity) const;
  /// Row of a base output for a quantity. Throws InputError naming the unknown name/quantity.
  DofIndex row(const std::string& base_name, OutputQuantity quantity) const;
  /// Row of a suffixed name such as "hull uz/acc". Throws InputError when unknown.
  DofIndex row(const std::string& name) const;

 private:
  std::vector<std::string> base_names_;
  std::vector<OutputQuantity> quantities_;
  std::vector<std::string> names_;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics

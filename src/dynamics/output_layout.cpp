#include "tracked_vehicle_dynamics/dynamics/output_layout.h"

#include <algorithm>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

const char* outputSuffix(OutputQuantity quantity) {
  switch (quantity) {
    case OutputQuantity::Displacement:
      return "disp";
    case OutputQuantity::Velocity:
      return "vel";
    case OutputQuantity::Acceleration:
      return "acc";
  }
  return "?";
}

OutputLayout::OutputLayout(std::vector<std::string> base_names,
                           std::vector<OutputQuantity> quantities)
    : base_names_(std::move(base_names)), quantities_(std::move(quantities)) {
  if (quantities_.empty())
    throw InputError("OutputLayout: no output quantity requested");
  for (std::size_t i = 0; i < quantities_.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (quantities_[i] == quantities_[j])
        throw InputError(std::string("OutputLayout: quantity '") + outputSuffix(quantities_[i]) +
                         "' requested twice");
  names_.reserve(base_names_.size() * quantities_.size());
  for (OutputQuantity q : quantities_)
    for (const std::string& base : base_names_)
      names_.push_back(base + "/" + outputSuffix(q));
}

bool OutputLayout::has(OutputQuantity quantity) const {
  return std::find(quantities_.begin(), quantities_.end(), quantity) != quantities_.end();
}

DofIndex OutputLayout::offset(OutputQuantity quantity) const {
  const auto it = std::find(quantities_.begin(), quantities_.end(), quantity);
  if (it == quantities_.end())
    throw InputError(std::string("OutputLayout: quantity '") + outputSuffix(quantity) +
                     "' was not requested");
  return static_cast<DofIndex>(it - quantities_.begin()) * baseCount();
}

DofIndex OutputLayout::row(const std::string& base_name, OutputQuantity quantity) const {
  const auto it = std::find(base_names_.begin(), base_names_.end(), base_name);
  if (it == base_names_.end())
    throw InputError("OutputLayout: unknown output '" + base_name + "'");
  return offset(quantity) + static_cast<DofIndex>(it - base_names_.begin());
}

DofIndex OutputLayout::row(const std::string& name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end())
    throw InputError("OutputLayout: unknown output '" + name + "'");
  return static_cast<DofIndex>(it - names_.begin());
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics

// The simulator's outputs at one sample, as the tools hand them around.
#pragma once

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// A row of the simulator's output block, viewed in place (a row of a column-major matrix is
/// strided; a plain Ref<const RowVectorXd> would copy it at every sample).
using OutputRow = Eigen::Ref<const Eigen::RowVectorXd, 0, Eigen::InnerStride<>>;

}  // namespace tools
}  // namespace tracked_vehicle_dynamics

// Private helpers of the dynamics module: dimension preconditions with messages naming sizes.
#pragma once

#include <cmath>
#include <string>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {
namespace detail {

inline std::string sizeText(Eigen::Index rows, Eigen::Index cols) {
  return std::to_string(rows) + "x" + std::to_string(cols);
}

/// Throws InputError "<where>: <what> is RxC, expected RxC".
template <typename MatrixType>
void requireSize(const std::string& where, const std::string& what, const MatrixType& m,
                 Eigen::Index rows, Eigen::Index cols) {
  if (m.rows() != rows || m.cols() != cols)
    throw InputError(where + ": " + what + " is " + sizeText(m.rows(), m.cols()) + ", expected " +
                     sizeText(rows, cols));
}

/// Throws InputError "<where>: <what> has N entries, expected M".
template <typename VectorType>
void requireLength(const std::string& where, const std::string& what, const VectorType& v,
                   Eigen::Index length) {
  if (static_cast<Eigen::Index>(v.size()) != length)
    throw InputError(where + ": " + what + " has " + std::to_string(v.size()) +
                     " entries, expected " + std::to_string(length));
}

/// Throws InputError "<where>: <what> entry i is nan" at the first non-finite entry: a NaN or
/// infinite input would enter the state and every later sample. The test is one vectorised pass.
template <typename VectorType>
void requireFinite(const std::string& where, const std::string& what, const VectorType& v) {
  if (v.allFinite())
    return;
  Eigen::Index i = 0;
  while (std::isfinite(v(i)))
    ++i;
  throw InputError(where + ": " + what + " entry " + std::to_string(i) + " is " + brief(v(i)) +
                   "; only finite values are accepted (nothing was changed)");
}

/// Throws InputError naming entry (row, column) of an input series as non-finite.
[[noreturn]] inline void throwNonFiniteSeriesEntry(Eigen::Index row, Eigen::Index column,
                                                   double value) {
  throw InputError("Simulator::simulate: input series row " + std::to_string(row) + " entry " +
                   std::to_string(column) + " is " + brief(value) +
                   "; only finite values are accepted (nothing was changed)");
}

/// Throws InputError unless 0 < dt < inf.
inline void requireTimeStep(const std::string& where, double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw InputError(where + ": time step must be positive and finite, got " + brief(dt) + " s");
}

}  // namespace detail
}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics

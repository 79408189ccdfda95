// Type aliases shared by every stage of the core (STYLE.md #6).
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cstdint>
#include <string>

// Eigen lays out its objects and aligns its heap blocks by the instruction set it is compiled
// for (EIGEN_MAX_ALIGN_BYTES: 16 with SSE2, 32 with AVX, 64 with AVX-512), so code that
// exchanges Eigen objects with tvd_core must be compiled for the same level: a program built
// without -march=x86-64-v3 against the x86-64-v3 library aborted at its first call ("double
// free or corruption"). Every translation unit that includes this header refers to a symbol
// named after its own alignment, and the library defines only the one of its build, so a
// mismatch fails at link time and says what to do: "undefined reference to
// `tracked_vehicle_dynamics::abi::eigen_max_align_bytes_16_compile_with_tvd_core_simd_flag'"
// (README, "SIMD": the flag is in the package's CMake extras and .pc Cflags).
#define TVD_ABI_JOIN_(a, b) a##b
#define TVD_ABI_JOIN(a, b) TVD_ABI_JOIN_(a, b)
#define TVD_ABI_ALIGNMENT_SYMBOL                                            \
  TVD_ABI_JOIN(TVD_ABI_JOIN(eigen_max_align_bytes_, EIGEN_MAX_ALIGN_BYTES), \
               _compile_with_tvd_core_simd_flag)

namespace tracked_vehicle_dynamics {
namespace abi {
extern const int TVD_ABI_ALIGNMENT_SYMBOL;
namespace {
// Kept in every object file (gnu::used), unused or not: the reference is the check.
[[gnu::used]] const int* const kAlignmentCheck = &TVD_ABI_ALIGNMENT_SYMBOL;
}  // namespace
}  // namespace abi

using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;
using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Matrix12 = Eigen::Matrix<double, 12, 12>;
/// Column-major sparse matrix; all assembled system matrices use it.
using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplet = Eigen::Triplet<double>;
/// Mass-normalised mode shapes, one column per mode [n_dof x n_modes].
using ModeShapes = Eigen::MatrixXd;

/// User-visible node identifier (any integer the model file chooses).
using NodeId = std::int64_t;
/// Index of a DOF in a vector or matrix.
using DofIndex = Eigen::Index;

/// Degrees of freedom per node: three translations then three rotations.
constexpr int kDofsPerNode = 6;

/// Nodal direction, in the global frame: x forward, y left, z up (REP-103).
enum class Direction : int { Ux = 0, Uy = 1, Uz = 2, Rx = 3, Ry = 4, Rz = 5 };

/// "ux", "uy", "uz", "rx", "ry", "rz".
const char* directionName(int direction);
/// Parses a direction name (case-insensitive); returns -1 when unknown.
int parseDirection(const std::string& name);

/// Standard gravity [m/s^2].
constexpr double kStandardGravity = 9.80665;
/// km/h in one m/s: speeds are m/s in the core, km/h where users give or read them.
constexpr double kKmhPerMs = 3.6;
/// pi and 2 pi (rad/s per Hz), to double precision: one definition for the whole project.
constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
/// Degrees per radian (180 / pi), for angles in reports.
constexpr double kRadToDegree = 180.0 / kPi;

}  // namespace tracked_vehicle_dynamics

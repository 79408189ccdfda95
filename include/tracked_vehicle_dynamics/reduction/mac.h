// Modal Assurance Criterion (paper eq. 11; Allemang 1982) and the correlation list built from it
// (paper §3.1.1, Fig. 9-10, Table 4).
#pragma once

#include <utility>
#include <vector>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

/// MAC above which two modes are taken as the same shape (paper §3.1.1: "MAC >= 70 %").
constexpr double kPaperMacThreshold = 0.7;

/// Relative norm below which a restricted mode shape is round-off rather than motion.
constexpr double kNegligibleShape = 1e-8;

/// MAC between every column of phi_a [n x a] and every column of phi_b [n x b] (paper eq. 11):
///   MAC_jk = (phi_j^T phi_k)^2 / ((phi_j^T phi_j) (phi_k^T phi_k))   in [0, 1], result [a x b].
/// It is invariant to the scaling (and sign) of each shape, and it is NOT mass-weighted: two
/// M-orthogonal modes can have a non-zero MAC. Both sets must be given over the same DOFs in the
/// same order (see commonTranslationalRows()).
/// A shape whose norm is at most kNegligibleShape times the largest norm of its set has MAC 0
/// with every shape: it does not move on these DOFs, and the round-off left there (a lateral
/// mode seen on vertical DOFs, say) would otherwise, being scale-invariant, correlate with
/// anything. Throws InputError when the row counts differ or an entry is not finite.
Matrix mac(const Matrix& phi_a, const Matrix& phi_b);

/// Modes whose frequencies are closer than this (relative) form one eigenspace for
/// eigenspaceMac(): the individual vectors of a repeated eigenvalue are any basis of its
/// eigenspace, which round-off picks. A solver returns a repeated eigenvalue equal to ~1e-10;
/// distinct modes closer than 1e-6 would turn with perturbations of 1e-6 of the matrices.
/// (The vehicle's closest distinct pairs, the left and right chain modes, are 1e-5 apart.)
constexpr double kDegenerateRelativeGap = 1e-6;

/// The MAC between eigenspaces: modes of A (frequencies f_a [Hz], ascending) and of B whose
/// neighbours lie within relative_gap in frequency are grouped; the entry of every mode j of a
/// group C and k of a group D is the largest MAC between any shape of span(C) and any of span(D),
///   MAC_jk = sigma_max(Q_C^T Q_D)^2,   Q_C, Q_D orthonormal bases of the groups' shapes
/// (the cosine squared of their smallest principal angle). Between single modes it is mac(). On
/// the un-tracked vehicle 11 road wheels bouncing alone share one frequency, so which vectors of
/// that eigenspace the solver returns, and so each mode's plain MAC with them, is round-off (a
/// build with FMA selected one tracked mode fewer); this is not. Shapes of negligible norm (see
/// mac()) add nothing to a group's span. Throws InputError like mac(), or when a frequency vector
/// does not have one entry per shape.
Matrix eigenspaceMac(const Matrix& phi_a, const Vector& f_a, const Matrix& phi_b, const Vector& f_b,
                     double relative_gap = kDegenerateRelativeGap);

/// The groups eigenspaceMac() forms: consecutive modes (frequencies ascending) whose neighbours lie
/// within relative_gap, as [begin, end) index ranges covering every mode.
std::vector<std::pair<Eigen::Index, Eigen::Index>> degenerateGroups(
    const Vector& frequencies_hz, double relative_gap = kDegenerateRelativeGap);

/// One mode of A with its matches among the modes of B.
struct ModeMatch {
  int mode = 0;  ///< 0-based column of phi_b
  double mac = 0.0;
};

struct ModeCorrelation {
  int mode = 0;  ///< 0-based column of phi_a
  int best_match =
      -1;  ///< mode of B with the largest MAC (lowest index on ties); -1 when B is empty
  double best_mac = 0.0;
  std::vector<ModeMatch> matches;  ///< every mode of B with MAC >= threshold, by decreasing MAC
};

/// For each mode of A (each row of `mac_ab` = mac(phi_a, phi_b)): its best-matching mode of B and
/// every mode of B with MAC >= threshold, the paper's correlation list (Table 4 lists the best
/// match plain and the others in brackets). Throws InputError when threshold is not in (0, 1].
std::vector<ModeCorrelation> correlateModes(const Matrix& mac_ab,
                                            double threshold = kPaperMacThreshold);

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics

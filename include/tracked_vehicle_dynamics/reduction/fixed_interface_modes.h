// How many fixed-interface modes Phi_S (paper eqs. 6-7) the Craig-Bampton basis keeps, and how
// that number follows from the global-mode selection of §3.1.1.
//
// The MAC selects GLOBAL modes of the free (unreduced) model, but the Craig-Bampton basis keeps
// the modes of the structure with its master DOFs clamped (eq. 6); the two are different sets,
// so the selection is carried over as a count or as a frequency limit, never mode by mode.
// The paper carries it over as a count: Table 5 has 8 and 12 "flexible modes" for the two models,
// exactly the numbers of modes selected in §3.1.1 (CMS DOFs 122 = 84 + 21 + 9 + 8 and
// 402 = 360 + 21 + 9 + 12). Because the masters already hold the hull, the wheel centres and the
// MoGeSeC DOFs, the constraint modes carry the global motion and each kept Phi_S mode adds one
// internal (mostly track-chain) deformation; SameCount reproduces the paper, UpToFrequency is the
// classical CMS rule (keep the clamped modes up to 1.5-2 times the highest frequency of interest)
// and is the safer choice when the selected band matters more than the size.
#pragma once

#include "tracked_vehicle_dynamics/reduction/mode_selection.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

/// The request passed to craigBampton(): the lowest `count` fixed-interface modes, or, when
/// max_frequency_hz > 0, every fixed-interface mode up to that frequency (at most `count`).
struct FixedInterfaceModes {
  int count = 0;                  ///< number of modes r (upper bound with a frequency limit)
  double max_frequency_hz = 0.0;  ///< [Hz] 0: count only
};

enum class FixedInterfaceRule {
  /// r = number of selected global modes + extra_modes (the paper, Table 5).
  SameCount,
  /// Every fixed-interface mode up to frequency_margin x the highest selected frequency, at most
  /// max_count.
  UpToFrequency,
};

struct FixedInterfaceOptions {
  FixedInterfaceRule rule = FixedInterfaceRule::SameCount;
  int extra_modes = 0;            ///< SameCount: modes added to the selected count
  double frequency_margin = 1.5;  ///< UpToFrequency: limit = margin x highest selected [Hz]
  int max_count = 200;            ///< UpToFrequency: bound on r
};

/// The fixed-interface request that carries `selection` over to the Craig-Bampton basis.
/// Throws InputError for a negative extra_modes, a margin < 1, a non-positive max_count, or
/// UpToFrequency without a selected mode above 0 Hz.
FixedInterfaceModes fixedInterfaceModes(const ModeSelection& selection,
                                        const FixedInterfaceOptions& options = {});

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics

// Which global modes the reduced model must represent (paper §3.1.1), with the reason for each,
// for the report. How the selection sets the number of fixed-interface modes of the Craig-Bampton
// basis is in fixed_interface_modes.h.
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/reduction/mac.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

enum class ModeSelectionRule {
  /// The lowest `count` modes.
  Count,
  /// Every mode with min_frequency_hz <= f <= max_frequency_hz.
  FrequencyBand,
  /// The paper's rule (§3.1.1, Fig. 10, Table 4): every candidate mode (e.g. of the tracked
  /// model) whose MAC with at least one reference mode (e.g. of the un-tracked model), computed
  /// on the common translational DOFs, is >= mac_threshold; restricted to the band when
  /// max_frequency_hz > 0. Applied to the tracked model against the un-tracked one it keeps 12
  /// modes in the paper, and the other way round 8 (Table 5).
  Correlation,
};

struct ModeSelectionOptions {
  ModeSelectionRule rule = ModeSelectionRule::Correlation;
  int count = 0;                  ///< Count rule
  double min_frequency_hz = 0.0;  ///< [Hz] FrequencyBand and Correlation
  double max_frequency_hz = 0.0;  ///< [Hz] 0: no upper limit (FrequencyBand needs one)
  double mac_threshold = kPaperMacThreshold;
  std::string reference_name = "reference";  ///< in reasons: "MAC 0.86 with un-tracked mode 5"
};

/// The reference modes for the Correlation rule.
struct ModeReference {
  Matrix mac;             ///< mac(candidate shapes, reference shapes) [candidates x references]
  Vector frequencies_hz;  ///< [Hz] one per reference mode
};

struct SelectedMode {
  int mode = 0;               ///< 0-based index in the candidate basis (reasons count from 1)
  double frequency_hz = 0.0;  ///< [Hz]
  std::string reason;         ///< e.g. "MAC 0.86 with un-tracked mode 5 (4.93 Hz)"
};

struct ModeSelection {
  std::vector<SelectedMode> modes;  ///< by increasing mode index

  int count() const { return static_cast<int>(modes.size()); }
  /// Highest selected frequency [Hz]; 0 when nothing is selected.
  double highestFrequencyHz() const;
};

/// Selects among candidate modes of frequencies `frequencies_hz` [Hz] (ascending, as returned by
/// fem::solveModes). `reference` is required by the Correlation rule and ignored otherwise.
/// Throws InputError for a non-positive count, an empty or inverted band, a threshold outside
/// (0, 1], a missing reference or a reference whose size does not match the candidates.
ModeSelection selectModes(const Vector& frequencies_hz, const ModeSelectionOptions& options,
                          const ModeReference* reference = nullptr);

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics

#include "tracked_vehicle_dynamics/reduction/mode_selection.h"

#include <algorithm>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/number_text.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

namespace {

/// Three significant figures, trailing zeros kept: 24.98 Hz reads "25.0 Hz" like its neighbours'
/// "6.95 Hz", not "25 Hz"; 120.4 Hz reads "120 Hz".
std::string hz(double f) {
  std::string text = io::formatC("%#.3g", f);
  if (text.back() == '.')
    text.pop_back();
  return text + " Hz";
}

bool inBand(double f, const ModeSelectionOptions& o) {
  return f >= o.min_frequency_hz && (o.max_frequency_hz <= 0.0 || f <= o.max_frequency_hz);
}

ModeSelection byCorrelation(const Vector& f, const ModeSelectionOptions& o,
                            const ModeReference* reference) {
  if (!reference)
    throw InputError("selectModes: the Correlation rule needs reference modes (MAC matrix)");
  if (reference->mac.rows() != f.size())
    throw InputError("selectModes: the MAC matrix has " + std::to_string(reference->mac.rows()) +
                     " rows, expected one per candidate mode (" + std::to_string(f.size()) + ")");
  if (reference->frequencies_hz.size() != reference->mac.cols())
    throw InputError("selectModes: " + std::to_string(reference->frequencies_hz.size()) +
                     " reference frequencies for " + std::to_string(reference->mac.cols()) +
                     " MAC columns");
  const std::vector<ModeCorrelation> correlation = correlateModes(reference->mac, o.mac_threshold);
  ModeSelection selection;
  for (const ModeCorrelation& c : correlation) {
    if (c.matches.empty() || !inBand(f(c.mode), o))
      continue;
    const ModeMatch& best = c.matches.front();
    std::string reason = "MAC " + io::formatC("%.2f", best.mac) + " with " + o.reference_name +
                         " mode " + std::to_string(best.mode + 1) + " (" +
                         hz(reference->frequencies_hz(best.mode)) + ")";
    for (std::size_t i = 1; i < c.matches.size(); ++i)
      reason += (i == 1 ? "; also " : ", ") + io::formatC("%.2f", c.matches[i].mac) +
                " with mode " + std::to_string(c.matches[i].mode + 1);
    selection.modes.push_back(SelectedMode{c.mode, f(c.mode), reason});
  }
  return selection;
}

}  // namespace

double ModeSelection::highestFrequencyHz() const {
  double highest = 0.0;
  for (const SelectedMode& m : modes)
    highest = std::max(highest, m.frequency_hz);
  return highest;
}

ModeSelection selectModes(const Vector& frequencies_hz, const ModeSelectionOptions& options,
                          const ModeReference* reference) {
  const ModeSelectionOptions& o = options;
  if (o.min_frequency_hz < 0.0 || o.max_frequency_hz < 0.0 ||
      (o.max_frequency_hz > 0.0 && o.max_frequency_hz < o.min_frequency_hz))
    throw InputError("selectModes: frequency band [" + std::to_string(o.min_frequency_hz) + ", " +
                     std::to_string(o.max_frequency_hz) + "] Hz is invalid");
  ModeSelection selection;
  switch (o.rule) {
    case ModeSelectionRule::Count: {
      if (o.count <= 0 || o.count > frequencies_hz.size())
        throw InputError("selectModes: count " + std::to_string(o.count) + " is not in 1.." +
                         std::to_string(frequencies_hz.size()) + " (the candidate modes)");
      for (int i = 0; i < o.count; ++i)
        selection.modes.push_back(SelectedMode{
            i, frequencies_hz(i),
            "mode " + std::to_string(i + 1) + " of the lowest " + std::to_string(o.count)});
      return selection;
    }
    case ModeSelectionRule::FrequencyBand: {
      if (o.max_frequency_hz <= 0.0)
        throw InputError("selectModes: the FrequencyBand rule needs max_frequency_hz > 0");
      const std::string band = "in the band [" + io::formatC("%g", o.min_frequency_hz) + ", " +
                               io::formatC("%g", o.max_frequency_hz) + "] Hz";
      for (int i = 0; i < frequencies_hz.size(); ++i)
        if (inBand(frequencies_hz(i), o))
          selection.modes.push_back(
              SelectedMode{i, frequencies_hz(i), hz(frequencies_hz(i)) + " " + band});
      return selection;
    }
    case ModeSelectionRule::Correlation:
      return byCorrelation(frequencies_hz, o, reference);
  }
  return selection;
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics

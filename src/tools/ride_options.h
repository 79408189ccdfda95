// The options of `tvd ride`, shared by its two methods: the time-domain run over a terrain
// (--track, ride_command.cpp) and the spectral evaluation on an ISO 8608 class's PSD (--iso8608,
// ride_spectral.cpp).
#pragma once

#include <string>
#include <vector>

#include "reduction_options.h"
#include "tracked_vehicle_dynamics/terrain/iso8608.h"

namespace tracked_vehicle_dynamics {
namespace tools {

struct RideOptions {
  std::string vehicle_file;
  std::string variant = "tracked";
  bool variant_given = false;
  std::string track;
  std::string speeds = "5:70:5";
  std::vector<std::string> points;  // --points, each comma-separated (repeated: all of them)
  bool points_given = false;        // false: the hull's CoG and every named point
  double power_limit_w = 6.0;
  double peak_limit_g = 2.5;
  double lowpass_hz = 30.0;
  double tolerance_kmh = 0.1;
  double dt = 1e-3;
  double lateral_offset = 0.0;
  ReducedModelFlags reduced;
  std::string out_file;
  bool json = false;
  // The spectral method: the road is the PSD of an ISO 8608 class (--iso8608), with the band,
  // slope and lateral correlation of `tvd terrain`'s roads.
  std::string iso_class;
  bool independent_sides = false;
  double waviness = terrain::Iso8608Options{}.waviness;
  double min_frequency = terrain::Iso8608Options{}.min_frequency;
  double max_frequency = terrain::Iso8608Options{}.max_frequency;
  bool max_frequency_given = false;  // the band note is for the default band only
  double points_per_decade = 400.0;
  std::string psd_out;  // --psd-out: the PSDs at the sweep's speeds (spectral only)
};

}  // namespace tools
}  // namespace tracked_vehicle_dynamics

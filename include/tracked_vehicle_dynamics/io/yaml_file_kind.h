// The package's YAML files told apart by their top-level keys, so that a file given where another
// kind belongs is named for what it is: a terrain file passed as a vehicle description used to
// fail on its first line with "spacing: unknown key", which sent users hunting for a typo.
#pragma once

#include "tracked_vehicle_dynamics/io/yaml_reader.h"

namespace tracked_vehicle_dynamics {
namespace io {

enum class YamlFileKind { VehicleDescription, FeModel, Terrain, NodeParameters, PaperReference };

/// Throws InputError "<file>: not <expected>: this is <other> (...)" when `root` holds none of the
/// keys only the expected kind has and some key only another kind has. Anything else returns, and
/// the kind's own reader names what is wrong key by key.
void expectNotOtherYamlFile(const YamlValue& root, YamlFileKind expected);

}  // namespace io
}  // namespace tracked_vehicle_dynamics

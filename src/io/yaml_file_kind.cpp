#include "tracked_vehicle_dynamics/io/yaml_file_kind.h"

#include <algorithm>
#include <initializer_list>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace io {

namespace {

struct KindKeys {
  YamlFileKind kind;
  const char* name;
  /// Top-level keys no other kind of the package's files has (a shared key, like name or ties,
  /// says nothing).
  std::initializer_list<const char*> keys;
};

const KindKeys kKinds[] = {
    {YamlFileKind::VehicleDescription,
     "a vehicle description (e.g. config/vehicles/paper_vehicle.yaml; tvd --vehicle)",
     {"hull", "running_gear", "road_wheel", "suspension", "track_assembly", "sprocket", "idler",
      "return_rollers"}},
    {YamlFileKind::FeModel,
     "an FE model file (doc/model_file.md; tvd modes --model)",
     {"nodes", "beams", "materials", "sections", "masses", "rigid_joints"}},
    {YamlFileKind::Terrain, "a terrain file (tvd simulate --track)", {"heights"}},
    {YamlFileKind::NodeParameters,
     "the node's parameter file (config/vehicle_dynamics.yaml; its key vehicle names the "
     "description)",
     {"variant", "rate", "catch_up_limit", "speed_timeout", "odom_frame", "base_frame"}},
    {YamlFileKind::PaperReference,
     "the file of the paper's reference figures (config/paper_reference.yaml)",
     {"table4"}},
};

const KindKeys& entryOf(YamlFileKind kind) {
  return *std::find_if(std::begin(kKinds), std::end(kKinds),
                       [kind](const KindKeys& k) { return k.kind == kind; });
}

bool hasAnyKey(const YamlValue& root, const KindKeys& kind) {
  for (const auto& [key, value] : root.entries())
    for (const char* k : kind.keys)
      if (key == k)
        return true;
  return false;
}

}  // namespace

void expectNotOtherYamlFile(const YamlValue& root, YamlFileKind expected) {
  if (!root.isMap() || hasAnyKey(root, entryOf(expected)))
    return;
  for (const KindKeys& other : kKinds)
    if (other.kind != expected && hasAnyKey(root, other))
      throw InputError(root.file() + ": not " + entryOf(expected).name + ": this is " + other.name);
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics

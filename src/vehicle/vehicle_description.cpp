#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/fnv1a.h"
#include "tracked_vehicle_dynamics/io/message_text.h"
#include "tracked_vehicle_dynamics/io/number_text.h"
#include "tracked_vehicle_dynamics/io/yaml_file_kind.h"
#include "tracked_vehicle_dynamics/io/yaml_reader.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

namespace {

constexpr double kDegree = kPi / 180.0;
/// Relative tolerance of the chain-length checks (pitch x count against the stated lengths).
constexpr double kLengthTolerance = 1e-3;
/// No value of a vehicle comes near 1e15 in SI (the stiffest, k_w, is 2e10 N/m); beyond it a value
/// is a typo, and 1e300 kg once overflowed the statics into -4.8e293 m of sag.
constexpr double kImplausible = 1e15;
/// The optional scalars of the description (suspension.guide_stiffness,
/// track_assembly.static_tension), outside the table of required fields.
constexpr const char* kGuideStiffnessKey = "guide_stiffness";
constexpr const char* kStaticTensionKey = "static_tension";

enum class Kind { Real, Integer, RealList, IntegerList, Angle };
// PoissonRatio: (-1, 0.5], outside which an isotropic material has a negative or infinite bulk
// or shear modulus (as a model file's nu, model_yaml.cpp).
enum class Range { Any, Positive, NonNegative, Fraction, PoissonRatio };

/// One scalar or list value of the description: where it lives in the file, its unit and range.
/// The table of fields is the single list that the loader, the validator and the canonical dump
/// share, so a parameter is declared once.
struct Field {
  const char* section;
  const char* key;
  const char* unit;
  Kind kind;
  Range range;
  void* target;

  std::string path() const { return std::string(section) + "." + key; }
};

std::vector<Field> fieldsOf(VehicleDescription& d) {
  auto& h = d.hull;
  auto& g = d.running_gear;
  auto& w = d.road_wheel;
  auto& s = d.suspension;
  auto& t = d.track_assembly;
  using K = Kind;
  using R = Range;
  return {
      {"hull", "mass", "kg", K::Real, R::Positive, &h.mass},
      {"hull", "roll_inertia", "kg*m^2", K::Real, R::Positive, &h.roll_inertia},
      {"hull", "pitch_inertia", "kg*m^2", K::Real, R::Positive, &h.pitch_inertia},
      {"hull", "yaw_inertia", "kg*m^2", K::Real, R::Positive, &h.yaw_inertia},
      {"hull", "cog_height", "m", K::Real, R::Positive, &h.cog_height},
      {"hull", "cog_x", "m", K::Real, R::Any, &h.cog_x},
      {"hull", "length", "m", K::Real, R::Positive, &h.length},
      {"hull", "width", "m", K::Real, R::Positive, &h.width},
      {"hull", "height", "m", K::Real, R::Positive, &h.height},
      {"running_gear", "axle_count", "1", K::Integer, R::Positive, &g.axle_count},
      {"running_gear", "axle_spacing", "m", K::Real, R::Positive, &g.axle_spacing},
      {"running_gear", "track_centre_distance", "m", K::Real, R::Positive,
       &g.track_centre_distance},
      {"road_wheel", "mass", "kg", K::Real, R::Positive, &w.mass},
      {"road_wheel", "radius", "m", K::Real, R::Positive, &w.radius},
      {"road_wheel", "spin_inertia", "kg*m^2", K::Real, R::Positive, &w.spin_inertia},
      {"road_wheel", "tilt_inertia", "kg*m^2", K::Real, R::Positive, &w.tilt_inertia},
      {"suspension", "torsion_bar_stiffness", "N*m/rad", K::Real, R::Positive,
       &s.torsion_bar_stiffness},
      {"suspension", "arm_length", "m", K::Real, R::Positive, &s.arm_length},
      {"suspension", "arm_angle", "deg", K::Angle, R::Any, &s.arm_angle},
      {"suspension", "pivot_y", "m", K::Real, R::Positive, &s.pivot_y},
      {"suspension", "contact_stiffness", "N/m", K::Real, R::Positive, &s.contact_stiffness},
      // Positive: it is the un-tracked hull's only longitudinal restraint (0 left it free).
      {"suspension", "contact_shear_stiffness", "N/m", K::Real, R::Positive,
       &s.contact_shear_stiffness},
      {"suspension", "guide_contact_height", "m", K::Real, R::NonNegative, &s.guide_contact_height},
      {"suspension", "arm_damping", "N*m*s/rad", K::Real, R::NonNegative, &s.arm_damping},
      {"track_assembly", "count", "1", K::Integer, R::Positive, &t.count},
      {"track_assembly", "ground_count", "1", K::Integer, R::Positive, &t.ground_count},
      {"track_assembly", "chain_length", "m", K::Real, R::Positive, &t.chain_length},
      {"track_assembly", "ground_length", "m", K::Real, R::Positive, &t.ground_length},
      {"track_assembly", "pitch", "m", K::Real, R::Positive, &t.pitch},
      {"track_assembly", "pin_joint_distance", "m", K::Real, R::Positive, &t.pin_joint_distance},
      {"track_assembly", "mass", "kg", K::Real, R::Positive, &t.mass},
      {"track_assembly", "shear_stiffness_x", "N/m", K::Real, R::Positive, &t.shear_stiffness_x},
      {"track_assembly", "shear_stiffness_y", "N/m", K::Real, R::Positive, &t.shear_stiffness_y},
      {"track_assembly", "compression_stiffness", "N/m", K::Real, R::Positive,
       &t.compression_stiffness},
      {"track_assembly", "torsional_stiffness_y", "N*m/rad", K::Real, R::Positive,
       &t.torsional_stiffness_y},
      {"track_assembly", "width", "m", K::Real, R::Positive, &t.width},
      {"track_assembly", "pitch_line_height", "m", K::Real, R::Positive, &t.pitch_line_height},
      {"track_assembly", "upper_surface_height", "m", K::Real, R::Positive,
       &t.upper_surface_height},
      {"track_assembly", "pad_lateral_offset", "m", K::Real, R::Positive, &t.pad_lateral_offset},
      {"track_assembly", "pad_column_offset", "m", K::Real, R::Positive, &t.pad_column_offset},
      {"track_assembly", "pad_rubber_below_core", "m", K::Real, R::Positive,
       &t.pad_rubber_below_core},
      {"track_assembly", "pad_rubber_above_core", "m", K::Real, R::Positive,
       &t.pad_rubber_above_core},
      {"track_assembly", "pad_core_thickness", "m", K::Real, R::Positive, &t.pad_core_thickness},
      {"track_assembly", "pad_mass", "kg", K::Real, R::Positive, &t.pad_mass},
      {"track_assembly", "pad_sole_mass_fraction", "1", K::Real, R::Fraction,
       &t.pad_sole_mass_fraction},
      {"track_assembly", "pin_diameter", "m", K::Real, R::Positive, &t.pin_diameter},
      {"track_assembly", "steel_young_modulus", "Pa", K::Real, R::Positive, &t.steel_young_modulus},
      {"track_assembly", "steel_poisson_ratio", "1", K::Real, R::PoissonRatio,
       &t.steel_poisson_ratio},
      {"track_assembly", "steel_density", "kg/m^3", K::Real, R::Positive, &t.steel_density},
      {"track_assembly", "link_member_area", "m^2", K::Real, R::Positive, &t.link_member_area},
      {"track_assembly", "link_member_bending_inertia", "m^4", K::Real, R::Positive,
       &t.link_member_bending_inertia},
      {"track_assembly", "link_member_lateral_inertia", "m^4", K::Real, R::Positive,
       &t.link_member_lateral_inertia},
      {"track_assembly", "link_member_torsion_constant", "m^4", K::Real, R::Positive,
       &t.link_member_torsion_constant},
      {"track_assembly", "link_beam_area", "m^2", K::Real, R::Positive, &t.link_beam_area},
      {"track_assembly", "link_beam_bending_inertia", "m^4", K::Real, R::Positive,
       &t.link_beam_bending_inertia},
      {"track_assembly", "link_beam_inplane_inertia", "m^4", K::Real, R::Positive,
       &t.link_beam_inplane_inertia},
      {"track_assembly", "link_beam_torsion_constant", "m^4", K::Real, R::Positive,
       &t.link_beam_torsion_constant},
      {"sprocket", "radius", "m", K::Real, R::Positive, &d.sprocket.radius},
      {"sprocket", "centre_x", "m", K::Real, R::Any, &d.sprocket.centre_x},
      {"sprocket", "centre_z", "m", K::Real, R::Positive, &d.sprocket.centre_z},
      {"sprocket", "mass", "kg", K::Real, R::NonNegative, &d.sprocket.mass},
      {"sprocket", "inertia", "kg*m^2", K::Real, R::NonNegative, &d.sprocket.inertia},
      {"idler", "radius", "m", K::Real, R::Positive, &d.idler.radius},
      {"idler", "centre_z", "m", K::Real, R::Positive, &d.idler.centre_z},
      {"idler", "mass", "kg", K::Real, R::NonNegative, &d.idler.mass},
      {"idler", "inertia", "kg*m^2", K::Real, R::NonNegative, &d.idler.inertia},
      {"return_rollers", "x", "m", K::RealList, R::Any, &d.return_rollers.x},
      {"return_rollers", "radius", "m", K::Real, R::Positive, &d.return_rollers.radius},
      {"return_rollers", "mass", "kg", K::Real, R::NonNegative, &d.return_rollers.mass},
      {"ties", "ground_stiffness", "N/m", K::Real, R::Positive, &d.ties.ground_stiffness},
      {"damping", "modal_ratio", "1", K::Real, R::Fraction, &d.damping.modal_ratio},
      {"damping", "rayleigh_alpha", "1/s", K::Real, R::NonNegative, &d.damping.rayleigh_alpha},
      {"damping", "rayleigh_beta", "s", K::Real, R::NonNegative, &d.damping.rayleigh_beta},
      {"damping", "damped_stations", "1", K::IntegerList, R::Positive, &d.damping.damped_stations},
  };
}

const char* const kSections[] = {"hull",           "running_gear", "road_wheel", "suspension",
                                 "track_assembly", "sprocket",     "idler",      "return_rollers",
                                 "ties",           "damping"};

const char* dampingModelName(DampingModel m) {
  return m == DampingModel::Modal ? "modal" : "rayleigh";
}

const char* roadInputStationName(RoadInputStation s) {
  return s == RoadInputStation::PadCentre ? "pad_centre" : "sole";
}

/// Full precision, for the canonical text: "%.17g" in every locale (the hash must not change
/// with the process's locale).
std::string format(double v) {
  std::string text;
  io::appendGeneral(text, v, 17);
  return text;
}

// ------------------------------------------------------------------------------------------
// Loading
// ------------------------------------------------------------------------------------------

/// Checks a map holds exactly the keys in `allowed` (the reader's expectMap takes a fixed list).
void expectKeys(const io::YamlValue& map, const std::set<std::string>& allowed) {
  map.expectMap();
  std::string list;
  for (const auto& k : allowed)
    list += (list.empty() ? "" : ", ") + k;
  for (const auto& [key, value] : map.entries())
    if (!allowed.count(key))
      value.fail("unknown key (allowed keys: " + list + ")");
}

void checkRange(const io::YamlValue& v, double x, Range range) {
  if (range == Range::Positive && !(x > 0.0))
    v.fail("must be positive, got " + brief(x));
  if (range == Range::NonNegative && x < 0.0)
    v.fail("must not be negative, got " + brief(x));
  if (range == Range::Fraction && (x < 0.0 || x > 1.0))
    v.fail("must lie in [0, 1], got " + brief(x));
  if (range == Range::PoissonRatio && !(x > -1.0 && x <= 0.5))
    v.fail("Poisson's ratio must lie in (-1, 0.5], got " + brief(x));
}

/// Reads {value, unit, source} and returns the value node after checking unit and source.
io::YamlValue quantity(const io::YamlValue& entry, const char* expected_unit,
                       std::map<std::string, std::string>& sources) {
  if (expected_unit)
    entry.expectMap({"value", "unit", "source"});
  else
    entry.expectMap({"value", "source"});
  if (expected_unit) {
    const io::YamlValue unit = entry["unit"];
    const std::string given = unit.asString();
    if (given != expected_unit)
      unit.fail("unit '" + given + "' is not the expected '" + expected_unit +
                "' (convert the value)");
  }
  const io::YamlValue source = entry["source"];
  // A number names no origin: a value typed under source (5.2e5), or a source cut to its number.
  if (source.isPlainNumber())
    source.fail(
        "source must name where the value comes from (a text, e.g. \"Table 1, k_t\" or "
        "\"estimated\"), got the number " +
        source.asString() + " (quote it if it is one: \"" + source.asString() + "\")");
  const std::string text = source.asString();
  if (text.empty())
    source.fail("source must name where the value comes from");
  sources[entry.path()] = text;
  return entry["value"];
}

void readField(const io::YamlValue& section, const Field& f,
               std::map<std::string, std::string>& sources) {
  const io::YamlValue v = quantity(section[f.key], f.unit, sources);
  switch (f.kind) {
    case Kind::Real:
    case Kind::Angle: {
      double x = v.asNumber();
      checkRange(v, x, f.range);
      if (std::abs(x) > kImplausible)
        v.fail("value " + brief(x) + " is implausibly large");
      if (f.kind == Kind::Angle) {
        if (std::abs(x) >= 90.0)
          v.fail("angle must lie in (-90, 90) deg, got " + brief(x));
        x *= kDegree;
      }
      *static_cast<double*>(f.target) = x;
      break;
    }
    case Kind::Integer: {
      const std::int64_t n = v.asInteger();
      checkRange(v, static_cast<double>(n), f.range);
      if (n > 1000000)
        v.fail("value " + std::to_string(n) + " is implausibly large");
      *static_cast<int*>(f.target) = static_cast<int>(n);
      break;
    }
    case Kind::RealList: {
      std::vector<double> xs;
      for (const io::YamlValue& e : v.elements("a list of numbers")) {
        xs.push_back(e.asNumber());
        checkRange(e, xs.back(), f.range);
        if (std::abs(xs.back()) > kImplausible)
          e.fail("value " + brief(xs.back()) + " is implausibly large");
      }
      *static_cast<std::vector<double>*>(f.target) = xs;
      break;
    }
    case Kind::IntegerList: {
      std::vector<int> ns;
      for (const io::YamlValue& e : v.elements("a list of integers")) {
        const std::int64_t n = e.asInteger();
        checkRange(e, static_cast<double>(n), f.range);
        if (n > 1000000)
          e.fail("value " + std::to_string(n) + " is implausibly large");
        ns.push_back(static_cast<int>(n));
      }
      *static_cast<std::vector<int>*>(f.target) = ns;
      break;
    }
  }
}

// ------------------------------------------------------------------------------------------
// Validation
// ------------------------------------------------------------------------------------------

class Checker {
 public:
  explicit Checker(const std::string& where) : where_(where) {}
  void require(bool ok, const std::string& key, const std::string& what) const {
    if (!ok)
      throw InputError(where_ + ": " + key + ": " + what);
  }

 private:
  std::string where_;
};

}  // namespace

void validateDescription(const VehicleDescription& d, const std::string& where) {
  const Checker c(where);
  // Ranges first (descriptions built in code bypass the loader).
  VehicleDescription copy = d;
  for (const Field& f : fieldsOf(copy)) {
    auto bad = [&](double x) {
      return !std::isfinite(x) || std::abs(x) > kImplausible ||
             (f.range == Range::Positive && !(x > 0.0)) ||
             (f.range == Range::NonNegative && x < 0.0) ||
             (f.range == Range::Fraction && (x < 0.0 || x > 1.0)) ||
             (f.range == Range::PoissonRatio && !(x > -1.0 && x <= 0.5));
    };
    if (f.kind == Kind::Real || f.kind == Kind::Angle) {
      const double x = *static_cast<double*>(f.target);
      c.require(!bad(x), f.path(), "value " + brief(x) + " is out of range or not finite");
    } else if (f.kind == Kind::Integer) {
      const double x = *static_cast<int*>(f.target);
      c.require(!bad(x), f.path(), "value " + brief(x) + " is out of range");
    } else if (f.kind == Kind::RealList) {
      for (double x : *static_cast<std::vector<double>*>(f.target))
        c.require(!bad(x), f.path(), "value " + brief(x) + " is out of range or not finite");
    } else {
      for (int x : *static_cast<std::vector<int>*>(f.target))
        c.require(!bad(x), f.path(), "value " + std::to_string(x) + " is out of range");
    }
  }

  if (d.suspension.guide_stiffness) {
    const double x = *d.suspension.guide_stiffness;
    c.require(std::isfinite(x) && x > 0.0 && x <= kImplausible,  // 0: free sideways, singular
              std::string("suspension.") + kGuideStiffnessKey,
              "value " + brief(x) + " is out of range or not finite");
  }
  if (d.track_assembly.static_tension) {
    const double x = *d.track_assembly.static_tension;
    c.require(std::isfinite(x) && x >= 0.0 && x <= kImplausible,  // < 0: a chain pushed, buckling
              std::string("track_assembly.") + kStaticTensionKey,
              "value " + brief(x) + " N is out of range or not finite (a tension: 0 or more)");
  }
  const auto& t = d.track_assembly;
  const auto& g = d.running_gear;
  c.require(t.ground_count <= t.count, "track_assembly.ground_count",
            std::to_string(t.ground_count) + " ground-contact assemblies but the chain has only " +
                std::to_string(t.count));
  c.require(std::abs(t.pitch * t.count - t.chain_length) <= kLengthTolerance * t.chain_length,
            "track_assembly.chain_length",
            brief(t.chain_length) +
                " m is inconsistent with pitch x count = " + brief(t.pitch * t.count) + " m");
  c.require(
      std::abs(t.pitch * t.ground_count - t.ground_length) <= kLengthTolerance * t.ground_length,
      "track_assembly.ground_length",
      brief(t.ground_length) + " m is inconsistent with pitch x ground_count = " +
          brief(t.pitch * t.ground_count) + " m");
  c.require(t.pin_joint_distance < t.pitch, "track_assembly.pin_joint_distance",
            "must be shorter than the pitch " + brief(t.pitch) + " m");
  c.require(2.0 * t.pad_column_offset < t.pitch, "track_assembly.pad_column_offset",
            "pads longer than the pitch overlap their neighbours");
  c.require(t.pad_lateral_offset < 0.5 * t.width, "track_assembly.pad_lateral_offset",
            "pads lie outside the track width " + brief(t.width) + " m");
  // A pad's offsets and rubber layers of less than a millimetre are no pad: at 1e-300 m a zero
  // offset put two nodes of the link's beam on one point, and a rubber layer's stiffness, which
  // goes as 1 / its thickness, made the assembly's stiffness matrix indefinite (the message
  // blamed "a track_assembly stiffness"). The bundled vehicles' are 10 mm and more.
  constexpr double kMinPadDimension = 1e-3;
  for (const auto& [value, key] :
       {std::pair<double, const char*>{t.pad_lateral_offset, "pad_lateral_offset"},
        {t.pad_column_offset, "pad_column_offset"},
        {t.pad_rubber_below_core, "pad_rubber_below_core"},
        {t.pad_rubber_above_core, "pad_rubber_above_core"}})
    c.require(value >= kMinPadDimension, std::string("track_assembly.") + key,
              brief(value) +
                  " m is less than 1 mm (at least 0.001 m: a pad's offsets and rubber "
                  "layers are centimetres)");
  const double pad_height =
      t.pad_rubber_below_core + t.pad_core_thickness + t.pad_rubber_above_core;
  c.require(t.pitch_line_height > pad_height, "track_assembly.pitch_line_height",
            "the pins must lie above the pads (" + brief(pad_height) + " m)");
  c.require(t.upper_surface_height > t.pitch_line_height, "track_assembly.upper_surface_height",
            "the wheel path must lie above the pitch line");
  // Around the sprocket and the idler the pitch line wraps their radius and the wheel path lies
  // inside it by (upper_surface_height - pitch_line_height): that must be less than either
  // radius, or the links' upper surfaces would cross the wheel's centre (a height in mm read as m).
  const double inside = t.upper_surface_height - t.pitch_line_height;
  const double wrap_radius = std::min(d.sprocket.radius, d.idler.radius);
  c.require(inside < wrap_radius, "track_assembly.upper_surface_height",
            brief(t.upper_surface_height) + " m puts the wheel path " + brief(inside) +
                " m inside the pitch line, more than the " +
                (d.sprocket.radius <= d.idler.radius ? "sprocket" : "idler") + " radius " +
                brief(wrap_radius) + " m that the chain wraps");
  // A section's radius of gyration sqrt(I / A) cannot exceed the link it belongs to (pitch
  // along the track, width across): an inertia in mm^4 typed as m^4, 1e12 times too stiff
  // against the pins' flexibility, leaves a chain whose stiffness matrix the solvers lose.
  const double link_size = std::max(t.pitch, t.width);
  const struct {
    double inertia, area;
    const char *key, *area_key;
  } sections[] = {
      {t.link_member_bending_inertia, t.link_member_area, "link_member_bending_inertia",
       "link_member_area"},
      {t.link_member_lateral_inertia, t.link_member_area, "link_member_lateral_inertia",
       "link_member_area"},
      {t.link_member_torsion_constant, t.link_member_area, "link_member_torsion_constant",
       "link_member_area"},
      {t.link_beam_bending_inertia, t.link_beam_area, "link_beam_bending_inertia",
       "link_beam_area"},
      {t.link_beam_inplane_inertia, t.link_beam_area, "link_beam_inplane_inertia",
       "link_beam_area"},
      {t.link_beam_torsion_constant, t.link_beam_area, "link_beam_torsion_constant",
       "link_beam_area"},
  };
  // An area in mm^2 typed as m^2 (1.2e-3 m^2 read as 1200) is a section no link could hold:
  // larger than the square of the link's largest dimension. It would pass the gyration check
  // below (sqrt(I / A) only shrinks) and leave a chain 1e6 times too stiff axially.
  for (const auto& [area, key] :
       {std::pair<double, const char*>{t.link_member_area, "link_member_area"},
        {t.link_beam_area, "link_beam_area"}})
    c.require(area <= link_size * link_size, std::string("track_assembly.") + key,
              brief(area) + " m^2 is larger than the link itself (" + brief(link_size) +
                  " m, the larger of pitch and width, squared: " + brief(link_size * link_size) +
                  " m^2): mm^2 typed as m^2?");
  for (const auto& sec : sections) {
    const double gyration = std::sqrt(sec.inertia / sec.area);
    c.require(gyration <= link_size, std::string("track_assembly.") + sec.key,
              brief(sec.inertia) + " m^4 over " + sec.area_key + " " + brief(sec.area) +
                  " m^2 gives a radius of gyration sqrt(I / A) = " + brief(gyration) +
                  " m, larger than the link (" + brief(link_size) +
                  " m, the larger of pitch and width): mm^4 typed as m^4?");
  }
  // The ground springs stand for the road under the pads; at a thousandth of a pad's stiffness
  // (1.9e4 N/m for the paper's) the vehicle already sinks 91 mm into it (8 mm on the bundled
  // 2e10 N/m), and at 1e-200 it is a free body that the statics can only report as a list of DOFs.
  c.require(d.ties.ground_stiffness >= 1e-3 * t.compression_stiffness, "ties.ground_stiffness",
            brief(d.ties.ground_stiffness) +
                " N/m is less than a thousandth of the pads' compression_stiffness " +
                brief(t.compression_stiffness) +
                " N/m: the vehicle would sink into such a ground (a value in another unit?)");
  // The guide horns touch the wheel's rim between the wheel path and the hub.
  c.require(d.suspension.guide_contact_height < d.road_wheel.radius,
            "suspension.guide_contact_height",
            brief(d.suspension.guide_contact_height) +
                " m above the wheel path reaches past the road wheel's hub (radius " +
                brief(d.road_wheel.radius) + " m): the guide horns touch the rim below it");
  c.require(g.axle_count >= 2 && g.axle_count <= 9, "running_gear.axle_count",
            "2 to 9 axles per side are supported (node numbering)");
  c.require(t.count <= 999, "track_assembly.count",
            "at most 999 assemblies per side are supported (node numbering)");
  const double wheelbase = g.axle_spacing * (g.axle_count - 1);
  // Longer than both the ground run and the hull: the wheelbase itself is what is wrong, not
  // either of the two lengths a check below would otherwise name.
  c.require(wheelbase < t.ground_length || wheelbase < d.hull.length, "running_gear.axle_spacing",
            brief(g.axle_spacing) + " m between " + std::to_string(g.axle_count) +
                " axles makes a wheelbase of " + brief(wheelbase) +
                " m, longer than both the hull (hull.length " + brief(d.hull.length) +
                " m) and the ground run (track_assembly.ground_length " + brief(t.ground_length) +
                " m)");
  c.require(wheelbase < t.ground_length, "track_assembly.ground_length",
            "the ground run " + brief(t.ground_length) + " m is not longer than the wheelbase " +
                brief(wheelbase) + " m");
  c.require(t.width < g.track_centre_distance, "track_assembly.width",
            "the tracks overlap (width >= track_centre_distance)");
  c.require(d.suspension.pivot_y < 0.5 * g.track_centre_distance, "suspension.pivot_y",
            "pivots must lie inboard of the track centre lines");
  c.require(std::abs(d.hull.cog_x) < 0.5 * d.hull.length, "hull.cog_x",
            "the centre of gravity lies outside the hull length");
  c.require(d.hull.cog_height < d.hull.height, "hull.cog_height",
            "the centre of gravity lies above the hull height");
  // Principal moments of a rigid body: each at most the sum of the other two.
  const double inertia_sum = d.hull.roll_inertia + d.hull.pitch_inertia + d.hull.yaw_inertia;
  const std::pair<double, const char*> inertias[] = {{d.hull.roll_inertia, "hull.roll_inertia"},
                                                     {d.hull.pitch_inertia, "hull.pitch_inertia"},
                                                     {d.hull.yaw_inertia, "hull.yaw_inertia"}};
  for (const auto& [i, key] : inertias)
    c.require(2.0 * i <= inertia_sum, key,
              brief(i) + " kg*m^2 exceeds the sum of the other two principal inertias (" +
                  brief(inertia_sum - i) + "), which no rigid body has");
  // Stiffness-proportional damping gives a mode of omega the ratio beta omega / 2: beta = 1 s is
  // already 3 times critical at the hull's 1 Hz bounce, and every mode above it more (structural
  // values are 1e-4 .. 1e-2 s). Beyond it a value is a typo (1e10 s was accepted).
  constexpr double kMaxRayleighBeta = 1.0;
  c.require(d.damping.rayleigh_beta <= kMaxRayleighBeta, "damping.rayleigh_beta",
            brief(d.damping.rayleigh_beta) +
                " s is more than 1 s: it damps a 1 Hz mode beta omega / 2 = " +
                brief(d.damping.rayleigh_beta * kPi) +
                " times critically (typical: 1e-4 .. 1e-2 s)");
  // The arm dampers sit on the damped stations only: without any, arm_damping was silently
  // unused (a description's value that would be ignored is refused, as the tools' options are).
  c.require(d.suspension.arm_damping == 0.0 || !d.damping.damped_stations.empty(),
            "suspension.arm_damping",
            brief(d.suspension.arm_damping) +
                " N*m*s/rad would be unused: damping.damped_stations lists no station with an arm "
                "damper (list the axles, e.g. [1, " +
                std::to_string(g.axle_count) + "], or give arm_damping 0)");
  std::set<int> damped;
  for (int s : d.damping.damped_stations) {
    c.require(s >= 1 && s <= g.axle_count, "damping.damped_stations",
              "station " + std::to_string(s) + " is not in 1.." + std::to_string(g.axle_count));
    // Listed twice is one damper (a set), so most likely a typo for another station.
    c.require(damped.insert(s).second, "damping.damped_stations",
              "station " + std::to_string(s) + " is listed twice");
  }
  // Geometry a builder would accept but no vehicle has: each of these once gave a model.
  c.require(2.0 * d.road_wheel.radius < g.axle_spacing, "road_wheel.radius",
            "wheels of radius " + brief(d.road_wheel.radius) + " m overlap at the axle spacing " +
                brief(g.axle_spacing) + " m");
  c.require(
      wheelbase < d.hull.length, "hull.length",
      brief(d.hull.length) + " m is not longer than the wheelbase " + brief(wheelbase) + " m");
  c.require(g.track_centre_distance < d.hull.width, "hull.width",
            brief(d.hull.width) + " m is not wider than the track centre distance " +
                brief(g.track_centre_distance) + " m");
  // The chain wraps the sprocket at one end of the ground run and the idler at the other
  // (chain_path.h): a rear drive sprocket (x < 0, the paper's vehicle) or a front one (x > 0).
  const bool front_drive = frontDrive(d);
  c.require(std::abs(d.sprocket.centre_x) > 0.5 * t.ground_length, "sprocket.centre_x",
            "the sprocket must lie beyond an end of the ground run (|x| > " +
                brief(0.5 * t.ground_length) +
                " m; x < 0 for a rear drive, x > 0 for a front one)");
  // The sprocket wheel within the hull length, with kWheelOverhang to spare (the idler follows
  // from the chain length: solveIdlerX checks it).
  c.require(
      std::abs(d.sprocket.centre_x) + d.sprocket.radius <= 0.5 * d.hull.length + kWheelOverhang,
      "sprocket.centre_x",
      "the sprocket reaches x = " +
          brief(d.sprocket.centre_x + (front_drive ? 1.0 : -1.0) * d.sprocket.radius) +
          " m, more than " + brief(kWheelOverhang) + " m beyond the hull's " +
          (front_drive ? "front end (x = " + brief(0.5 * d.hull.length)
                       : "rear end (x = " + brief(-0.5 * d.hull.length)) +
          " m)");
  // Sprocket and idler within the vehicle's height (else the chain cannot wrap them, and the
  // builder would blame the chain's length).
  for (const auto& [centre_z, radius, key] :
       {std::tuple<double, double, const char*>{d.sprocket.centre_z, d.sprocket.radius,
                                                "sprocket.centre_z"},
        std::tuple<double, double, const char*>{d.idler.centre_z, d.idler.radius,
                                                "idler.centre_z"}})
    c.require(centre_z + radius <= d.hull.height, key,
              brief(centre_z) + " m puts the wheel's top at " + brief(centre_z + radius) +
                  " m, above the hull's height " + brief(d.hull.height) + " m");
  for (double x : d.return_rollers.x)
    c.require(front_drive ? x < d.sprocket.centre_x : x > d.sprocket.centre_x, "return_rollers.x",
              "roller at x = " + brief(x) + " m lies " + (front_drive ? "ahead of" : "behind") +
                  " the sprocket");
  c.require(d.return_rollers.x.size() <= 50, "return_rollers.x",
            std::to_string(d.return_rollers.x.size()) +
                " rollers per side; at most 50 are supported (node numbering)");
  std::vector<double> rollers = d.return_rollers.x;
  std::sort(rollers.begin(), rollers.end());
  for (std::size_t i = 1; i < rollers.size(); ++i)
    c.require(rollers[i] - rollers[i - 1] >= 2.0 * d.return_rollers.radius, "return_rollers.x",
              "rollers at x = " + brief(rollers[i - 1]) + " and " + brief(rollers[i]) +
                  " m overlap (radius " + brief(d.return_rollers.radius) + " m)");
  // Arm pivot z_p = z_w + a sin(beta) (vehicle_model.cpp) must be above the ground.
  const double wheel_z = wheelCentreZ(d);
  const double pivot_z = wheel_z + d.suspension.arm_length * std::sin(d.suspension.arm_angle);
  c.require(pivot_z > 0.0, "suspension.arm_angle",
            "the arm pivot lies below the ground (z = " + brief(pivot_z) + " m)");
  c.require(d.suspension.arm_length < d.hull.length, "suspension.arm_length",
            "an arm of " + brief(d.suspension.arm_length) + " m is longer than the hull");
  // The wheel rate goes as k_t / a^2: an arm of 1e-300 m made it infinite and the statics NaN.
  constexpr double kMinArmLength = 0.01;
  c.require(d.suspension.arm_length >= kMinArmLength, "suspension.arm_length",
            "an arm of " + brief(d.suspension.arm_length) +
                " m is shorter than 1 cm (a road-wheel arm is tens of cm long)");
  // The torsion bar is the arm's only restraint in the un-tracked model: its wheel rate
  // k_t / (a cos beta)^2 in series with the wheel's contact_stiffness carries the hull. Below a
  // billionth of that spring the solve keeps fewer than 7 of 16 digits (at 1e-10 the paper's
  // statics were off 1e-6 in force balance, at 1e-14 by 2 %, at 1e-16 singular: "a mechanism
  // involving node 1001 ry", naming no key). A bar 1000 times too soft (8e-8 of it for the
  // paper's) is a valid value that staticWarnings() reports.
  constexpr double kMinWheelRateShare = 1e-9;
  const double lever = d.suspension.arm_length * std::cos(d.suspension.arm_angle);
  const double min_torsion = kMinWheelRateShare * d.suspension.contact_stiffness * lever * lever;
  c.require(d.suspension.torsion_bar_stiffness >= min_torsion, "suspension.torsion_bar_stiffness",
            brief(d.suspension.torsion_bar_stiffness) +
                " N*m/rad gives a wheel rate k_t / (arm_length cos(arm_angle))^2 of " +
                brief(d.suspension.torsion_bar_stiffness / (lever * lever)) +
                " N/m, less than 1e-9 of suspension.contact_stiffness " +
                brief(d.suspension.contact_stiffness) + " N/m in series with it: at least " +
                brief(min_torsion) + " N*m/rad (a value in another unit?)");
  // The name is printed in every report and written into results: an escape code or a newline
  // in it reached the terminal raw.
  c.require(std::none_of(d.name.begin(), d.name.end(),
                         [](char ch) {
                           const auto u = static_cast<unsigned char>(ch);
                           return u < 0x20 || u == 0x7f;
                         }),
            "name",
            "the vehicle's name must not hold control characters (a newline, a tab, an escape "
            "code), got \"" +
                io::printable(d.name, 60) + "\"");
  std::set<std::string> names;
  for (const NamedPoint& p : d.named_points) {
    const std::string key = "named_points." + p.name;
    c.require(!p.name.empty(), "named_points", "a point has no name");
    c.require(names.insert(p.name).second, key, "name given twice");
    // The name becomes CSV columns, MAT variables ("<name>_accel_z_m_s2", at most 63 characters;
    // ride's longest, "<name>_vibration_total_value_m_s2", is checked by ride --out .mat) and a tf
    // frame, next to the hull's and the road wheels' own.
    const bool identifier = std::isalpha(static_cast<unsigned char>(p.name[0])) &&
                            std::all_of(p.name.begin(), p.name.end(), [](char ch) {
                              return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
                            });
    c.require(identifier && p.name.size() <= 40, key,
              "a name must start with a letter, hold only letters, digits and '_', and have at "
              "most 40 characters");
    c.require(p.name != "hull" && p.name != "base_link" && p.name != "odom" &&
                  p.name.rfind("road_wheel_", 0) != 0,
              key, "the name is reserved (hull, base_link, odom, road_wheel_*)");
    c.require(p.position.allFinite(), key, "non-finite position");
    // Rigid with the hull: inside its envelope, with 1 m to spare (masts, bumpers).
    const Vector3& x = p.position;
    c.require(std::abs(x.x()) <= 0.5 * d.hull.length + 1.0 &&
                  std::abs(x.y()) <= 0.5 * d.hull.width + 1.0 && x.z() >= -1.0 &&
                  x.z() <= d.hull.height + 1.0,
              key,
              "the point lies more than 1 m outside the hull (" + brief(d.hull.length) + " x " +
                  brief(d.hull.width) + " x " + brief(d.hull.height) + " m)");
  }
}

namespace {

/// A value {value: name, source: ...} that must be one of `choices`; `what` names it in the
/// error: "unknown damping model 'viscous' (modal or rayleigh)".
template <typename E>
E readChoice(const io::YamlValue& entry, const std::string& what,
             std::initializer_list<std::pair<const char*, E>> choices,
             std::map<std::string, std::string>& sources) {
  const io::YamlValue v = quantity(entry, nullptr, sources);
  const std::string name = v.asString();
  std::string names;
  for (const auto& [choice, value] : choices) {
    if (name == choice)
      return value;
    names += (names.empty() ? "" : " or ") + std::string(choice);
  }
  v.fail("unknown " + what + " '" + name + "' (" + names + ")");
}

// Every key path of the document with the line of its key (maps only: a list's elements have no
// key).
void collectKeyLines(const io::YamlValue& node, const std::string& prefix,
                     std::map<std::string, int>* lines) {
  if (!node.isMap())
    return;
  for (const auto& [key, value] : node.entries()) {
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    if (value.entryLine() > 0)
      (*lines)[path] = value.entryLine();
    collectKeyLines(value, path, lines);
  }
}

/// Refuses, as a whole, another of the package's files, or one that has none of a description's
/// sections (its first key would be "unknown", as if misspelt).
void expectDescription(const io::YamlValue& root) {
  io::expectNotOtherYamlFile(root, io::YamlFileKind::VehicleDescription);
  std::string given;
  if (root.isMap())
    for (const auto& [key, value] : root.entries()) {
      for (const char* s : kSections)
        if (key == s)
          return;
      given += (given.empty() ? "" : ", ") + key;
    }
  std::string sections;
  for (const char* s : kSections)
    sections += (sections.empty() ? "" : ", ") + std::string(s);
  const std::string expected = "a vehicle description has the sections " + sections +
                               " (e.g. config/vehicles/paper_vehicle.yaml)";
  if (!root.isMap())
    throw InputError(root.file() + ": not a vehicle description: its top level is not a map of " +
                     "sections; " + expected);
  throw InputError(root.file() + ": not a vehicle description: none of its top-level keys (" +
                   (given.empty() ? std::string("none") : given) + ") is a section; " + expected);
}

VehicleDescription fromYaml(const io::YamlValue& root) {
  const std::string& file = root.file();
  expectDescription(root);
  std::set<std::string> top = {"name", "named_points"};
  for (const char* s : kSections)
    top.insert(s);
  expectKeys(root, top);

  VehicleDescription d;
  d.sources.clear();
  d.origin = file;
  d.name = root["name"].asString();
  if (d.name.empty())
    root["name"].fail("name must not be empty");
  std::vector<Field> fields = fieldsOf(d);
  for (const char* section_name : kSections) {
    const io::YamlValue section = root[section_name];
    std::set<std::string> keys;
    for (const Field& f : fields)
      if (std::string(f.section) == section_name)
        keys.insert(f.key);
    const bool damping = std::string(section_name) == "damping";
    const bool ties = std::string(section_name) == "ties";
    const bool suspension = std::string(section_name) == "suspension";
    const bool track = std::string(section_name) == "track_assembly";
    if (damping)
      keys.insert("model");
    if (ties)
      keys.insert("road_input_station");
    if (suspension)
      keys.insert(kGuideStiffnessKey);
    if (track)
      keys.insert(kStaticTensionKey);
    expectKeys(section, keys);
    for (const Field& f : fields)
      if (std::string(f.section) == section_name)
        readField(section, f, d.sources);
    // Optional (descriptions written before it keep their meaning and their hash).
    if (suspension && section.has(kGuideStiffnessKey)) {
      double value = 0.0;
      readField(section,
                Field{"suspension", kGuideStiffnessKey, "N/m", Kind::Real, Range::Positive, &value},
                d.sources);
      d.suspension.guide_stiffness = value;
    }
    if (track && section.has(kStaticTensionKey)) {
      double value = 0.0;
      readField(
          section,
          Field{"track_assembly", kStaticTensionKey, "N", Kind::Real, Range::NonNegative, &value},
          d.sources);
      d.track_assembly.static_tension = value;
    }
    if (damping)
      d.damping.model = readChoice<DampingModel>(
          section["model"], "damping model",
          {{"modal", DampingModel::Modal}, {"rayleigh", DampingModel::Rayleigh}}, d.sources);
    if (ties)
      d.ties.road_input_station = readChoice<RoadInputStation>(
          section["road_input_station"], "road input station",
          {{"pad_centre", RoadInputStation::PadCentre}, {"sole", RoadInputStation::Sole}},
          d.sources);
  }
  const io::YamlValue points = root["named_points"];
  d.named_points.clear();
  for (const auto& [name, entry] : points.entries()) {
    const io::YamlValue v = quantity(entry, "m", d.sources);
    d.named_points.push_back(NamedPoint{name, v.asVector3()});
  }
  collectKeyLines(root, "", &d.key_lines);
  try {
    validateDescription(d, file);
  } catch (const InputError& e) {
    throw InputError(withKeyLine(d, e.what()));
  }
  return d;
}

}  // namespace

// The consistency checks and the model builder's geometric checks run on the loaded values,
// where the file's lines are gone; their messages start "<file>: <key path>: " like the
// loader's, so the key's line is looked up and appended as the loader does ("(line N)"); a check
// of two keys names them "<key> / <key>" and gets both lines ("(lines N, M)"). A path that is
// not a key of the document leaves the message as it is.
std::string withKeyLine(const VehicleDescription& d, const std::string& message) {
  const std::string prefix = d.origin + ": ";
  if (message.compare(0, prefix.size(), prefix) != 0 || message.find("(line ") != std::string::npos)
    return message;
  const std::size_t end = message.find(": ", prefix.size());
  if (end == std::string::npos)
    return message;
  const std::string path = message.substr(prefix.size(), end - prefix.size());
  std::vector<int> lines;
  for (std::size_t from = 0;;) {
    const std::size_t to = path.find(" / ", from);
    const auto it = d.key_lines.find(path.substr(from, to - from));
    if (it == d.key_lines.end())
      return message;
    lines.push_back(it->second);
    if (to == std::string::npos)
      break;
    from = to + 3;
  }
  if (lines.size() == 1)
    return message + " (line " + std::to_string(lines[0]) + ")";
  std::string text = " (lines ";
  for (std::size_t i = 0; i < lines.size(); ++i)
    text += (i ? ", " : "") + std::to_string(lines[i]);
  return message + text + ")";
}

VehicleDescription parseVehicleDescription(const std::string& text, const std::string& file) {
  return fromYaml(io::YamlValue::parse(text, file));
}

VehicleDescription loadVehicleDescription(const std::string& path) {
  return fromYaml(io::YamlValue::loadFile(path));
}

std::string canonicalDescription(const VehicleDescription& d) {
  VehicleDescription copy = d;
  std::ostringstream out;
  out << "name=" << d.name << "\n";
  for (const Field& f : fieldsOf(copy)) {
    out << f.path() << "=";
    switch (f.kind) {
      case Kind::Real:
      case Kind::Angle:
        out << format(*static_cast<double*>(f.target));
        break;
      case Kind::Integer:
        out << *static_cast<int*>(f.target);
        break;
      case Kind::RealList:
        for (double x : *static_cast<std::vector<double>*>(f.target))
          out << format(x) << ",";
        break;
      case Kind::IntegerList:
        for (int x : *static_cast<std::vector<int>*>(f.target))
          out << x << ",";
        break;
    }
    out << "\n";
  }
  // Only when given: a description without it hashes as before the key existed.
  if (d.suspension.guide_stiffness)
    out << "suspension." << kGuideStiffnessKey << "=" << format(*d.suspension.guide_stiffness)
        << "\n";
  if (d.track_assembly.static_tension)
    out << "track_assembly." << kStaticTensionKey << "=" << format(*d.track_assembly.static_tension)
        << "\n";
  out << "damping.model=" << dampingModelName(d.damping.model) << "\n";
  out << "ties.road_input_station=" << roadInputStationName(d.ties.road_input_station) << "\n";
  for (const NamedPoint& p : d.named_points)
    out << "named_points." << p.name << "=" << format(p.position.x()) << ","
        << format(p.position.y()) << "," << format(p.position.z()) << "\n";
  return out.str();
}

std::uint64_t descriptionHash(const VehicleDescription& d) {
  return io::fnv1a(canonicalDescription(d));
}

std::string descriptionHashHex(const VehicleDescription& d) {
  char buffer[17];
  std::snprintf(buffer, sizeof(buffer), "%016llx",
                static_cast<unsigned long long>(descriptionHash(d)));
  return buffer;
}

bool frontDrive(const VehicleDescription& d) {
  return d.sprocket.centre_x > 0.0;
}

double wheelCentreZ(const VehicleDescription& d) {
  return d.track_assembly.upper_surface_height + d.road_wheel.radius;
}

std::vector<std::string> descriptionWarnings(const VehicleDescription& d) {
  std::vector<std::string> warnings;
  const auto& damping = d.damping;
  const bool proportional = damping.model == DampingModel::Modal
                                ? damping.modal_ratio > 0.0
                                : damping.rayleigh_alpha > 0.0 || damping.rayleigh_beta > 0.0;
  const bool dampers = !damping.damped_stations.empty() && d.suspension.arm_damping > 0.0;
  if (!proportional && !dampers)
    warnings.push_back(
        std::string(damping.model == DampingModel::Modal ? "damping.modal_ratio"
                                                         : "damping.rayleigh_beta") +
        ": the vehicle has no damping at all: FRF peaks are unbounded at the resonances and "
        "free vibrations never decay (" +
        (damping.model == DampingModel::Modal
             ? std::string("give damping.modal_ratio, e.g. the bundled vehicle's 0.05")
             : std::string("give damping.rayleigh_alpha or damping.rayleigh_beta")) +
        ", or arm dampers: suspension.arm_damping > 0 on some damping.damped_stations)");
  // A rigid hull on n equal suspensions at x_i (sum x_i = 0) loads the one farthest from the
  // CoG, at x_N = -sign(x_G) * half the wheelbase, with m_s g (1/n - |x_G| x_N / sum x_i^2):
  // it unloads beyond |x_G| = sum x_i^2 / (n x_N) (1.04 m on the bundled 7 axles, well inside
  // the wheelbase), and with the wheel's own weight m_u g its ground load goes negative beyond
  // sum x_i^2 / x_N (1/n + m_u / m_s). The bonded linear model carries either on.
  const int axles = d.running_gear.axle_count;
  const double spacing = d.running_gear.axle_spacing;
  const double half_wheelbase = 0.5 * spacing * (axles - 1);
  double sum_x2 = 0.0;
  for (int i = 0; i < axles; ++i)
    sum_x2 += std::pow((i - 0.5 * (axles - 1)) * spacing, 2);
  const double x_g = std::abs(d.hull.cog_x);
  const double unload = half_wheelbase > 0.0 ? sum_x2 / (axles * half_wheelbase) : 0.0;
  if (half_wheelbase > 0.0 && x_g > unload) {
    const double lift = sum_x2 / half_wheelbase * (1.0 / axles + d.road_wheel.mass / d.hull.mass);
    const std::string far_end = d.hull.cog_x > 0 ? "rear" : "front";
    std::string text =
        "hull.cog_x: the centre of gravity (x = " + brief(d.hull.cog_x) + " m) lies ";
    if (x_g > half_wheelbase)
      text += std::string(d.hull.cog_x > 0 ? "ahead of the front" : "behind the rear") +
              " axle (x = " + brief(d.hull.cog_x > 0 ? half_wheelbase : -half_wheelbase) +
              " m), where a real vehicle would tip";
    else
      text += "more than " + brief(unload) + " m (sum x_i^2 / (n x_N)) from the wheelbase centre";
    text += ": a rigid hull on equal suspensions leaves the " + far_end +
            " suspensions negative static loads (their torsion bars pulling the hull down)";
    if (x_g > lift)
      text += ", and beyond " + brief(lift) + " m the " + far_end +
              " road wheels' ground loads too, where the linear model's ground holds down "
              "wheels a real vehicle would lift";
    warnings.push_back(text + " (tvd statics gives the loads)");
  }
  const auto& h = d.hull;
  // The hull hangs on its suspension: its CoG lies above the arm pivots (0.53 m against 1.57 m on
  // the paper vehicle). One below them is almost always measured from another datum (the hull's
  // floor, the wheel axles) instead of the ground.
  const double pivot_z =
      wheelCentreZ(d) + d.suspension.arm_length * std::sin(d.suspension.arm_angle);
  if (h.cog_height < pivot_z)
    warnings.push_back("hull.cog_height: " + brief(h.cog_height) +
                       " m lies below the suspension arm pivots (z = " + brief(pivot_z) +
                       " m above the ground): the hull's mass centre under the points it hangs "
                       "from; a height measured from the hull floor or the axles instead of the "
                       "ground?");
  // A mass or inertia in the wrong unit (tonnes for kg, t*m^2 for kg*m^2) still builds a model:
  // said by what no hull has. No point of a body lies farther from its CoG than the hull box's
  // diagonal, so neither can a radius of gyration; one below 5 % of the smallest hull dimension
  // is a thin plate, not a hull.
  const double unsprung = 2.0 * d.running_gear.axle_count * d.road_wheel.mass;
  if (h.mass < unsprung)
    warnings.push_back("hull.mass: " + brief(h.mass) + " kg is less than the road wheels' " +
                       brief(unsprung) + " kg (" + std::to_string(2 * d.running_gear.axle_count) +
                       " x road_wheel.mass): a mass in tonnes?");
  const double diagonal = std::sqrt(h.length * h.length + h.width * h.width + h.height * h.height);
  const double smallest = std::min({h.length, h.width, h.height});
  const std::pair<double, const char*> inertias[] = {{h.roll_inertia, "hull.roll_inertia"},
                                                     {h.pitch_inertia, "hull.pitch_inertia"},
                                                     {h.yaw_inertia, "hull.yaw_inertia"}};
  for (const auto& [inertia, key] : inertias) {
    const double k = std::sqrt(inertia / h.mass);
    if (k > diagonal || k < 0.05 * smallest)
      warnings.push_back(std::string(key) + ": " + brief(inertia) + " kg*m^2 on the hull's " +
                         brief(h.mass) + " kg is a radius of gyration of " + brief(k) + " m, " +
                         (k > diagonal
                              ? "more than the hull's diagonal " + brief(diagonal)
                              : "less than 5 % of its smallest dimension " + brief(smallest)) +
                         " m: the mass or the inertia in another unit (t, t*m^2)?");
  }
  // The wheels likewise: a wheel's radius of gyration about its axle is at most its radius (a
  // ring), and a value for the wheel with its arm lumped in stays within twice it; one below
  // 5 % of the radius is no wheel either. A 1 kg wheel of 69 kg*m^2 (8.3 m) was taken silently.
  const std::tuple<double, double, double, const char*, const char*> wheels[] = {
      {d.road_wheel.spin_inertia, d.road_wheel.mass, d.road_wheel.radius, "road_wheel.spin_inertia",
       "road_wheel.mass"},
      {d.road_wheel.tilt_inertia, d.road_wheel.mass, d.road_wheel.radius, "road_wheel.tilt_inertia",
       "road_wheel.mass"},
      {d.sprocket.inertia, d.sprocket.mass, d.sprocket.radius, "sprocket.inertia", "sprocket.mass"},
      {d.idler.inertia, d.idler.mass, d.idler.radius, "idler.inertia", "idler.mass"}};
  for (const auto& [inertia, mass, radius, key, mass_key] : wheels) {
    if (!(mass > 0.0) || !(radius > 0.0))
      continue;
    const double k = std::sqrt(inertia / mass);
    if (k > 2.0 * radius || k < 0.05 * radius)
      warnings.push_back(std::string(key) + ": " + brief(inertia) + " kg*m^2 on " + mass_key + " " +
                         brief(mass) + " kg is a radius of gyration of " + brief(k) + " m, " +
                         (k > 2.0 * radius ? "more than twice" : "less than 5 % of") +
                         " the wheel's radius " + brief(radius) +
                         " m: the mass or the inertia in another unit (t, t*m^2)?");
  }
  // The tensioner's pre-load against the vehicle's weight: beyond half of it, a value meant in
  // another unit rather than a track. The model stays linear either way, but far beyond the
  // weight the hull's share of the pre-stress outweighs its suspension (an unstable pitch).
  if (d.track_assembly.static_tension) {
    const double weight =
        kStandardGravity *
        (h.mass + unsprung + 2.0 * d.track_assembly.count * d.track_assembly.mass +
         2.0 * (d.sprocket.mass + d.idler.mass) +
         2.0 * static_cast<double>(d.return_rollers.x.size()) * d.return_rollers.mass);
    if (*d.track_assembly.static_tension > 0.5 * weight)
      warnings.push_back(
          "track_assembly.static_tension: " + brief(*d.track_assembly.static_tension) +
          " N in each chain is more than half the vehicle's weight (" + brief(weight) +
          " N): a value in another unit?");
  }
  return warnings;
}

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics

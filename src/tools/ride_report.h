// What both methods of `tvd ride` report alike: the points rated and the limit speeds found.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "reduction_options.h"
#include "ride_options.h"
#include "tracked_vehicle_dynamics/dynamics/limit_crossing.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/terrain/terrain.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// The points the user asked for (`specs`: each --points given, comma-separated), or "hull" and
/// every named point when --points was not `given`. Throws InputError for a point the model
/// lacks, one listed twice or an empty name (an empty spec included).
std::vector<std::string> choosePoints(const std::vector<std::string>& specs, bool given,
                                      const std::vector<std::string>& named);

/// What both methods rate: the points (checked against the description before any work) and the
/// reduced model, loaded or reduced as the options say. A `track` (the time-domain method's) is
/// checked first for a --lateral-offset that drives beside it (refuseDrivingBesideTerrain).
/// Warnings of the description are added to `warnings`.
struct RideModel {
  std::vector<std::string> points;
  ReducedModelSource reduced;
  std::string vehicle_name;  ///< the description's name (JSON "vehicle", as every command)
};
RideModel loadRideModel(const RideOptions& opt, const terrain::Terrain* track,
                        std::vector<std::string>* warnings);

/// A table's columns as MAT variables: when `file` (given to --`option`) is a .mat file, throws
/// InputError for a column name longer than a MAT variable may be (63 characters; a point name
/// of up to 40, the description's limit, with a long suffix can be), before any run.
void checkMatColumns(const std::string& option, const std::string& file,
                     const std::vector<std::string>& columns);

/// One limit to search: the metric of point-run `value(run)` and its threshold.
template <typename Run>
struct RideCriterion {
  std::function<double(const Run&)> value;
  double limit;
};

/// The runs of a sweep, one per speed [km/h], made on demand by `make` and kept (a speed that
/// several points and limits ask for is evaluated once), and the lowest speed at which each
/// criterion is reached over all of them (lowestCrossing), the searches repeated until a round
/// adds no run: the bisections of one criterion add runs the others see.
template <typename Run>
class RideRuns {
 public:
  explicit RideRuns(std::function<Run(double)> make) : make_(std::move(make)) {}

  const Run& at(double speed_kmh) {
    auto found = runs_.find(speed_kmh);
    if (found != runs_.end())
      return found->second;
    return runs_.emplace(speed_kmh, make_(speed_kmh)).first->second;
  }
  /// Evaluates every speed of the sweep and marks its runs (Run::in_sweep).
  void sweep(const std::vector<double>& speeds) {
    for (double v : speeds)
      at(v);
    for (double v : speeds)
      runs_.at(v).in_sweep = true;
  }
  const std::map<double, Run>& all() const { return runs_; }

  std::vector<dynamics::LimitCrossing> limits(const std::vector<RideCriterion<Run>>& criteria,
                                              double tolerance) {
    auto known = [this] {
      std::vector<double> v;
      for (const auto& entry : runs_)
        v.push_back(entry.first);
      return v;
    };
    std::vector<dynamics::LimitCrossing> found(criteria.size());
    for (std::size_t before = 0; before != runs_.size();) {
      before = runs_.size();
      for (std::size_t i = 0; i < criteria.size(); ++i) {
        const int so_far = found[i].refinements;
        found[i] = lowestCrossing(
            known, [&](double v) { return criteria[i].value(at(v)); }, criteria[i].limit,
            tolerance);
        found[i].refinements += so_far;  // summed over the rounds
      }
    }
    return found;
  }

 private:
  std::function<Run(double)> make_;
  std::map<double, Run> runs_;
};

/// The lowest speed at which `metric` reaches `limit` over EVERY speed evaluated so far, not only
/// the sweep's: the bisections of other points and limits add runs, and one of them may already
/// lie above the limit below the sweep's first bracket. `known_speeds()` lists the evaluated
/// speeds in increasing order; `metric(v)` evaluates (or reads the run at) speed v, adding it to
/// the known ones. dynamics::findLimitCrossing runs over the known speeds until its bisection
/// adds none (at most twice: the second pass finds the first pass's final bracket again, no wider
/// than the tolerance); the refinements of both passes are counted.
dynamics::LimitCrossing lowestCrossing(const std::function<std::vector<double>()>& known_speeds,
                                       const std::function<double(double)>& metric, double limit,
                                       double tolerance);

/// {limit, unit, status, speed_kmh, bracket_kmh, refinements} of one crossing; speed_kmh is null
/// unless the status is reached (bracket_kmh then holds the lowest, or the highest, speed run).
void writeLimitJson(io::JsonWriter& json, const dynamics::LimitCrossing& c, double limit,
                    const char* unit);

/// "6 W at 14.03 km/h (between 14.00 and 14.06)", "... already at the lowest speed, ...",
/// "... not reached up to ... km/h"; `what` names the limit ("6 W").
std::string describeLimit(const dynamics::LimitCrossing& c, const std::string& what);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics

#include "tracked_vehicle_dynamics/online/road_input_sampler.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace online {

RoadInputSampler::RoadInputSampler(const Vector& stations, const Vector& lateral,
                                   std::vector<bool> needs_rate)
    : stations_(stations), lateral_(lateral), needs_rate_(std::move(needs_rate)) {
  if (lateral_.size() != stations_.size()) {
    throw InputError("road input sampler: " + std::to_string(stations_.size()) +
                     " input stations but " + std::to_string(lateral_.size()) +
                     " lateral positions");
  }
  if (needs_rate_.empty())
    needs_rate_.assign(static_cast<std::size_t>(stations_.size()), true);
  if (static_cast<Eigen::Index>(needs_rate_.size()) != stations_.size()) {
    throw InputError("road input sampler: " + std::to_string(needs_rate_.size()) +
                     " rate flags for " + std::to_string(stations_.size()) + " inputs");
  }
  for (Eigen::Index q = 0; q < stations_.size(); ++q) {
    if (!std::isfinite(stations_(q)) || !std::isfinite(lateral_(q))) {
      throw InputError("road input sampler: position of input " + std::to_string(q) +
                       " is not finite");
    }
  }
  held_.setZero(stations_.size());
  // Groups of contacts at exactly the same station, in station order.
  members_.resize(static_cast<std::size_t>(stations_.size()));
  std::iota(members_.begin(), members_.end(), Eigen::Index{0});
  std::stable_sort(members_.begin(), members_.end(),
                   [&](Eigen::Index a, Eigen::Index b) { return stations_(a) < stations_(b); });
  for (std::size_t k = 0; k < members_.size(); ++k) {
    if (k == 0 || stations_(members_[k]) != stations_(members_[k - 1]))
      group_begin_.push_back(k);
  }
  group_begin_.push_back(members_.size());
  lookups_.resize(group_begin_.size() - 1);
  cells_.resize(members_.size());
  group_rate_.assign(lookups_.size(), 0);
  for (std::size_t g = 0; g < lookups_.size(); ++g) {
    for (std::size_t k = group_begin_[g]; k < group_begin_[g + 1]; ++k)
      if (needs_rate_[static_cast<std::size_t>(members_[k])])
        group_rate_[g] = 1;
  }
  if (stations_.size() > 0) {
    rearmost_ = stations_.minCoeff();
    frontmost_ = stations_.maxCoeff();
  }
}

int RoadInputSampler::sample(const terrain::TerrainBuffer& buffer, double station, double speed,
                             double lateral_offset, Vector* w) {
  const Eigen::Index n = stations_.size();
  if (&buffer != lookup_buffer_ || buffer.revision() != lookup_revision_) {
    // Grids may have been freed (and their addresses reused): forget every one.
    for (Lookup& lookup : lookups_)
      lookup.grid = nullptr;
    for (ContactCell& cell : cells_)
      cell.grid = nullptr;
    lookup_buffer_ = &buffer;
    lookup_revision_ = buffer.revision();
  }
  // Contiguous coverage, computed once per call: inside it height() cannot throw.
  const double from = buffer.coveredFrom();
  const double until = buffer.coveredUntil();
  int uncovered = 0;
  for (std::size_t g = 0; g + 1 < group_begin_.size(); ++g) {
    const std::size_t first = group_begin_[g], last = group_begin_[g + 1];
    const double x = station + stations_(members_[first]);
    if (!((x >= from && x <= until) || buffer.covers(x))) {
      for (std::size_t k = first; k < last; ++k) {
        const Eigen::Index q = members_[k];
        (*w)(q) = held_(q);
        (*w)(n + q) = 0.0;
      }
      uncovered += static_cast<int>(last - first);
      continue;
    }
    Lookup& lookup = lookups_[g];
    // A group that needs u' leaves the run at its last station: the cell ahead is not flat.
    const bool in_flat_run =
        x >= lookup.flat_from && (group_rate_[g] ? x < lookup.flat_until : x <= lookup.flat_until);
    if (lookup.grid != nullptr && x >= lookup.from && x <= lookup.until && in_flat_run &&
        lateral_offset == lookup.offset) {
      // Still on the same flat run of the same grid: the heights held are the terrain's, and
      // the cell ahead is flat (u' = 0).
      for (std::size_t k = first; k < last; ++k) {
        const Eigen::Index q = members_[k];
        (*w)(q) = held_(q);
        (*w)(n + q) = 0.0;
      }
      continue;
    }
    if (lookup.grid == nullptr || !(x >= lookup.from && x <= lookup.until))
      lookup.grid = buffer.gridFor(x, &lookup.from, &lookup.until);  // nullptr: a bridged gap
    terrain::Terrain::StationWeight weight;
    lookup.flat_from = 1.0;
    lookup.flat_until = 0.0;
    if (lookup.grid != nullptr) {
      weight = lookup.grid->stationWeightOf(x);
      // A run of one sample is no run: the heights held were sampled inside its sloped cell,
      // not on its station, which a contact moved back onto it would be given.
      if (weight.edge == 0 &&
          lookup.grid->flatRunEnd(weight.cell) > lookup.grid->stations()(weight.cell)) {
        lookup.flat_from = lookup.grid->stations()(weight.cell);
        lookup.flat_until = lookup.grid->flatRunEnd(weight.cell);
        lookup.offset = lateral_offset;
      }
    }
    for (std::size_t k = first; k < last; ++k) {
      const Eigen::Index q = members_[k];
      const double y = lateral_(q) + lateral_offset;
      ContactCell& cell = cells_[k];
      const bool on_grid = lookup.grid != nullptr && !std::isnan(y);
      if (!on_grid) {
        held_(q) = buffer.height(x, y);
      } else {
        if (cell.grid != lookup.grid || cell.y != y) {
          cell.grid = lookup.grid;
          cell.y = y;
          cell.cell = lookup.grid->lateralCellOf(y);
        }
        held_(q) = lookup.grid->height(weight, cell.cell);
      }
      (*w)(q) = held_(q);
      double rate_q = 0.0;
      if (needs_rate_[static_cast<std::size_t>(q)] && speed != 0.0) {
        // Inside a grid its cell's slope, as Terrain::slope() gives it; on a grid's last
        // station (where the next patch may go on) or in a bridged gap, rate().
        rate_q = on_grid && weight.edge == 0 ? speed * lookup.grid->slope(weight, cell.cell)
                                             : rate(buffer, x, y, held_(q), speed, from, until);
      }
      (*w)(n + q) = rate_q;
    }
  }
  return uncovered;
}

double RoadInputSampler::rate(const terrain::TerrainBuffer& buffer, double x, double y,
                              double height, double speed, double from, double until) const {
  // The cell ahead, as inside a grid: the cell slope of the grid that answers just ahead (the
  // next patch, or an older one a newer patch ends inside: its heights may step from ours); in a
  // bridged gap the bridge's, linear from `height`. Nothing ahead: 0, as Terrain::slope() at a
  // terrain's end.
  const double xb = x + kSlopeStep;
  if (!((xb >= from && xb <= until) || buffer.covers(xb)))
    return 0.0;
  double grid_from = 0.0, grid_until = 0.0;
  if (const terrain::Terrain* grid = buffer.gridFor(xb, &grid_from, &grid_until))
    return speed * grid->slope(xb, y);
  return speed * (buffer.height(xb, y) - height) / (xb - x);
}

void RoadInputSampler::setHeld(const Vector& heights) {
  if (heights.size() != held_.size()) {
    throw InputError("road input sampler: " + std::to_string(heights.size()) +
                     " held heights for " + std::to_string(held_.size()) + " inputs");
  }
  held_ = heights;
}

}  // namespace online
}  // namespace tracked_vehicle_dynamics

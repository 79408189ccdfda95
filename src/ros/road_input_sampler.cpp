#include "tracked_vehicle_dynamics/ros/road_input_sampler.h"

#include <cmath>
#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {

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
  lookups_.resize(static_cast<std::size_t>(stations_.size()));
  if (stations_.size() > 0) {
    rearmost_ = stations_.minCoeff();
    frontmost_ = stations_.maxCoeff();
  }
}

int RoadInputSampler::sample(const terrain::TerrainBuffer& buffer, double station, double speed,
                             double lateral_offset, Vector* w) {
  const Eigen::Index n = stations_.size();
  if (&buffer != lookup_buffer_ || buffer.revision() != lookup_revision_) {
    for (Lookup& lookup : lookups_) lookup.grid = nullptr;
    lookup_buffer_ = &buffer;
    lookup_revision_ = buffer.revision();
  }
  // Contiguous coverage, computed once per call: inside it height() cannot throw.
  const double from = buffer.coveredFrom();
  const double until = buffer.coveredUntil();
  auto covered = [&](double x) { return (x >= from && x <= until) || buffer.covers(x); };
  int uncovered = 0;
  for (Eigen::Index q = 0; q < n; ++q) {
    const double x = station + stations_(q);
    const double y = lateral_(q) + lateral_offset;
    double rate = 0.0;
    if (covered(x)) {
      held_(q) = height(buffer, q, x, y);
      if (needs_rate_[static_cast<std::size_t>(q)] && speed != 0.0) {
        const double xa = x - kSlopeStep, xb = x + kSlopeStep;
        const bool a = covered(xa), b = covered(xb);
        if (a && b) {
          rate = speed * (buffer.height(xb, y) - buffer.height(xa, y)) / (2.0 * kSlopeStep);
        } else if (b) {
          rate = speed * (buffer.height(xb, y) - held_(q)) / kSlopeStep;
        } else if (a) {
          rate = speed * (held_(q) - buffer.height(xa, y)) / kSlopeStep;
        }
      }
    } else {
      ++uncovered;
    }
    (*w)(q) = held_(q);
    (*w)(n + q) = rate;
  }
  return uncovered;
}

double RoadInputSampler::height(const terrain::TerrainBuffer& buffer, Eigen::Index q, double x,
                                double y) {
  Lookup& lookup = lookups_[static_cast<std::size_t>(q)];
  if (lookup.grid == nullptr || !(x >= lookup.from && x <= lookup.until) || y != lookup.y) {
    lookup.grid = std::isnan(y) ? nullptr : buffer.gridFor(x, &lookup.from, &lookup.until);
    if (lookup.grid == nullptr) return buffer.height(x, y);  // bridged gap (or NaN)
    lookup.y = y;
    lookup.cell = lookup.grid->lateralCellOf(y);
  }
  return lookup.grid->height(x, lookup.cell);
}

void RoadInputSampler::setHeld(const Vector& heights) {
  if (heights.size() != held_.size()) {
    throw InputError("road input sampler: " + std::to_string(heights.size()) +
                     " held heights for " + std::to_string(held_.size()) + " inputs");
  }
  held_ = heights;
}

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics

#include "tracked_vehicle_dynamics/terrain/terrain_buffer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace terrain {
namespace {

// Relative slack on lengths compared in the searches (stations are sums of rounded products).
constexpr double kSlack = 1e-9;

// The longest gap bridged between patches of these spacings [m]: kBridgeFactor times the larger,
// with the slack. The one rule behind bridge(), the searches and dropsPatchEnding().
double bridgeableGap(double spacing) {
  return TerrainBuffer::kBridgeFactor * spacing * (1.0 + kSlack);
}

std::size_t gridBytes(const Terrain& grid) {
  return TerrainBuffer::patchBytes(static_cast<std::size_t>(grid.lateral().size()),
                                   static_cast<std::size_t>(grid.stations().size()));
}

// A memory size for the messages: MB (1e6 bytes, as ~terrain_max_memory), kB or bytes, to one
// decimal.
std::string memoryText(std::size_t bytes) {
  const double b = static_cast<double>(bytes);
  if (b >= 1e6)
    return brief(std::round(b / 1e5) / 10.0) + " MB";
  if (b >= 1e3)
    return brief(std::round(b / 1e2) / 10.0) + " kB";
  return std::to_string(bytes) + " bytes";
}

}  // namespace

std::size_t TerrainBuffer::patchBytes(std::size_t n_lines, std::size_t n_samples) {
  // Saturating: a count no buffer can hold compares above any limit instead of wrapping.
  constexpr std::size_t kMax = std::numeric_limits<std::size_t>::max();
  constexpr std::size_t kDouble = sizeof(double);
  if (n_lines != 0 && n_samples > (kMax / kDouble - n_lines) / (n_lines + 1))
    return kMax;
  return kDouble * (n_samples * (n_lines + 1) + n_lines);
}

void TerrainBuffer::addPatch(double start_station, double spacing, const Vector& lateral,
                             const Matrix& heights) {
  const std::string where = "terrain patch at station " + brief(start_station) + " m: ";
  if (!std::isfinite(start_station))
    throw InputError(where + "start station is not finite");
  if (!std::isfinite(spacing) || spacing <= 0.0) {
    throw InputError(where + "spacing " + brief(spacing) + " m must be positive and finite");
  }
  if (lateral.size() == 0)
    throw InputError(where + "no lateral positions");
  if (heights.rows() != lateral.size()) {
    throw InputError(where + "heights have " + std::to_string(heights.rows()) +
                     " lines but there are " + std::to_string(lateral.size()) +
                     " lateral positions");
  }
  if (heights.cols() == 0)
    throw InputError(where + "no samples");
  // The stations start + k spacing must stay finite and distinct in double precision: a spacing
  // of 1e308, or of 1e-300 at 1e6 m, passes the checks above and breaks the grid.
  const double last_station = start_station + spacing * static_cast<double>(heights.cols() - 1);
  if (!std::isfinite(last_station) || !(start_station + spacing > start_station) ||
      !(last_station - spacing < last_station)) {
    throw InputError(where + "spacing " + brief(spacing) + " m over " +
                     std::to_string(heights.cols()) +
                     " samples gives stations that are not finite and distinct (last " +
                     brief(last_station) + " m): too large or too small for the start station");
  }
  for (Eigen::Index j = 0; j < lateral.size(); ++j) {
    if (!std::isfinite(lateral(j))) {
      throw InputError(where + "lateral position " + std::to_string(j) + " is not finite");
    }
    if (j > 0 && lateral(j) <= lateral(j - 1)) {
      throw InputError(where + "lateral position " + std::to_string(j) + " (" + brief(lateral(j)) +
                       " m) is not greater than the previous one (" + brief(lateral(j - 1)) +
                       " m)");
    }
  }
  for (Eigen::Index j = 0; j < heights.rows(); ++j) {
    for (Eigen::Index k = 0; k < heights.cols(); ++k) {
      if (!std::isfinite(heights(j, k))) {
        throw InputError(where + "height at line " + std::to_string(j) + ", sample " +
                         std::to_string(k) + " is not finite");
      }
    }
  }

  // The memory limit, judged before anything is copied: what stays of the stored patches (the
  // ones lying entirely under this one are freed below) and this one.
  const std::size_t bytes = patchBytes(static_cast<std::size_t>(heights.rows()),
                                       static_cast<std::size_t>(heights.cols()));
  if (memory_limit_ != std::numeric_limits<std::size_t>::max()) {
    std::size_t freed = 0;
    for (auto it = patches_.lower_bound(start_station);
         it != patches_.end() && it->first <= last_station; ++it) {
      if (it->second.end() <= last_station)
        freed += gridBytes(it->second.grid);
    }
    const std::size_t kept = stored_bytes_ - freed;
    if (bytes > memory_limit_ || kept > memory_limit_ - bytes) {
      const std::string stored = kept == 0 ? std::string()
                                           : " with the " + memoryText(kept) +
                                                 " stored (stations " + brief(coveredFrom()) +
                                                 " .. " + brief(furthestEnd()) + " m)";
      throw InputError(where + memoryText(bytes) + stored + " exceed" + (kept == 0 ? "s" : "") +
                       " the terrain buffer's limit of " + memoryText(memory_limit_) +
                       ": terrain sent far ahead of the vehicle, or stations that are not "
                       "along its path?");
    }
  }

  Vector stations(heights.cols());
  for (Eigen::Index k = 0; k < stations.size(); ++k) {
    stations(k) = start_station + static_cast<double>(k) * spacing;
  }
  // Named by its place: the grid's own checks (heights within +-10 km) then read "terrain
  // 'patch at x = 12 m': ...".
  Patch patch{Terrain(stations, lateral, heights, "patch at x = " + brief(start_station) + " m"),
              spacing, next_sequence_++};
  const double end = patch.end();
  // Older patches lying entirely under the new one can never win a query again.
  for (auto it = patches_.lower_bound(start_station); it != patches_.end() && it->first <= end;) {
    if (it->second.end() <= end) {
      stored_bytes_ -= gridBytes(it->second.grid);
      it = patches_.erase(it);
    } else {
      ++it;
    }
  }
  patches_.emplace(start_station, std::move(patch));
  stored_bytes_ += bytes;
  updateExtents();
}

const TerrainBuffer::Patch* TerrainBuffer::containing(double x) const {
  const Patch* best = nullptr;
  const double reach = max_length_ * (1.0 + kSlack);
  for (auto it = patches_.upper_bound(x); it != patches_.begin();) {
    --it;
    if (it->first < x - reach)
      break;
    const Patch& patch = it->second;
    if (patch.end() >= x && (best == nullptr || patch.sequence > best->sequence))
      best = &patch;
  }
  return best;
}

bool TerrainBuffer::bridge(double x, const Patch** left, const Patch** right) const {
  // The heights across the gap come from the newest patch at each side; whether the gap is
  // bridged is judged on the coarsest spacing of all the patches ending (starting) there, the
  // rule updateExtents() follows, so that x within coveredUntil() always has a height.
  *left = nullptr;
  *right = nullptr;
  double left_spacing = 0.0, right_spacing = 0.0;
  const double gap_limit = bridgeableGap(max_spacing_);
  for (auto it = patches_.upper_bound(x); it != patches_.begin();) {
    --it;
    if (it->first < x - max_length_ - gap_limit)
      break;
    const Patch& patch = it->second;
    if (patch.end() >= x || patch.end() < x - gap_limit)
      continue;
    if (*left == nullptr || patch.end() > (*left)->end()) {
      *left = &patch;
      left_spacing = patch.spacing;
    } else if (patch.end() == (*left)->end()) {
      left_spacing = std::max(left_spacing, patch.spacing);
      if (patch.sequence > (*left)->sequence)
        *left = &patch;
    }
  }
  const auto next = patches_.upper_bound(x);
  if (*left == nullptr || next == patches_.end())
    return false;
  for (auto it = next; it != patches_.end() && it->first == next->first; ++it) {
    right_spacing = std::max(right_spacing, it->second.spacing);
    if (*right == nullptr || it->second.sequence > (*right)->sequence)
      *right = &it->second;
  }
  const double gap = (*right)->grid.startStation() - (*left)->end();
  return gap <= bridgeableGap(std::max(left_spacing, right_spacing));
}

const Terrain* TerrainBuffer::gridFor(double x, double* from, double* until) const {
  const Patch* winner = std::isnan(x) ? nullptr : containing(x);
  if (winner == nullptr)
    return nullptr;
  double lo = winner->grid.startStation();
  double hi = winner->end();
  // Newer patches overlapping the winner's range take over where they lie; none holds x (the
  // winner is the newest that does), so each one trims the interval on one side of x.
  const double reach = max_length_ * (1.0 + kSlack);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (auto it = patches_.lower_bound(lo - reach); it != patches_.end() && it->first <= hi; ++it) {
    const Patch& patch = it->second;
    if (patch.sequence <= winner->sequence || patch.end() < lo)
      continue;
    if (patch.end() < x) {
      lo = std::max(lo, std::nextafter(patch.end(), kInf));
    } else if (patch.grid.startStation() > x) {
      hi = std::min(hi, std::nextafter(patch.grid.startStation(), -kInf));
    }
  }
  *from = lo;
  *until = hi;
  return &winner->grid;
}

bool TerrainBuffer::covers(double x) const {
  if (std::isnan(x))
    return false;
  const Patch* left = nullptr;
  const Patch* right = nullptr;
  return containing(x) != nullptr || bridge(x, &left, &right);
}

double TerrainBuffer::height(double x, double y) const {
  if (const Patch* patch = std::isnan(x) ? nullptr : containing(x))
    return patch->grid.height(x, y);
  const Patch* left = nullptr;
  const Patch* right = nullptr;
  if (!std::isnan(x) && bridge(x, &left, &right)) {
    // Linear in x across the gap, between the last sample of one patch and the first of the next.
    const double x0 = left->end();
    const double x1 = right->grid.startStation();
    const double w = (x - x0) / (x1 - x0);
    return (1.0 - w) * left->grid.height(x0, y) + w * right->grid.height(x1, y);
  }
  throw InputError("terrain buffer: station x = " + brief(x) + " m is not covered (" +
                   (empty() ? std::string("no terrain received")
                            : "coverage starts at " + brief(coveredFrom()) +
                                  " m, contiguous until " + brief(coveredUntil()) + " m") +
                   ")");
}

double TerrainBuffer::heightBefore(double x, double y) const {
  if (std::isnan(x))
    return std::numeric_limits<double>::quiet_NaN();
  if (covers(x))
    return height(x, y);
  const Patch* last = nullptr;
  for (auto it = patches_.begin(); it != patches_.end() && it->first <= x; ++it) {
    const Patch& patch = it->second;
    if (last == nullptr || patch.end() > last->end() ||
        (patch.end() == last->end() && patch.sequence > last->sequence))
      last = &patch;
  }
  return last == nullptr ? std::numeric_limits<double>::quiet_NaN()
                         : last->grid.height(last->end(), y);
}

bool TerrainBuffer::dropsPatchEnding(double end, double spacing, double station) {
  return end < station - bridgeableGap(spacing);
}

void TerrainBuffer::dropBehind(double station) {
  if (std::isnan(station))
    return;
  std::vector<Patch> trimmed;
  for (auto it = patches_.begin(); it != patches_.end() && it->first < station;) {
    Patch& patch = it->second;
    if (dropsPatchEnding(patch.end(), patch.spacing, station)) {
      stored_bytes_ -= gridBytes(patch.grid);
      it = patches_.erase(it);
      continue;
    }
    const Vector& x = patch.grid.stations();
    const auto* last_behind = std::upper_bound(x.data(), x.data() + x.size(), station) - 1;
    const Eigen::Index keep_from = std::max<Eigen::Index>(0, last_behind - x.data());
    // Cut only once half the patch lies behind: a cut copies (and checks again) the part kept,
    // which under a vehicle on one long patch was the whole rest of it at every new patch
    // (3 ms per arrival on a 10 km patch, in the tick). Halving bounds the copies of a patch to
    // its own size over its life, and the data kept behind to as much as is ahead.
    if (keep_from == 0 || 2 * keep_from < x.size()) {
      ++it;
      continue;
    }
    const Eigen::Index kept = x.size() - keep_from;
    trimmed.push_back(Patch{Terrain(x.tail(kept), patch.grid.lateral(),
                                    patch.grid.heights().rightCols(kept), patch.grid.name()),
                            patch.spacing, patch.sequence});
    stored_bytes_ -= gridBytes(patch.grid);
    stored_bytes_ += gridBytes(trimmed.back().grid);
    it = patches_.erase(it);
  }
  for (Patch& patch : trimmed) {
    const double start = patch.grid.startStation();
    patches_.emplace(start, std::move(patch));
  }
  updateExtents();
}

double TerrainBuffer::coveredFrom() const {
  return empty() ? std::numeric_limits<double>::infinity() : patches_.begin()->first;
}

double TerrainBuffer::furthestEnd() const {
  double end = -std::numeric_limits<double>::infinity();
  for (const auto& entry : patches_)
    end = std::max(end, entry.second.end());
  return end;
}

void TerrainBuffer::clear() {
  patches_.clear();
  stored_bytes_ = 0;
  updateExtents();
}

void TerrainBuffer::updateExtents() {
  // Unique across all buffers, so a grid remembered from one buffer (or from an earlier buffer
  // at the same address) never passes for another's.
  static std::atomic<std::uint64_t> next_revision{1};
  revision_ = next_revision.fetch_add(1, std::memory_order_relaxed);
  max_length_ = 0.0;
  max_spacing_ = 0.0;
  for (const auto& [start, patch] : patches_) {
    max_length_ = std::max(max_length_, patch.end() - start);
    max_spacing_ = std::max(max_spacing_, patch.spacing);
  }
  // The contiguous reach from the first patch, across bridgeable gaps (read at every step).
  covered_until_ = -std::numeric_limits<double>::infinity();
  if (empty())
    return;
  // As bridge() judges a gap: on the coarsest spacing of the patches ending at the reach and of
  // those starting after the gap (equal starts taken together).
  double reach = patches_.begin()->first;
  double reach_spacing = 0.0;
  for (auto group = patches_.begin(); group != patches_.end();) {
    const double start = group->first;
    const auto group_end = patches_.upper_bound(start);
    double group_spacing = 0.0;
    for (auto it = group; it != group_end; ++it)
      group_spacing = std::max(group_spacing, it->second.spacing);
    if (start > reach + bridgeableGap(std::max(reach_spacing, group_spacing)))
      break;
    for (auto it = group; it != group_end; ++it) {
      const Patch& patch = it->second;
      if (patch.end() > reach) {
        reach = patch.end();
        reach_spacing = patch.spacing;
      } else if (patch.end() == reach) {
        reach_spacing = std::max(reach_spacing, patch.spacing);
      }
    }
    group = group_end;
  }
  covered_until_ = reach;
}

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics

// A station-indexed store of terrain patches as they arrive online (the ROS node feeds it from
// TerrainProfile messages; the class itself is ROS-free).
//
// A patch is a regular grid: stations start + k spacing (k = 0..n-1) [m] along the path,
// lateral positions y_j [m] (y left), heights [n_y x n]. Queries interpolate bilinearly inside
// the newest patch that covers the station (overlapping patches: newer wins). Consecutive
// patches leave a gap of one spacing between the last sample of one and the first of the next;
// a gap up to kBridgeFactor times the larger spacing is bridged by linear interpolation in x, so
// contiguous patches behave as one grid. Laterally, positions outside a patch's lines take the
// nearest line (clamp), as in Terrain.
//
// Not thread-safe: the owner serialises access.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>

#include "tracked_vehicle_dynamics/terrain/terrain.h"

namespace tracked_vehicle_dynamics {
namespace terrain {

class TerrainBuffer {
 public:
  /// Largest gap between patches bridged, in spacings.
  static constexpr double kBridgeFactor = 1.5;

  /// Stores a patch; the newest patch wins where patches overlap, and older patches it covers
  /// entirely are freed. start_station [m], spacing [m] > 0, lateral [n_y] strictly increasing
  /// [m], heights [n_y x n_samples] [m], n_samples >= 1. Throws InputError (naming the patch
  /// start and the offending index) for non-finite values, size mismatches, spacing <= 0, and
  /// when the patches stored with it would hold more than memoryLimit(); nothing changes then.
  void addPatch(double start_station, double spacing, const Vector& lateral, const Matrix& heights);

  /// Memory a patch of n_lines x n_samples holds in the buffer [bytes]: its stations, lateral
  /// positions and heights (8 bytes each; the container's own few hundred bytes not counted).
  static std::size_t patchBytes(std::size_t n_lines, std::size_t n_samples);
  /// Largest memory the stored patches may hold together [bytes] (default: no limit). An online
  /// source streaming stations the vehicle never reaches (a map's x instead of the path's)
  /// would otherwise grow the buffer for as long as it runs. Patches already stored stay.
  void setMemoryLimit(std::size_t bytes) { memory_limit_ = bytes; }
  std::size_t memoryLimit() const { return memory_limit_; }
  /// Memory the stored patches hold [bytes], as patchBytes() counts it.
  std::size_t storedBytes() const { return stored_bytes_; }

  /// True when height(x, ·) is defined: x inside a patch or inside a bridged gap.
  bool covers(double x) const;
  /// Height [m] at station x [m], lateral y [m]. Throws InputError when x is not covered.
  double height(double x, double y) const;
  /// The height [m] at lateral y of the terrain a contact reaching station x [m] comes from:
  /// height(x, y) where covered, else the height at the last sample of the patch ending last
  /// before x (the newest of equals), which an uncovered contact holds. NaN when no patch starts
  /// at or before x.
  double heightBefore(double x, double y) const;

  /// The patch grid answering height(x, ·) — its height(x, y) is this buffer's — and the
  /// station interval [*from, *until] around x over which that grid keeps answering, as long as
  /// revision() is unchanged. nullptr (interval unset) when x is in no patch (bridged gap or
  /// not covered: ask height()). For callers sampling the same places at a high rate.
  const Terrain* gridFor(double x, double* from, double* until) const;
  /// Changes with every addPatch(), dropBehind() and clear(), to a value no other buffer has had
  /// (0: never changed, empty): pointers from gridFor() stay valid, and its intervals exact,
  /// while it does not. A copy starts with its original's revision (and its own grids).
  std::uint64_t revision() const { return revision_; }
  /// Frees data behind `station` [m]: patches ending before it are dropped and a patch straddling
  /// it is cut to its samples from the last one at or before `station` once at least half of it
  /// lies behind (a cut copies what it keeps); queries at stations >= station keep their values.
  void dropBehind(double station);
  /// Whether dropBehind(station) frees a patch ending at `end` [m] with `spacing` [m]: it ends
  /// before `station` by more than a bridgeable gap (a nearer one still anchors the bridge).
  static bool dropsPatchEnding(double end, double spacing, double station);
  /// End of the contiguous coverage (bridged gaps included) that starts at coveredFrom() [m];
  /// -infinity when empty.
  double coveredUntil() const { return covered_until_; }
  /// First covered station [m]; +infinity when empty.
  double coveredFrom() const;
  /// Last station of any stored patch [m] (beyond gaps too); -infinity when empty.
  double furthestEnd() const;

  std::size_t patchCount() const { return patches_.size(); }
  bool empty() const { return patches_.empty(); }
  void clear();

 private:
  struct Patch {
    Terrain grid;
    double spacing;
    std::uint64_t sequence;
    double end() const { return grid.endStation(); }
  };
  using PatchMap = std::multimap<double, Patch>;

  /// The newest patch containing x, nullptr if none.
  const Patch* containing(double x) const;
  /// Patches bounding a bridgeable gap around x, false if x is not in one.
  bool bridge(double x, const Patch** left, const Patch** right) const;
  void updateExtents();

  PatchMap patches_;  // keyed by start station
  std::uint64_t next_sequence_ = 0;
  std::uint64_t revision_ = 0;
  double max_length_ = 0.0;   // longest stored patch [m], bounds the backward search
  double max_spacing_ = 0.0;  // largest stored spacing [m]
  double covered_until_ = -std::numeric_limits<double>::infinity();  // coveredUntil()
  std::size_t stored_bytes_ = 0;                                     // storedBytes()
  std::size_t memory_limit_ = std::numeric_limits<std::size_t>::max();
};

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics

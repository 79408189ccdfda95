// The road inputs of a reduced vehicle model sampled from a TerrainBuffer as the vehicle moves.
// ROS-free (the node feeds it; the tests drive it directly).
//
// Contact q sits at x_q, y_q in base_link (SecondOrderSystem::input_stations/input_lateral). With
// the vehicle reference point at station s, speed v and the vehicle centre line at lateral
// position `lateral_offset` on the terrain (y left), the input w = [u; u'] is
//   u_q  = h(s + x_q, y_q + lateral_offset)                                    [m]
//   u'_q = v dh/dx                                                              [m/s]
// with dh/dx the slope of the bilinear cell under the contact, on a station the cell ahead: what
// Terrain::slope() gives on the same grid (offline: RoadExcitation), bit for bit. On a grid's
// last station (the next patch may go on), the cell ahead is that of whatever answers at x + e,
// e = kSlopeStep: another grid's own cell slope (a difference across two grids would turn a step
// between them into a slope of step / e), or in a gap bridged between patches the bridge's,
// (h(x + e) - h(x)) / e. Where nothing covers x + e (the end of coverage) u' = 0, as
// Terrain::slope() is at a terrain's end.
// u' is evaluated only for the inputs flagged (OnlineVehicle: a C_u column, or a K_u column when
// modes are quasi-static) and is 0 elsewhere.
//
// A contact the buffer does not cover (no terrain yet, or a gap ahead) keeps its last height with
// u' = 0 and is counted, so the state stays finite and the node can warn.
//
// Speed: at 1 kHz the same contacts are looked up again and again in the same patches.
// - Contacts at the same station (the soles of the two assemblies, left and right, at one
//   station: 12 per station on the bundled vehicles) are sampled together: one search for the patch
//   and the station cell, then each contact's lateral blend (Terrain::StationWeight, LateralCell).
// - Each station remembers the patch grid that answered it and the station interval over which
//   that grid keeps answering (TerrainBuffer::gridFor), each contact its lateral cell in that
//   grid, until the buffer changes (TerrainBuffer::revision).
// - On flat terrain (a run of equal grid samples, Terrain::flatRunEnd) the heights are those of
//   the last call, exactly, and u' = 0: a station still in the run skips the lookups (most of a
//   track); one whose u' is used leaves it at the run's last station, where the cell ahead rises.
// The heights are the buffer's, bit for bit.
#pragma once

#include <cstdint>
#include <vector>

#include "tracked_vehicle_dynamics/terrain/terrain_buffer.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace online {

class RoadInputSampler {
 public:
  /// Step of the difference for dh/dx at a grid's edge [m].
  static constexpr double kSlopeStep = 1e-6;

  /// stations x_q [m], lateral y_q [m] (same length n); needs_rate: n flags, true where u'_q is
  /// used (empty: all). Throws InputError for mismatched lengths or non-finite positions.
  RoadInputSampler(const Vector& stations, const Vector& lateral,
                   std::vector<bool> needs_rate = {});

  /// Writes w = [u; u'] [2 n] for station s [m], speed v [m/s] and lateral offset [m]; w must
  /// already have 2 n entries (no allocation). Returns the number of contacts not covered.
  int sample(const terrain::TerrainBuffer& buffer, double station, double speed,
             double lateral_offset, Vector* w);

  /// Sets the heights held for uncovered contacts [n] [m] (e.g. 0 after a reset).
  void setHeld(const Vector& heights);
  const Vector& held() const { return held_; }

  int size() const { return static_cast<int>(stations_.size()); }
  const Vector& stations() const { return stations_; }
  const Vector& lateral() const { return lateral_; }
  /// min_q x_q and max_q x_q [m] (0 when there are no inputs).
  double rearmost() const { return rearmost_; }
  double frontmost() const { return frontmost_; }

 private:
  /// What the contacts at one station found last time (see the file comment).
  struct Lookup {
    const terrain::Terrain* grid = nullptr;  ///< nullptr: look up again
    double from = 0.0, until = 0.0;          ///< stations where `grid` answers [m]
    /// Stations [m] of the flat run the last heights came from (empty: flat_from > flat_until),
    /// with the lateral offset [m] they were sampled at.
    double flat_from = 1.0, flat_until = 0.0, offset = 0.0;
  };
  /// Contact q's lateral cell in `grid` at lateral position y.
  struct ContactCell {
    const terrain::Terrain* grid = nullptr;  ///< nullptr: find again
    double y = 0.0;                          ///< [m]
    terrain::Terrain::LateralCell cell;
  };
  /// u'_q by differences on the buffer, at a grid's edge or in a gap (see the file comment).
  double rate(const terrain::TerrainBuffer& buffer, double x, double y, double height, double speed,
              double from, double until) const;

  Vector stations_;
  Vector lateral_;
  std::vector<bool> needs_rate_;
  Vector held_;
  double rearmost_ = 0.0;
  double frontmost_ = 0.0;
  // Contacts grouped by station: group g holds members_[group_begin_[g] .. group_begin_[g+1]).
  std::vector<Eigen::Index> members_;
  std::vector<std::size_t> group_begin_;
  std::vector<Lookup> lookups_;     // per group
  std::vector<char> group_rate_;    // per group: a member needs u' (leaves a run at its end)
  std::vector<ContactCell> cells_;  // per contact
  const terrain::TerrainBuffer* lookup_buffer_ = nullptr;
  std::uint64_t lookup_revision_ = 0;
};

}  // namespace online
}  // namespace tracked_vehicle_dynamics

// The ground-contact check of a vehicle stepped online (the node), in bounded memory: at chosen
// samples it recovers every contact force from the simulator's state (ground_contact.h)
//   F_i = k_i (u_i - q_m(i)) + c_i (u_i' - q_m(i)')          compression positive      [N]
// and keeps what a running simulation needs to know about the bonded model's range, which
// GroundContactMonitor (the offline run's summary) gives for a finished series: whether a contact
// that pressed at rest now pulls the vehicle down (F_i < 0), which no road does; from then on a
// real vehicle would have lifted that contact, and the linear result no longer describes it.
//
// "At rest" is the state restart() is given, the static equilibrium the vehicle (re)starts from:
// the bonded tracked model already pulls on some contacts there (the road between its wheels,
// doc/vehicle_model.md), so those are counted apart, as the offline monitor does. Two records:
// one since the restart (the run's first departure from the range) and one since the last
// takeInterval() (what a periodic diagnostics report shows).
//
// Pads. Where the contacts carry groups (GroundContact::group: a pad's soles,
// reduction::groupContactsByAssembly), each group's force is the sum of its contacts' and is
// watched the same way: a sole can pull while its pad as a whole presses (the pad carries its
// moments as opposite forces on its soles and would rock onto an edge), but a pad pressed at rest
// whose total pulls would leave the road. Single soles pull first (the tracked model's
// least-loaded sole carries 78 N at rest), but on real roads whole pads follow: on an ISO 8608
// class A road at 30 km/h whole tracked pads pull too (doc/ros_node.md).
//
// Cost per check: O(n_contacts) on a state the caller provides: the full [q; q'], or only the
// contacts' coordinates with the contacts numbering them (the node: Simulator::coordinates(),
// O(n_contacts x (modes + inputs)), 30-60 us on the tracked model; Simulator::state() is O(n^2)).
// A check every few steps, not every step. No allocation after construction.
#pragma once

#include <limits>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/ground_contact.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// What the checks of one period saw (since a restart, or since the last takeInterval()).
struct GroundContactRecord {
  long checks = 0;
  /// Checks at which a contact pressed at rest pulled (beyond the linear model's range).
  long checks_beyond = 0;
  /// Most contacts pressed at rest that pulled at one check.
  DofIndex most_pulling = 0;
  /// The largest total pull at one check: the sum of -F_i over the contacts pressed at rest with
  /// F_i < 0 [N]; how far beyond its range the model went, against the weight it carries.
  double max_pull = 0.0;
  /// The first check beyond the range: time [s], station [m] and the contact pulling hardest
  /// among those pressed at rest; NaN and -1 when none.
  double first_beyond_time = std::numeric_limits<double>::quiet_NaN();
  double first_beyond_station = std::numeric_limits<double>::quiet_NaN();
  DofIndex first_beyond_contact = -1;
  /// The lowest force of a contact pressed at rest [N], its contact and time [s] (+inf, -1,
  /// NaN before any check).
  double min_force = std::numeric_limits<double>::infinity();
  DofIndex min_contact = -1;
  double min_force_time = std::numeric_limits<double>::quiet_NaN();

  /// The same for the groups (pads) pressed at rest, each force the sum of its contacts'; all 0,
  /// -1, NaN or +inf when the contacts have no groups.
  long checks_groups_beyond = 0;
  int most_groups_pulling = 0;
  double first_group_beyond_time = std::numeric_limits<double>::quiet_NaN();
  double first_group_beyond_station = std::numeric_limits<double>::quiet_NaN();
  int first_group_beyond = -1;
  double min_group_force = std::numeric_limits<double>::infinity();
  int min_group = -1;
  double min_group_force_time = std::numeric_limits<double>::quiet_NaN();

  bool beyondRange() const { return checks_beyond > 0; }
  /// A whole group (pad) pressed at rest pulled.
  bool groupsBeyondRange() const { return checks_groups_beyond > 0; }
};

/// The forces at the last check.
struct GroundContactNow {
  double time = std::numeric_limits<double>::quiet_NaN();  ///< [s]
  DofIndex pulling = 0;          ///< contacts pressed at rest that pull now
  DofIndex pulling_at_rest = 0;  ///< contacts that pull now and already pulled at rest
  double pull = 0.0;       ///< sum of -F_i over the contacts pressed at rest that pull now [N]
  double left = 0.0;       ///< total ground force on the left side (y > 0) [N]
  double right = 0.0;      ///< and on the right (y < 0) [N]
  int groups_pulling = 0;  ///< groups pressed at rest whose total pulls now
  int groups_pulling_at_rest = 0;  ///< groups whose total pulls now and already pulled at rest
};

class GroundContactWatch {
 public:
  /// contacts: groundContacts() of the simulated system, with groups where set (-1: none);
  /// input_count: its inputs n_u, so that w = [u; u'] has u_i at w(i) and u_i' at w(n_u + i) (a
  /// travel-inertia system's extra input counts: contacts index only the road inputs). Throws
  /// InputError for an empty contact list or a contact input outside [0, n_u).
  GroundContactWatch(std::vector<GroundContact> contacts, DofIndex input_count);

  /// The vehicle is at rest in `state` z = [q; q'] [2n] under input w [2 n_u]: the contacts
  /// with F_i >= 0 there are those "pressed at rest". Clears both records and the interval.
  /// Throws InputError for wrong lengths (a coordinate of a contact outside q).
  void restart(double time, const Vector& state, const Vector& input);
  /// One check at time t [s], station s [m]. Throws InputError for wrong lengths, or when
  /// restart() has not been called.
  void check(double time, double station, const Vector& state, const Vector& input);

  /// Since the last restart().
  const GroundContactRecord& sinceRestart() const { return since_restart_; }
  /// Since the last takeInterval() (or restart()); the interval starts afresh.
  GroundContactRecord takeInterval();
  const GroundContactNow& now() const { return now_; }
  /// Forces at the last check (or restart) [n_contacts] [N].
  const Vector& forces() const { return forces_; }
  /// Group forces at the last check (or restart), each the sum of its contacts' [groups] [N].
  const Vector& groupForces() const { return group_forces_; }

  DofIndex contactCount() const { return static_cast<DofIndex>(contacts_.size()); }
  /// Contacts pulling (F < 0) at the last restart.
  DofIndex pullingAtRest() const { return pulling_at_rest_; }
  /// The total ground force at the last restart, sum of F_i [N]: the weight of a vehicle at rest.
  double restForce() const { return rest_force_; }
  /// Groups: 1 + the largest GroundContact::group (0 when none has one).
  int groupCount() const { return static_cast<int>(group_forces_.size()); }
  /// Groups whose total pulled at the last restart.
  int groupsPullingAtRest() const { return groups_pulling_at_rest_; }
  /// The first contact of group g (for its side and name); -1 for a group without contacts.
  DofIndex groupContact(int g) const { return group_contact_.at(static_cast<std::size_t>(g)); }
  const std::vector<GroundContact>& contacts() const { return contacts_; }

 private:
  /// forces_ and group_forces_ (each group's the sum of its contacts') from the state.
  void evaluate(const Vector& state, const Vector& input);
  /// now_ from forces_ (side totals; among the contacts pressed at rest, those pulling).
  /// Returns the contact pressed at rest with the lowest force (-1: none).
  DofIndex tally(double time);
  /// The same for the groups: now_'s group counts from group_forces_; returns the group pressed
  /// at rest with the lowest force (-1: none).
  int tallyGroups();

  std::vector<GroundContact> contacts_;
  DofIndex input_count_ = 0;
  std::vector<char> pressed_at_rest_;  // per contact: F_i >= 0 at the restart
  DofIndex pulling_at_rest_ = 0;
  double rest_force_ = 0.0;
  std::vector<DofIndex> group_contact_;      // per group: its first contact
  std::vector<char> group_pressed_at_rest_;  // per group: its total >= 0 at the restart
  int groups_pulling_at_rest_ = 0;
  Vector group_forces_;
  bool started_ = false;
  Vector forces_;
  GroundContactNow now_;
  GroundContactRecord since_restart_, interval_;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics

#!/usr/bin/env python3
"""Summary and plot of a bag recorded from vehicle_dynamics_node (launch/replay_track.launch).

Prints the peaks of the hull motion and road-wheel displacements, what the simulated IMUs read
(imu/<point>, the node's ~imu_points), the final ride-comfort metrics and the real-time figures, and writes a PNG of heave, pitch, wheel displacements and the vertical
acceleration against the station.

    ros_demo_summary.py OUTPUT.bag --png plot.png [--wall-seconds S] [--title TEXT]
"""
import argparse
import math
import re
import sys


def pitch_of(q):
    """Pitch [rad] of a quaternion, R = Rz Ry Rx (REP-103)."""
    s = 2.0 * (q.w * q.y - q.z * q.x)
    return math.asin(max(-1.0, min(1.0, s)))


def plotted_wheels(names):
    """The front, middle and rear left road wheels among the wheel names of /road_wheels
    ([frame prefix]road_wheel_left_N, N = 1..axle count front to rear), front first; fewer when
    the vehicle has fewer than three axles."""
    left = {}
    for n in names:
        m = re.search(r"road_wheel_left_(\d+)$", n)
        if m:
            left[int(m.group(1))] = n
    axles = sorted(left)
    if not axles:
        return []
    picks = [axles[0], axles[len(axles) // 2], axles[-1]]
    return [left[a] for a in sorted(set(picks))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("bag")
    parser.add_argument("--png", required=True)
    parser.add_argument("--wall-seconds", type=float, default=None,
                        help="wall time of the replay, for the real-time factor")
    parser.add_argument("--title", default="")
    parser.add_argument("--base-frame", default="base_link",
                        help="the node's ~frame_prefix + ~base_frame (default base_link)")
    args = parser.parse_args()
    import rosbag

    pose = {}        # stamp -> (z [m], pitch [rad])
    wheels = {}      # stamp -> (station, {name: displacement})
    accel = {}       # stamp -> vertical acceleration [m/s^2]
    comfort = None
    loop = {}
    model = {}
    imus = {}        # frame -> [(specific force x, y, z [m/s^2], |body rate| [rad/s])]
    with rosbag.Bag(args.bag) as bag:
        topics = ["/tf", "/road_wheels", "/hull/accel", "/comfort", "/diagnostics"]
        topics += [t for t in bag.get_type_and_topic_info().topics if t.startswith("/imu/")]
        for topic, msg, _ in bag.read_messages(topics=topics):
            if topic == "/tf":
                for t in msg.transforms:
                    if t.child_frame_id == args.base_frame:
                        pose[t.header.stamp.to_sec()] = (t.transform.translation.z,
                                                         pitch_of(t.transform.rotation))
            elif topic == "/road_wheels":
                wheels[msg.header.stamp.to_sec()] = (
                    msg.station, {w.name: w.displacement for w in msg.wheels})
            elif topic == "/hull/accel":
                accel[msg.header.stamp.to_sec()] = msg.accel.linear.z
            elif topic == "/comfort":
                comfort = msg
            elif topic.startswith("/imu/"):
                a, w = msg.linear_acceleration, msg.angular_velocity
                imus.setdefault(msg.header.frame_id, []).append(
                    (a.x, a.y, a.z, math.sqrt(w.x ** 2 + w.y ** 2 + w.z ** 2)))
            elif topic == "/diagnostics":
                for s in msg.status:
                    values = {kv.key: kv.value for kv in s.values}
                    if s.name.endswith(": loop"):
                        loop = values
                    elif s.name.endswith(": model"):
                        model = values
    stamps = sorted(set(pose) & set(wheels))
    if not stamps:
        print("no samples in %s" % args.bag, file=sys.stderr)
        return 1
    station = [wheels[t][0] for t in stamps]
    z = [pose[t][0] for t in stamps]
    pitch = [math.degrees(pose[t][1]) for t in stamps]
    names = sorted(wheels[stamps[0]][1])
    acc = [accel.get(t, float("nan")) for t in stamps]
    z0, p0 = z[0], pitch[0]
    duration = stamps[-1] - stamps[0]

    print("samples: %d over %.2f s of simulated time, station %.2f .. %.2f m"
          % (len(stamps), duration, station[0], station[-1]))
    if model:
        print("model: %s %s, %s reduced DOFs, %s road inputs (%s)"
              % (model.get("vehicle", "?"), model.get("variant", "?"),
                 model.get("reduced DOFs", "?"), model.get("road inputs", "?"),
                 model.get("cache note", "")))
    print("%s heave: peak %+.3f m, min %+.3f m (from static)"
          % (args.base_frame, max(z) - z0, min(z) - z0))
    print("hull pitch: max %+.2f deg, min %+.2f deg (from static)"
          % (max(pitch) - p0, min(pitch) - p0))
    peak_wheel = max(((abs(d), n) for t in stamps for n, d in wheels[t][1].items()))
    print("road wheels: largest displacement %.3f m (%s)" % peak_wheel)
    finite_acc = [a for a in acc if not math.isnan(a)]
    if finite_acc:
        print("hull CoG vertical acceleration: peak %.2f m/s^2" % max(abs(a) for a in finite_acc))
    for frame, readings in sorted(imus.items()):
        fz = [r[2] for r in readings]
        print("IMU at %s (specific force, gravity included: %+.2f m/s^2 at rest): z %+.2f .. "
              "%+.2f m/s^2, |x| up to %.2f m/s^2, body rate up to %.1f deg/s"
              % (frame, fz[0], min(fz), max(fz), max(abs(r[0]) for r in readings),
                 math.degrees(max(r[3] for r in readings))))
    if comfort is not None:
        print("comfort at %s (ISO 2631-1 %s): a_w,rms %.3f m/s^2, VDV %.3f m/s^1.75, MTVV %.3f "
              "m/s^2, peak |a| %.2f m/s^2 over %.2f s"
              % (comfort.point, comfort.weighting, comfort.weighted_rms, comfort.vdv,
                 comfort.mtvv, comfort.peak_acceleration, comfort.duration))
        if hasattr(comfort, "seat_surface_total_value"):  # a bag of version 0.5.0 or later
            print("  every axis of the seat surface: a_v %.3f m/s^2 (x, y, z), hull rotations (We) "
                  "roll %.3f, pitch %.3f, yaw %.3f rad/s^2, seat-surface total %.3f m/s^2"
                  % (comfort.vibration_total_value, comfort.weighted_rms_roll,
                     comfort.weighted_rms_pitch, comfort.weighted_rms_yaw,
                     comfort.seat_surface_total_value))
        if hasattr(comfort, "mtvv_linear"):  # a bag of version 0.5.1 or later
            print("  MTVV (linear) %.3f m/s^2, crest factor %.2f"
                  % (comfort.mtvv_linear,
                     comfort.peak_weighted / comfort.weighted_rms if comfort.weighted_rms > 0
                     else float("nan")))
    if loop:
        mean_us = float(loop.get("step time mean [us]", "nan"))
        rate = float(loop.get("rate [Hz]", "1000"))
        print("node: step time p99 %s us (since start), mean %.1f us in the last report -> "
              "the step runs %.1fx faster than real time at %.0f Hz; %s late ticks, %s "
              "resynchronisations"
              % (loop.get("step time p99 since start [us]", "?"), mean_us,
                 1e6 / rate / mean_us if mean_us > 0 else float("nan"), rate,
                 loop.get("late ticks (total)", "?"), loop.get("resynchronisations (total)", "?")))
    if args.wall_seconds:
        print("replay: %.2f s simulated in %.2f s of wall time for the whole launch "
              "(rosbag plays in real time; start-up included)" % (duration, args.wall_seconds))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(4, 1, figsize=(9, 10), sharex=True)
    axes[0].plot(station, [v - z0 for v in z])
    axes[0].set_ylabel("base_link z\nfrom static [m]")
    axes[1].plot(station, [v - p0 for v in pitch])
    axes[1].set_ylabel("pitch [deg]\n(+ nose down)")
    for n in plotted_wheels(names):
        axes[2].plot(station, [wheels[t][1][n] for t in stamps], label=n)
    axes[2].set_ylabel("wheel displacement\n[m]")
    axes[2].legend(loc="upper right", fontsize=8)
    axes[3].plot(station, acc)
    axes[3].set_ylabel("hull CoG vertical\nacceleration [m/s^2]")
    axes[3].set_xlabel("station of the reference point [m]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    fig.suptitle(args.title or "vehicle_dynamics_node: %s" % args.bag)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)
    print("plot: %s" % args.png)
    return 0


if __name__ == "__main__":
    sys.exit(main())

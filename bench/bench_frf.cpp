// Benchmark of the exact FRF of a reduced model whose damping couples its modes (discrete arm
// dampers), side by side with SciPy on the same exported matrices, in one run:
//
//   ours:  frfStateSpace (one Hessenberg reduction of the 2n state matrix, then O(n^2) per
//          frequency; what `tvd frf` runs when "solution" is "direct") and frfDirect (a dense
//          complex LU per frequency, the textbook solution of eq. 18), on the tracked and the
//          un-tracked paper vehicle with 20 kN m s/rad arm dampers on axles 1 and 7;
//   SciPy: scipy.linalg.solve of (K - w^2 M + j w C) x = (K_u + j w C_u) tau per frequency, as
//          a SciPy user writes eq. 18 (bench/scipy_frf.py), compared entry by entry with ours.
//
// 1001 frequencies 0..50 Hz (tvd frf's default grid), travelled excitation at 30 km/h, the
// outputs of the reduced model (hull 6 DOF, wheels, named points), accelerations.
//
//   bench_frf [--repeat N]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_common.h"
#include "tracked_vehicle_dynamics/dynamics/frf.h"
#include "tracked_vehicle_dynamics/dynamics/frf_state_space.h"
#include "tracked_vehicle_dynamics/heap_reuse.h"
#include "tracked_vehicle_dynamics/io/mat_file.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

namespace tvd = tracked_vehicle_dynamics;
using bench::Clock;
using bench::median;
using bench::seconds;

namespace {

struct Timing {
  double state_space = 0.0;  // ModalSystem + frfStateSpace [s], median
  double direct = 0.0;       // frfDirect [s], one run
  double difference = 0.0;   // max |ours - direct| / peak
};

Timing run(const tvd::vehicle::VehicleDescription& description, tvd::vehicle::Variant variant,
           int repeat, const std::filesystem::path& dir) {
  const tvd::reduction::ReducedModel model =
      tvd::reduction::reduceVehicle(description, variant, {}, nullptr);
  const tvd::dynamics::SecondOrderSystem& s = model.system;
  const tvd::Vector hz = tvd::Vector::LinSpaced(1001, 0.0, 50.0);
  const double speed = 30.0 / tvd::kKmhPerMs;
  const tvd::dynamics::InputDelay delay =
      tvd::dynamics::InputDelay::travelling(s.input_stations, speed);
  Timing t;
  std::vector<double> times;
  tvd::dynamics::ComplexMatrix fast;
  double coupling = 0.0;
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = Clock::now();
    const tvd::dynamics::ModalSystem modal(s);
    fast = tvd::dynamics::frfStateSpace(s, modal, hz, delay);
    times.push_back(seconds(t0));
    coupling = modal.maxOffDiagonalDampingRatio();
  }
  t.state_space = median(times);
  const auto t1 = Clock::now();
  const tvd::dynamics::ComplexMatrix direct = tvd::dynamics::frfDirect(s, hz, delay);
  t.direct = seconds(t1);
  t.difference = (fast - direct).cwiseAbs().maxCoeff() / direct.cwiseAbs().maxCoeff();
  std::printf(
      "%s: %ld DOFs, %ld road inputs, %ld outputs, damping coupling %.3g\n"
      "ours: state space (modes + Hessenberg + 1001 solves) %.3f s (median of %d); dense LU per "
      "frequency %.3f s; ratio %.1f; max difference %.2g of the peak\n",
      tvd::vehicle::variantName(variant), static_cast<long>(s.size()),
      static_cast<long>(s.inputCount()), static_cast<long>(s.outputCount()), coupling,
      t.state_space, repeat, t.direct, t.direct / t.state_space, t.difference);
  tvd::io::MatWriter w((dir / (std::string(tvd::vehicle::variantName(variant)) + ".mat")).string());
  w.writeMatrix("M", s.mass);
  w.writeMatrix("K", s.stiffness);
  w.writeMatrix("C", s.damping);
  w.writeMatrix("K_u", s.input_stiffness);
  w.writeMatrix("C_u", s.input_damping);
  w.writeMatrix("H", s.output);
  w.writeMatrix("stations", s.input_stations);
  w.writeMatrix("hz", hz);
  w.writeScalar("speed", speed);
  w.writeMatrix("ours_re", fast.real());
  w.writeMatrix("ours_im", fast.imag());
  w.close();
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const tvd::HeapReuse heap_reuse;
  int repeat = 3;
  const char* const usage =
      "usage: bench_frf [--repeat N]   (N >= 1 repetitions, default 3)\n"
      "The exact FRF of the paper vehicle with arm dampers (coupled modes), ours beside SciPy's\n"
      "solve per frequency on the same matrices (bench/scipy_frf.py); about a minute.\n";
  if (const int status = bench::parseRepeat(argc, argv, "bench_frf", usage, &repeat); status >= 0)
    return status;
  tvd::vehicle::VehicleDescription description = tvd::vehicle::loadVehicleDescription(
      std::string(TVD_SOURCE_DIR) + "/config/vehicles/paper_vehicle.yaml");
  // Two 20 kN m s/rad rotary dampers on the front and rear arms: Phi^T C Phi is then not
  // diagonal, and eq. 20's modal damping moves the front wheel's peak by a factor 2 (README).
  description.suspension.arm_damping = 2.0e4;
  description.damping.damped_stations = {1, 7};
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tvd_bench_frf";
  std::filesystem::create_directories(dir);
  std::printf("== exact FRF with coupled damping, 1001 frequencies 0-50 Hz, 30 km/h\n");
  const Timing untracked = run(description, tvd::vehicle::Variant::Untracked, repeat, dir);
  const Timing tracked = run(description, tvd::vehicle::Variant::Tracked, repeat, dir);
  std::fflush(stdout);

  const std::string cmd = "/usr/bin/python3 " + std::string(TVD_SOURCE_DIR) +
                          "/bench/scipy_frf.py " + dir.string() + " " + std::to_string(repeat);
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe)
    return 1;
  double sp_untracked = 0, sp_untracked_diff = 1, sp_tracked = 0, sp_tracked_diff = 1;
  char line[1024];
  while (std::fgets(line, sizeof(line), pipe)) {
    std::fputs(line, stdout);
    std::sscanf(line, "scipy_frf untracked %lf %lf", &sp_untracked, &sp_untracked_diff);
    std::sscanf(line, "scipy_frf tracked %lf %lf", &sp_tracked, &sp_tracked_diff);
  }
  if (pclose(pipe) != 0 || sp_untracked <= 0 || sp_tracked <= 0) {
    std::printf("scipy: comparison failed (is python3-scipy installed?)\n");
    return 1;
  }
  std::printf(
      "\nratio SciPy solve per frequency / ours: un-tracked %.1f (%.3f s / %.3f s), tracked %.1f "
      "(%.3f s / %.3f s); ours vs SciPy: max difference %.2g and %.2g of the peak\n",
      sp_untracked / untracked.state_space, sp_untracked, untracked.state_space,
      sp_tracked / tracked.state_space, sp_tracked, tracked.state_space, sp_untracked_diff,
      sp_tracked_diff);
  const bool agree = sp_untracked_diff < 1e-6 && sp_tracked_diff < 1e-6 &&
                     untracked.difference < 1e-6 && tracked.difference < 1e-6;
  if (!agree)
    std::printf("the solutions disagree beyond 1e-6 of the peak\n");
  return agree ? 0 : 1;
}

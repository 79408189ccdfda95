// Benchmark: lowest 40 modes of a ~17,000-DOF beam/spring model shaped like two track chains
// (closed loops of short beams on ground springs, joined by a rigid hull), ours vs SciPy's
// shift-invert eigsh on the same exported matrices, in the same run.
//
//   bench_modal [--repeat N] [--modes N] [--assemblies N]
#include <unsupported/Eigen/SparseExtra>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "bench_common.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/heap_reuse.h"

namespace tvd = tracked_vehicle_dynamics;
using bench::median;

namespace {

using tvd::kPi;

// Two closed chains of `assemblies` links (each link: `nodes_per_link` nodes joined by beams),
// the lower run of each chain on ground springs, and a rigid hull on torsion-like springs.
tvd::fem::Model makeChainModel(int assemblies, int nodes_per_link) {
  tvd::fem::Model m;
  m.name = "bench_track_chains";
  m.materials.push_back({"steel", 205e9, 79e9, 7850});
  tvd::fem::Section link;
  link.name = "link";
  link.area = 4e-3;
  link.iy = 2e-7;
  link.iz = 5e-6;
  link.torsion = 6e-7;
  m.sections.push_back(link);
  const double pitch = 0.16, length = assemblies * pitch / 2.0 - 0.5;
  tvd::NodeId id = 1;
  m.addNode(100000, tvd::Vector3(0, 0, 1.5));  // hull
  tvd::fem::Mass hull;
  hull.node = 100000;
  hull.mass = 30000;
  hull.inertia = tvd::Vector3(4e4, 1.4e5, 1.6e5).asDiagonal();
  m.masses.push_back(hull);
  for (int side = 0; side < 2; ++side) {
    const double y = side == 0 ? 1.4 : -1.4;
    const int n = assemblies * nodes_per_link;
    const tvd::NodeId first = id;
    for (int i = 0; i < n; ++i) {
      // A stadium-shaped loop: bottom run, front arc, top run, rear arc.
      const double s = (static_cast<double>(i) / n) * (2 * length + 2 * kPi * 0.3);
      tvd::Vector3 x;
      if (s < length) {
        x = {-length / 2 + s, y, 0.0};
      } else if (s < length + kPi * 0.3) {
        const double a = (s - length) / 0.3;
        x = {length / 2 + 0.3 * std::sin(a), y, 0.3 - 0.3 * std::cos(a)};
      } else if (s < 2 * length + kPi * 0.3) {
        x = {length / 2 - (s - length - kPi * 0.3), y, 0.6};
      } else {
        const double a = (s - 2 * length - kPi * 0.3) / 0.3;
        x = {-length / 2 - 0.3 * std::sin(a), y, 0.3 + 0.3 * std::cos(a)};
      }
      m.addNode(id, x);
      tvd::fem::Mass lumped;
      lumped.node = id;
      lumped.mass = 27.0 / nodes_per_link;
      lumped.inertia = tvd::Matrix3::Identity() * 1e-3;
      m.masses.push_back(lumped);
      if (x.z() == 0.0) {
        tvd::fem::Spring ground;
        ground.n1 = id;
        ground.stiffness << 1.4e6 / nodes_per_link, 3.4e6 / nodes_per_link, 1.9e7 / nodes_per_link,
            0, 0, 0;
        m.springs.push_back(ground);
      }
      if (i % (nodes_per_link * 6) == 0) {
        tvd::fem::Spring suspension;  // road-wheel-like tie to the hull
        suspension.n1 = id;
        suspension.n2 = 100000;
        suspension.stiffness << 1e7, 1e7, 2e6, 0, 0, 0;
        m.springs.push_back(suspension);
      }
      ++id;
    }
    for (int i = 0; i < n; ++i) {
      tvd::fem::Beam b;
      b.n1 = first + i;
      b.n2 = first + (i + 1) % n;
      b.material = "steel";
      b.section = "link";
      b.orientation = tvd::Vector3::UnitY().cross(m.nodes.back().position - m.nodes[1].position);
      b.orientation = tvd::Vector3(0, 1, 0);
      m.beams.push_back(b);
    }
  }
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  const tvd::HeapReuse heap_reuse;  // as tvd does (heap_reuse.h)
  int repeat = 5, modes = 40, assemblies = 92, nodes_per_link = 15;
  const char* const usage =
      "usage: bench_modal [--repeat N] [--modes N] [--assemblies N]   (whole numbers >= 1;\n"
      "defaults 5, 40, 92)\n"
      "The lowest modes of a beam/spring model shaped like two track chains, beside SciPy's\n"
      "eigsh on the same K and M (bench/scipy_modal.py).\n";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::fputs(usage, stdout);
      return 0;
    }
    int* value = a == "--repeat"       ? &repeat
                 : a == "--modes"      ? &modes
                 : a == "--assemblies" ? &assemblies
                                       : nullptr;
    if (value == nullptr) {
      std::fprintf(stderr, "bench_modal: unexpected argument '%s'\n%s", a.c_str(), usage);
      return 2;
    }
    *value = i + 1 < argc ? std::atoi(argv[++i]) : 0;
    if (*value < 1) {
      std::fprintf(stderr, "bench_modal: %s needs a whole number >= 1\n%s", a.c_str(), usage);
      return 2;
    }
  }
  const tvd::fem::Model model = makeChainModel(assemblies, nodes_per_link);
  const auto t0 = std::chrono::steady_clock::now();
  const tvd::fem::System sys = tvd::fem::assemble(model);
  const double assemble_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  tvd::fem::ModalRequest request;
  request.count = modes;
  request.shift = -1.0;  // [rad^2/s^2], the same shift is given to SciPy
  std::vector<double> ours;
  tvd::fem::ModalBasis basis;
  for (int r = 0; r < repeat; ++r) {
    basis = tvd::fem::solveModes(sys.stiffness, sys.mass, request);
    ours.push_back(basis.seconds);
  }

  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tvd_bench_modal";
  std::filesystem::create_directories(dir);
  Eigen::saveMarket(sys.stiffness, (dir / "K.mtx").string());
  Eigen::saveMarket(sys.mass, (dir / "M.mtx").string());

  std::printf("model: %s, %ld active DOFs, K nnz %ld, assembly %.3f s\n", model.name.c_str(),
              static_cast<long>(sys.size()), static_cast<long>(sys.stiffness.nonZeros()),
              assemble_s);
  std::printf(
      "ours  (CHOLMOD + Spectra shift-invert Lanczos): median %.3f s over %d runs "
      "(min %.3f), %d modes, f1 = %.4f Hz, f%d = %.4f Hz\n",
      median(ours), repeat, *std::min_element(ours.begin(), ours.end()), basis.count(),
      basis.frequencies_hz(0), basis.count(), basis.frequencies_hz(basis.count() - 1));
  std::fflush(stdout);

  const std::string script = std::string(TVD_SOURCE_DIR) + "/bench/scipy_modal.py";
  const std::string cmd = "/usr/bin/python3 " + script + " " + dir.string() + " " +
                          std::to_string(modes) + " " + std::to_string(request.shift) + " " +
                          std::to_string(repeat);
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) {
    std::printf("scipy: could not run %s\n", cmd.c_str());
    return 1;
  }
  double scipy_s = 0.0, scipy_f1 = 0.0, scipy_fn = 0.0;
  char line[512];
  while (std::fgets(line, sizeof(line), pipe)) {
    std::fputs(line, stdout);
    std::sscanf(line, "scipy_median_seconds %lf f1 %lf fn %lf", &scipy_s, &scipy_f1, &scipy_fn);
  }
  const int status = pclose(pipe);
  if (status != 0 || scipy_s <= 0) {
    std::printf("scipy: comparison failed (is python3-scipy installed?)\n");
    return 1;
  }
  std::printf("SciPy eigsh (shift-invert, SuperLU):              median %.3f s\n", scipy_s);
  std::printf("ratio SciPy / ours = %.2f   (frequency agreement: f1 %.2e, f%d %.2e relative)\n",
              scipy_s / median(ours), std::abs(scipy_f1 - basis.frequencies_hz(0)) / scipy_f1,
              basis.count(),
              std::abs(scipy_fn - basis.frequencies_hz(basis.count() - 1)) / scipy_fn);
  return 0;
}

#include "output_files.h"

#include <filesystem>
#include <fstream>
#include <iomanip>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {
std::ofstream openForWriting(const std::filesystem::path& path) {
  std::ofstream out(path);
  if (!out) throw InputError("cannot write " + path.string());
  out << std::setprecision(12);
  return out;
}
}  // namespace

void writeModeFiles(const std::string& dir, const fem::System& sys, const fem::ModalBasis& basis) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError("cannot create output directory " + dir + ": " + ec.message());
  const std::filesystem::path root(dir);
  {
    auto out = openForWriting(root / "modes.csv");
    out << "mode,frequency_hz,eigenvalue_rad2_s2\n";
    for (int i = 0; i < basis.count(); ++i)
      out << i + 1 << "," << basis.frequencies_hz(i) << "," << basis.eigenvalues(i) << "\n";
  }
  {
    auto out = openForWriting(root / "shapes.csv");
    out << "node,direction";
    for (int i = 0; i < basis.count(); ++i) out << ",mode_" << i + 1;
    out << "\n";
    for (DofIndex r = 0; r < sys.size(); ++r) {
      const fem::DofRef d = sys.dofs.dofOf(r);
      out << d.node << "," << directionName(d.direction);
      for (int i = 0; i < basis.count(); ++i) out << "," << basis.shapes(r, i);
      out << "\n";
    }
  }
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics

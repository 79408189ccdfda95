// Result files shared by the CLI subcommands (CSV for spreadsheets, .mat for MATLAB/Octave/SciPy).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/io/mat_file.h"
#include "tracked_vehicle_dynamics/vehicle/mode_classification.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// The files of one command, written all or none: each is written under a staged name of its
/// own next to it ("modes~Ab3xYz.csv": the extension, which chooses the format, is kept;
/// io::createTemporaryBeside) and commit()
/// renames them all onto their names once every one was written; without commit() (an
/// exception unwinding) the destructor removes the staged files.
/// A failed run into a directory of an earlier one thus leaves the earlier files as they were,
/// not a mix of old and new.
class OutputFileSet {
 public:
  OutputFileSet() = default;
  ~OutputFileSet();
  OutputFileSet(const OutputFileSet&) = delete;
  OutputFileSet& operator=(const OutputFileSet&) = delete;

  /// Calls `write(staged)` with the staged name of `path`; an InputError it throws is rethrown
  /// naming `path` instead of the staged name. Throws std::logic_error for a path given twice.
  void write(const std::string& path, const std::function<void(const std::string&)>& write);
  /// Renames every staged file onto its name. Throws InputError naming a name that is a
  /// directory (before any rename) or whose rename fails.
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> staged_;  // (staged, final)
  bool committed_ = false;
};

/// What a result .mat says about its run beside the data: a text (char array) or a number (1 x 1
/// double: forward_acceleration_m_s2 is a number in MATLAB, not "-2.942").
struct MetadataEntry {
  std::string name;
  std::variant<std::string, double> value;
};
using Metadata = std::vector<MetadataEntry>;

/// Writes each entry as a variable of `mat` (names as MatWriter checks them).
void writeMetadata(io::MatWriter& mat, const Metadata& metadata);

/// Writes the rows of the active DOFs: dof_node, dof_direction (0..5: ux uy uz rx ry rz) as
/// n x 1 doubles and dof_labels ("node 12 uz") as a cell array.
void writeDofTable(io::MatWriter& mat, const fem::System& system);
/// The same for the active DOFs of a DOF map (a system's rows).
void writeDofTable(io::MatWriter& mat, const fem::DofMap& dofs);

/// Writes DIR/modes.csv (mode, frequency_hz, eigenvalue[, type and the kinetic-energy shares]),
/// DIR/shapes.csv (one row per active DOF: node, direction, then one column per mode) and
/// DIR/modes.mat (frequencies_hz, eigenvalues, shapes, dof_node, dof_direction, dof_labels[,
/// mode_types, energy_shares, hull_component_energy_shares], then `metadata`). `classes`: one
/// per mode for a vehicle (classifyModes), empty for a generic model. Creates DIR. Each file is
/// staged in `written` (the caller commits); InputError names a file that cannot be written.
void writeModeFiles(const std::string& dir, const fem::System& system, const fem::ModalBasis& basis,
                    const std::vector<vehicle::ModeClass>& classes, const Metadata& metadata,
                    OutputFileSet& written);

/// The energy-share columns of modes.csv and of tvd modes --json, in order: the hull (with what
/// rides rigidly on it), the road wheels' own motion, the track; then the hull's six components.
extern const std::vector<std::string> kEnergyShareNames;
/// Those shares of one mode, in kEnergyShareNames' order.
std::vector<double> energyShares(const vehicle::ModeClass& mode);

/// Writes a table of named columns: MATLAB/Octave/SciPy .mat when `path` ends in ".mat" (one n x 1
/// variable per column, named by its header, plus the `metadata` variables), CSV
/// otherwise (a header row, then `precision` significant digits; metadata not written). Either way
/// the data go to a temporary file renamed onto `path`, so a failure leaves no partial file. Names
/// must be valid MATLAB identifiers. Throws InputError naming the file when it cannot be written.
void writeTable(const std::string& path, const std::vector<std::string>& names, const Matrix& data,
                int precision, const Metadata& metadata = {});

/// Where reduced models are cached: $XDG_CACHE_HOME/tracked_vehicle_dynamics when it is an
/// absolute path, else ~/.cache/tracked_vehicle_dynamics, else /tmp/tracked_vehicle_dynamics.
std::string defaultCacheDir();

/// Creates DIR (and parents); throws InputError naming it when that fails.
void makeOutputDirectory(const std::string& dir);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics

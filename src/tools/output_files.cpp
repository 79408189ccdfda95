#include "output_files.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <stdexcept>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/atomic_file.h"
#include "tracked_vehicle_dynamics/io/file_type.h"
#include "tracked_vehicle_dynamics/io/mat_file.h"
#include "tracked_vehicle_dynamics/io/number_text.h"
#include "tracked_vehicle_dynamics/io/staged_files.h"

namespace tracked_vehicle_dynamics {
namespace tools {

void makeOutputDirectory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw InputError("cannot create output directory " + dir + ": " + ec.message());
}

void writeMetadata(io::MatWriter& mat, const Metadata& metadata) {
  for (const MetadataEntry& entry : metadata) {
    if (const auto* text = std::get_if<std::string>(&entry.value))
      mat.writeString(entry.name, *text);
    else
      mat.writeScalar(entry.name, std::get<double>(entry.value));
  }
}

void writeDofTable(io::MatWriter& mat, const fem::System& sys) {
  writeDofTable(mat, sys.dofs);
}

void writeDofTable(io::MatWriter& mat, const fem::DofMap& dofs) {
  const DofIndex n = dofs.activeCount();
  Matrix node(n, 1), direction(n, 1);
  std::vector<std::string> labels;
  for (DofIndex r = 0; r < n; ++r) {
    const fem::DofRef d = dofs.dofOf(r);
    node(r, 0) = static_cast<double>(d.node);
    direction(r, 0) = d.direction;
    labels.push_back(dofs.label(r));
  }
  mat.writeMatrix("dof_node", node);
  mat.writeMatrix("dof_direction", direction);
  mat.writeStrings("dof_labels", labels);
}

const std::vector<std::string> kEnergyShareNames = {
    "hull",        "wheels",    "track",      "hull_longitudinal", "hull_lateral",
    "hull_bounce", "hull_roll", "hull_pitch", "hull_yaw"};

std::vector<double> energyShares(const vehicle::ModeClass& mode) {
  std::vector<double> out = {mode.hull_share, mode.wheel_share, mode.track_share};
  out.insert(out.end(), mode.hull_energy.begin(), mode.hull_energy.end());
  return out;
}

void writeModeFiles(const std::string& dir, const fem::System& sys, const fem::ModalBasis& basis,
                    const std::vector<vehicle::ModeClass>& classes, const Metadata& metadata,
                    OutputFileSet& written) {
  makeOutputDirectory(dir);
  const std::filesystem::path root(dir);
  const bool typed = static_cast<int>(classes.size()) == basis.count();
  std::vector<std::string> mode_types;
  Matrix shares(typed ? basis.count() : 0, static_cast<Eigen::Index>(kEnergyShareNames.size()));
  for (int i = 0; typed && i < basis.count(); ++i) {
    mode_types.push_back(classes[static_cast<std::size_t>(i)].label);
    const std::vector<double> row = energyShares(classes[static_cast<std::size_t>(i)]);
    for (std::size_t k = 0; k < row.size(); ++k)
      shares(i, static_cast<Eigen::Index>(k)) = row[k];
  }
  written.write((root / "modes.csv").string(), [&](const std::string& path) {
    io::AtomicTextFile file(path);
    std::ostream& out = file.stream();
    out << std::setprecision(12);
    out << "mode,frequency_hz,eigenvalue_rad2_s2";
    if (typed) {
      out << ",type";
      for (const std::string& name : kEnergyShareNames)
        out << "," << name << "_energy_share";
    }
    out << "\n";
    for (int i = 0; i < basis.count(); ++i) {
      out << i + 1 << "," << basis.frequencies_hz(i) << "," << basis.eigenvalues(i);
      if (typed) {
        out << "," << mode_types[static_cast<std::size_t>(i)];
        for (Eigen::Index k = 0; k < shares.cols(); ++k)
          out << "," << shares(i, k);
      }
      out << "\n";
    }
    file.commit();
  });
  written.write((root / "shapes.csv").string(), [&](const std::string& path) {
    io::AtomicTextFile file(path);
    std::ostream& out = file.stream();
    out << std::setprecision(12);
    out << "node,direction";
    for (int i = 0; i < basis.count(); ++i)
      out << ",mode_" << i + 1;
    out << "\n";
    for (DofIndex r = 0; r < sys.size(); ++r) {
      const fem::DofRef d = sys.dofs.dofOf(r);
      out << d.node << "," << directionName(d.direction);
      for (int i = 0; i < basis.count(); ++i)
        out << "," << basis.shapes(r, i);
      out << "\n";
    }
    file.commit();
  });
  written.write((root / "modes.mat").string(), [&](const std::string& path) {
    io::MatWriter mat(path);
    mat.writeMatrix("frequencies_hz", basis.frequencies_hz);
    mat.writeMatrix("eigenvalues", basis.eigenvalues);
    mat.writeMatrix("shapes", basis.shapes);
    writeDofTable(mat, sys);
    if (typed) {
      mat.writeStrings("mode_types", mode_types);
      mat.writeMatrix("energy_shares", shares.leftCols(3));
      mat.writeMatrix("hull_component_energy_shares", shares.rightCols(6));
    }
    writeMetadata(mat, metadata);
    mat.close();
  });
}

void writeTable(const std::string& path, const std::vector<std::string>& names, const Matrix& data,
                int precision, const Metadata& metadata) {
  if (static_cast<Eigen::Index>(names.size()) != data.cols())
    throw std::logic_error("writeTable: " + std::to_string(names.size()) + " names for " +
                           std::to_string(data.cols()) + " columns");
  if (io::lowerExtension(path) == ".mat") {
    io::MatWriter mat(path);
    writeMetadata(mat, metadata);
    for (std::size_t c = 0; c < names.size(); ++c)
      mat.writeMatrix(names[c], data.col(static_cast<Eigen::Index>(c)));
    mat.close();
    return;
  }
  io::AtomicTextFile csv(path);
  std::ostream& out = csv.stream();
  for (std::size_t c = 0; c < names.size(); ++c)
    out << (c ? "," : "") << names[c];
  out << "\n";
  // Row by row through one buffer: the stream's own formatting of each number costs about 0.6 us,
  // 18 s of a 312 s run's table; to_chars writes the same text (appendGeneral).
  std::string row;
  for (Eigen::Index k = 0; k < data.rows(); ++k) {
    row.clear();
    for (Eigen::Index j = 0; j < data.cols(); ++j) {
      if (j)
        row += ',';
      io::appendGeneral(row, data(k, j), precision);
    }
    row += '\n';
    out.write(row.data(), static_cast<std::streamsize>(row.size()));
  }
  csv.commit();
}

void OutputFileSet::write(const std::string& path,
                          const std::function<void(const std::string&)>& write) {
  for (const auto& entry : staged_)
    if (entry.second == path)
      throw std::logic_error("OutputFileSet: " + path + " written twice");
  // A name of its own, "modes~Ab3xYz.csv" (the extension chooses the format): two runs writing
  // one file never write the same staged one. Short: the writer's own temporary adds 8 more
  // characters, and the two stay within the 17 or so the older names added (a name near
  // NAME_MAX, 255 bytes, that worked still works).
  std::filesystem::path stem(path);
  const std::string extension = stem.extension().string();
  stem.replace_extension();
  std::string staged;
  try {
    staged = io::createTemporaryBeside(stem.string(), extension, "~");
  } catch (const InputError& e) {
    std::string message = e.what();  // "cannot write <stem>: why": name the file asked for
    const std::string named = "cannot write " + stem.string();
    if (message.rfind(named, 0) == 0)
      message.replace(0, named.size(), "cannot write " + path);
    throw InputError(message);
  }
  staged_.emplace_back(staged, path);
  try {
    write(staged);
  } catch (const InputError& e) {
    // The user asked for `path`: name it, not the staged file (which is removed).
    std::string message = e.what();
    for (std::size_t at = message.find(staged); at != std::string::npos;
         at = message.find(staged, at + path.size()))
      message.replace(at, staged.size(), path);
    throw InputError(message);
  }
}

void OutputFileSet::commit() {
  // A name taken by a directory fails every rename onto it: found before any file is replaced.
  for (const auto& [staged, path] : staged_)
    if (std::filesystem::is_directory(path))
      throw InputError(path + ": is a directory; cannot write the file there");
  for (const auto& [staged, path] : staged_)
    if (io::renameStagedFile(staged, path) != 0)
      throw InputError(path + ": cannot move the written file into place: " + std::strerror(errno));
  committed_ = true;
}

OutputFileSet::~OutputFileSet() {
  if (committed_)
    return;
  for (const auto& staged : staged_)
    io::removeStagedFile(staged.first);
}

std::string defaultCacheDir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  // The XDG base directory specification: a relative value is invalid and ignored (it would put
  // the cache wherever the command happens to run).
  if (xdg && *xdg == '/')
    return std::string(xdg) + "/tracked_vehicle_dynamics";
  if (home && *home)
    return std::string(home) + "/.cache/tracked_vehicle_dynamics";
  return "/tmp/tracked_vehicle_dynamics";
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics

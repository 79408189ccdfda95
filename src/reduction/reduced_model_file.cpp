#include "tracked_vehicle_dynamics/reduction/reduced_model_file.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/fnv1a.h"
#include "tracked_vehicle_dynamics/io/mat_file.h"
#include "tracked_vehicle_dynamics/io/utf8.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

namespace {

// Node ids and mode numbers travel as doubles; they are exact below 2^53.
constexpr double kMaxExactInteger = 9007199254740992.0;
// Negative LDL^T pivots of C_R beyond this share of the largest are a damping that feeds energy
// in, not round-off (the zero C_R of an undamped model passes).
constexpr double kDampingDefiniteness = 1e-9;

// One variable of the file, in file order (the checksum depends on the order).
// A model's matrices are referred to, not copied (7 MB of a tracked model, at every load's
// checksum): the model outlives the variables.
struct Variable {
  std::string name;
  enum class Kind { Numeric, Text, TextList } kind = Kind::Numeric;
  const Matrix* numeric_of_model = nullptr;  // or
  Matrix numeric_built;                      // built for the file (a column, a table)
  std::string text;
  std::vector<std::string> texts;

  const Matrix& numeric() const { return numeric_of_model ? *numeric_of_model : numeric_built; }
};

Variable numeric(const std::string& name, Matrix value) {
  Variable v;
  v.name = name;
  v.numeric_built = std::move(value);
  return v;
}
Variable numericOfModel(const std::string& name, const Matrix& value) {
  Variable v;
  v.name = name;
  v.numeric_of_model = &value;
  return v;
}
Variable text(const std::string& name, const std::string& value) {
  Variable v;
  v.name = name;
  v.kind = Variable::Kind::Text;
  v.text = value;
  return v;
}
Variable texts(const std::string& name, const std::vector<std::string>& value) {
  Variable v;
  v.name = name;
  v.kind = Variable::Kind::TextList;
  v.texts = value;
  return v;
}

Matrix column(const Vector& v) {
  return v.size() ? Matrix(v) : Matrix(0, 1);
}

// The variables refer to the model's matrices: never of a temporary.
std::vector<Variable> toVariables(const ReducedModel&& model) = delete;
std::vector<Variable> toVariables(const ReducedModel& model) {
  const dynamics::SecondOrderSystem& s = model.system;
  Matrix masters(model.masterCount(), 2);
  for (DofIndex i = 0; i < model.masterCount(); ++i) {
    masters(i, 0) = static_cast<double>(model.masters[static_cast<std::size_t>(i)].node);
    masters(i, 1) = model.masters[static_cast<std::size_t>(i)].direction;
  }
  const auto selected = static_cast<DofIndex>(model.selected_modes.size());
  Matrix numbers(selected, 1), frequencies(selected, 1);
  std::vector<std::string> reasons;
  for (DofIndex i = 0; i < selected; ++i) {
    const SelectedMode& mode = model.selected_modes[static_cast<std::size_t>(i)];
    numbers(i, 0) = mode.mode + 1;
    frequencies(i, 0) = mode.frequency_hz;
    reasons.push_back(mode.reason);
  }
  return {
      numeric("format_version", Matrix::Constant(1, 1, kReducedModelFormatVersion)),
      text("version", model.version),
      text("description_hash", model.description_hash),
      text("reduction", model.reduction),
      text("created_utc", model.created_utc),
      text("creator", model.creator),
      text("damping_model", model.damping),
      numeric("full_dof_count", Matrix::Constant(1, 1, static_cast<double>(model.full_dof_count))),
      numericOfModel("M_R", s.mass),
      numericOfModel("K_R", s.stiffness),
      numericOfModel("C_R", s.damping),
      numericOfModel("K_u", s.input_stiffness),
      numericOfModel("C_u", s.input_damping),
      numeric("gravity_load", column(model.gravity_load)),
      numeric("travel_load", column(model.travel_load)),
      numericOfModel("H", s.output),
      texts("output_names", s.output_names),
      texts("dof_labels", model.dof_labels),
      texts("input_labels", model.input_labels),
      numeric("input_stations", column(s.input_stations)),
      numeric("input_lateral", column(s.input_lateral)),
      numeric("masters", std::move(masters)),
      numericOfModel("master_positions", model.master_positions),
      texts("master_groups", model.master_groups),
      numeric("fixed_interface_frequencies_hz", column(model.fixed_interface_frequencies_hz)),
      numeric("selected_mode_numbers", std::move(numbers)),
      numeric("selected_mode_frequencies_hz", std::move(frequencies)),
      texts("selected_mode_reasons", reasons),
      texts("reduction_warnings", model.warnings)};
}

// FNV-1a, 64 bit (io/fnv1a.h). Numbers enter as little-endian bytes whatever the host's order, so a
// file checks the same on every machine (doc/reduced_model_file.md gives the encoding).
class Checksum {
 public:
  void add(const void* data, std::size_t bytes) { hash_ = io::fnv1a(data, bytes, hash_); }
  void add(const std::string& s) {
    add(static_cast<std::uint64_t>(s.size()));
    add(s.data(), s.size());
  }
  void add(std::uint64_t v) {
    unsigned char bytes[8];
    for (int i = 0; i < 8; ++i)
      bytes[i] = static_cast<unsigned char>(v >> (8 * i));
    add(bytes, sizeof(bytes));
  }
  // IEEE-754 doubles, each as its 8 little-endian bytes.
  void add(const double* values, std::size_t count) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    add(static_cast<const void*>(values), sizeof(double) * count);
#else
    for (std::size_t i = 0; i < count; ++i) {
      std::uint64_t bits;
      std::memcpy(&bits, &values[i], sizeof(bits));
      add(bits);
    }
#endif
  }
  std::string hex() const {
    char buffer[17];
    std::snprintf(buffer, sizeof(buffer), "%016llx", static_cast<unsigned long long>(hash_));
    return buffer;
  }

 private:
  std::uint64_t hash_ = io::kFnv1aOffset;
};

std::string checksum(const std::vector<Variable>& variables) {
  Checksum c;
  for (const Variable& v : variables) {
    c.add(v.name);
    c.add(static_cast<std::uint64_t>(v.kind));
    switch (v.kind) {
      case Variable::Kind::Numeric:
        c.add(static_cast<std::uint64_t>(v.numeric().rows()));
        c.add(static_cast<std::uint64_t>(v.numeric().cols()));
        c.add(v.numeric().data(), static_cast<std::size_t>(v.numeric().size()));
        break;
      // Over the text the file holds and reads back (utf8.h). The texts are ASCII in practice
      // (labels, identifiers, hashes), the same bytes either way; should one ever hold a byte of
      // no UTF-8 character, the file stores U+FFFD for it and the checksum must cover that.
      case Variable::Kind::Text:
        c.add(io::validUtf8(v.text));
        break;
      case Variable::Kind::TextList:
        c.add(static_cast<std::uint64_t>(v.texts.size()));
        for (const std::string& s : v.texts)
          c.add(io::validUtf8(s));
        break;
    }
  }
  return c.hex();
}

std::string dims(const Matrix& a) {
  return std::to_string(a.rows()) + "x" + std::to_string(a.cols());
}

void checkSize(const std::string& where, const char* name, const Matrix& a, DofIndex rows,
               DofIndex cols) {
  if (a.rows() != rows || a.cols() != cols)
    throw InputError(where + ": " + name + " is " + dims(a) + ", expected " + std::to_string(rows) +
                     "x" + std::to_string(cols));
}

void checkCount(const std::string& where, const char* name, std::size_t count, DofIndex expected) {
  if (static_cast<DofIndex>(count) != expected)
    throw InputError(where + ": " + name + " has " + std::to_string(count) + " entries, expected " +
                     std::to_string(expected));
}

void checkSymmetric(const std::string& where, const char* name, const Matrix& a, double tolerance) {
  const double scale = a.cwiseAbs().maxCoeff();
  const double asymmetry = (a - a.transpose()).cwiseAbs().maxCoeff();
  if (asymmetry > tolerance * scale)
    throw InputError(where + ": " + name + " is not symmetric (max |A - A^T| = " +
                     brief(asymmetry) + " for max |A| = " + brief(scale) + ")");
}

// Everything a usable model must satisfy; `where` starts each message (the file name).
void checkConsistency(const ReducedModel& model, const std::string& where,
                      double symmetry_tolerance) {
  const dynamics::SecondOrderSystem& s = model.system;
  const DofIndex k = s.mass.rows();
  const DofIndex inputs = s.input_stiffness.cols();
  if (k == 0)
    throw InputError(where + ": M_R is empty");
  checkSize(where, "M_R", s.mass, k, k);
  checkSize(where, "K_R", s.stiffness, k, k);
  checkSize(where, "C_R", s.damping, k, k);
  checkSize(where, "K_u", s.input_stiffness, k, inputs);
  checkSize(where, "C_u", s.input_damping, k, inputs);
  checkSize(where, "H", s.output, s.output.rows(), k);
  checkCount(where, "gravity_load", static_cast<std::size_t>(model.gravity_load.size()), k);
  checkCount(where, "travel_load", static_cast<std::size_t>(model.travel_load.size()), k);
  checkCount(where, "output_names", s.output_names.size(), s.output.rows());
  checkCount(where, "dof_labels", model.dof_labels.size(), k);
  checkCount(where, "input_labels", model.input_labels.size(), inputs);
  if (s.input_stations.size() != 0 || s.input_lateral.size() != 0) {
    checkCount(where, "input_stations", static_cast<std::size_t>(s.input_stations.size()), inputs);
    checkCount(where, "input_lateral", static_cast<std::size_t>(s.input_lateral.size()), inputs);
  }
  if (model.masterCount() + model.modeCount() != k)
    throw InputError(where + ": " + std::to_string(model.masterCount()) + " masters and " +
                     std::to_string(model.modeCount()) + " fixed-interface modes for " +
                     std::to_string(k) + " reduced coordinates");
  checkSize(where, "master_positions", model.master_positions, model.masterCount(), 3);
  checkCount(where, "master_groups", model.master_groups.size(),
             static_cast<std::size_t>(model.masterCount()));
  for (const fem::DofRef& d : model.masters)
    if (d.direction < 0 || d.direction >= kDofsPerNode)
      throw InputError(where + ": master of node " + std::to_string(d.node) + " has direction " +
                       std::to_string(d.direction));
  for (const Matrix* a :
       {&s.mass, &s.stiffness, &s.damping, &s.input_stiffness, &s.input_damping, &s.output})
    if (!a->allFinite())
      throw InputError(where + ": a system matrix has a non-finite entry");
  if (!model.gravity_load.allFinite() || !model.travel_load.allFinite())
    throw InputError(where + ": gravity_load or travel_load has a non-finite entry");
  checkSymmetric(where, "M_R", s.mass, symmetry_tolerance);
  checkSymmetric(where, "K_R", s.stiffness, symmetry_tolerance);
  checkSymmetric(where, "C_R", s.damping, symmetry_tolerance);
  if (Eigen::LLT<Matrix>(s.mass).info() != Eigen::Success)
    throw InputError(where + ": M_R is not positive definite");
  // A vehicle on its ground springs has no free motion, and damping dissipates: a file whose
  // checksum holds but whose K_R or C_R does not is refused here, naming the file, rather than
  // by the solver that first meets it.
  if (Eigen::LLT<Matrix>(s.stiffness).info() != Eigen::Success)
    throw InputError(where +
                     ": K_R is not positive definite (a vehicle on its ground springs "
                     "has no free motion)");
  const Eigen::LDLT<Matrix> damping(s.damping);  // k x k: checkSize above
  const double scale = damping.vectorD().cwiseAbs().maxCoeff();
  if (damping.info() != Eigen::Success ||
      damping.vectorD().minCoeff() < -kDampingDefiniteness * scale)
    throw InputError(where +
                     ": C_R is not positive semi-definite (damping that feeds energy "
                     "in)");
}

double integer(const std::string& where, const char* name, double value) {
  if (value != std::floor(value) || std::abs(value) > kMaxExactInteger)
    throw InputError(where + ": " + name + " holds " + brief(value) + ", not an integer");
  return value;
}

// The same, read into an int: a damaged file's 1e15 is refused here (a cast would be undefined
// behaviour before the checksum is even compared).
int intValue(const std::string& where, const char* name, double value) {
  const double v = integer(where, name, value);
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
    throw InputError(where + ": " + name + " holds " + brief(value) + ", beyond an int's range");
  return static_cast<int>(v);
}

Vector vectorOf(const io::MatReader& in, const std::string& name) {
  const Matrix m = in.readMatrix(name, io::kAnySize, 1);
  return m.col(0);
}

ReducedModel readModel(const io::MatReader& in, const std::string& expected_hash,
                       const ReducedModelLoadOptions& options) {
  const std::string& where = in.path();
  // The checks of where the file comes from first: they give the most useful message.
  // A file cut right after its 128-byte header reads as a valid MAT file holding nothing.
  if (in.names().empty())
    throw InputError(where +
                     ": holds no variables (an empty MAT file, or one cut after its 128-byte "
                     "header: an interrupted write?)");
  // A .mat of another command (tvd frf, statics, modes) lacks the model's marker altogether.
  // MATLAB's and Octave's save without -struct keep the loaded struct as one variable.
  if (!in.has("format_version") && in.names().size() == 1 &&
      in.className(in.names().front()) == "struct")
    throw InputError(where + ": holds one struct '" + in.names().front() +
                     "' and no variable 'format_version': saved without -struct? Save its "
                     "fields as variables: save(FILE, '-struct', '" +
                     in.names().front() + "', '-v7')");
  if (!in.has("format_version"))
    throw InputError(where +
                     ": not a reduced model file (no variable 'format_version'; written "
                     "by tvd frf, statics or modes?)");
  const double format = in.readScalar("format_version");
  if (format != kReducedModelFormatVersion)
    throw InputError(where + ": file format version " + beyond(format, kReducedModelFormatVersion) +
                     ", this software reads version " + std::to_string(kReducedModelFormatVersion));
  ReducedModel model;
  model.version = in.readString("version");
  // The release is the version before '+', the build (commit) after it.
  const auto release = [](const std::string& v) { return v.substr(0, v.find('+')); };
  std::string other_build;
  if (model.version != softwareVersion()) {
    if (options.require_same_version ||
        (options.require_same_release && release(model.version) != release(softwareVersion())))
      throw InputError(where + ": written by version " + model.version + ", this is version " +
                       softwareVersion());
    const bool same_release = release(model.version) == release(softwareVersion());
    other_build = where + ": written by " +
                  (same_release ? "build " + model.version + " of this release"
                                : "version " + model.version) +
                  ", this is " + softwareVersion() +
                  ": taken; if the reduction changed between them, tvd reduce writes it again";
  }
  model.description_hash = in.readString("description_hash");
  if (model.description_hash != expected_hash)
    throw InputError(where + ": reduced from another description (description hash " +
                     model.description_hash + ", this one's " + expected_hash + ")");
  if (!in.has("checksum"))
    throw InputError(where +
                     ": incomplete file: the final 'checksum' variable is missing "
                     "(truncated or interrupted write)");
  model.reduction = in.readString("reduction");
  if (!options.expected_reduction.empty() && model.reduction != options.expected_reduction)
    throw InputError(where + ": reduced as '" + model.reduction + "', expected '" +
                     options.expected_reduction + "'");

  model.created_utc = in.readString("created_utc");
  model.creator = in.readString("creator");
  model.damping = in.readString("damping_model");
  model.full_dof_count =
      static_cast<DofIndex>(integer(where, "full_dof_count", in.readScalar("full_dof_count")));
  dynamics::SecondOrderSystem& s = model.system;
  s.mass = in.readMatrix("M_R");
  s.stiffness = in.readMatrix("K_R");
  s.damping = in.readMatrix("C_R");
  s.input_stiffness = in.readMatrix("K_u");
  s.input_damping = in.readMatrix("C_u");
  model.gravity_load = vectorOf(in, "gravity_load");
  model.travel_load = vectorOf(in, "travel_load");
  s.output = in.readMatrix("H");
  s.output_names = in.readStrings("output_names");
  model.dof_labels = in.readStrings("dof_labels");
  model.input_labels = in.readStrings("input_labels");
  s.input_stations = vectorOf(in, "input_stations");
  s.input_lateral = vectorOf(in, "input_lateral");
  const Matrix masters = in.readMatrix("masters", io::kAnySize, 2);
  for (DofIndex i = 0; i < masters.rows(); ++i)
    model.masters.push_back(
        fem::DofRef{static_cast<NodeId>(integer(where, "masters", masters(i, 0))),
                    intValue(where, "masters", masters(i, 1))});
  model.master_positions = in.readMatrix("master_positions", masters.rows(), 3);
  model.master_groups = in.readStrings("master_groups", masters.rows());
  model.fixed_interface_frequencies_hz = vectorOf(in, "fixed_interface_frequencies_hz");
  const Vector numbers = vectorOf(in, "selected_mode_numbers");
  const Vector frequencies = vectorOf(in, "selected_mode_frequencies_hz");
  const std::vector<std::string> reasons = in.readStrings("selected_mode_reasons", numbers.size());
  if (frequencies.size() != numbers.size())
    throw InputError(where + ": " + std::to_string(numbers.size()) + " selected modes but " +
                     std::to_string(frequencies.size()) + " frequencies");
  for (DofIndex i = 0; i < numbers.size(); ++i) {
    const int number = intValue(where, "selected_mode_numbers", numbers(i));
    if (number < 1)
      throw InputError(where + ": selected_mode_numbers has mode " + std::to_string(number));
    model.selected_modes.push_back(
        SelectedMode{number - 1, frequencies(i), reasons[static_cast<std::size_t>(i)]});
  }
  model.warnings = in.readStrings("reduction_warnings");
  checkConsistency(model, where, options.symmetry_tolerance);
  const std::string stored = in.readString("checksum");
  const std::string computed = checksum(toVariables(model));
  if (stored != computed)
    throw InputError(where + ": corrupted: checksum " + computed +
                     " of the content differs from "
                     "the stored " +
                     stored);
  if (!other_build.empty())
    model.warnings.push_back(other_build);  // after the checksum, which covers the stored ones
  return model;
}

}  // namespace

void saveReducedModel(const ReducedModel& model, const std::string& path) {
  checkConsistency(model, path + " (saving)", ReducedModelLoadOptions{}.symmetry_tolerance);
  const std::vector<Variable> variables = toVariables(model);
  // Uncompressed: the cache is read at every start-up, and inflating it cost more than reading
  // the ~7 MB of a tracked model.
  io::MatWriter out(path, io::MatFormat::Mat5, /*compress=*/false);
  for (const Variable& v : variables) {
    switch (v.kind) {
      case Variable::Kind::Numeric:
        out.writeMatrix(v.name, v.numeric());
        break;
      case Variable::Kind::Text:
        out.writeString(v.name, v.text);
        break;
      case Variable::Kind::TextList:
        out.writeStrings(v.name, v.texts);
        break;
    }
  }
  out.writeString("checksum", checksum(variables));
  out.close();
}

ReducedModel loadReducedModel(const std::string& path, const std::string& expected_hash,
                              const ReducedModelLoadOptions& options) {
  try {
    const io::MatReader in(path);
    return readModel(in, expected_hash, options);
  } catch (const StaleCacheError&) {
    throw;
  } catch (const InputError& e) {
    throw StaleCacheError(e.what());
  }
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics

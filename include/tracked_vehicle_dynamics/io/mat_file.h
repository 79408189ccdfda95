// A narrow wrapper around matio (STYLE.md #9): named real double matrices, scalars, strings and
// string lists (cell arrays of char) in a MAT file that MATLAB, Octave and SciPy
// (scipy.io.loadmat, MAT 5 only) can read.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/types.h"

struct matvar_t;  // matio.h: a variable (header and data)

namespace tracked_vehicle_dynamics {
namespace io {

/// MAT file flavour. Mat5 is the default because scipy.io.loadmat reads it; Mat73 (HDF5) is for
/// variables over 2 GB and needs h5py on the Python side.
enum class MatFormat { Mat5, Mat73 };

/// Any size in a MatReader dimension check.
constexpr DofIndex kAnySize = -1;

/// Writes a MAT file. The data go to a temporary file next to `path` that close() renames onto
/// `path`, so a crash or an exception never leaves a half-written file under the final name (the
/// caller's cache stays either old or new). Variable names must be valid MATLAB identifiers
/// (a letter, then letters, digits or '_', at most 63 characters) and unique in the file.
class MatWriter {
 public:
  /// Throws InputError naming the file when it cannot be created.
  explicit MatWriter(const std::string& path, MatFormat format = MatFormat::Mat5,
                     bool compress = true);
  /// Without a successful close() the temporary file is removed and `path` is left untouched.
  ~MatWriter();
  MatWriter(const MatWriter&) = delete;
  MatWriter& operator=(const MatWriter&) = delete;

  /// A real double matrix (any size, including 0 x n). Throws InputError on a bad or repeated
  /// name or a write failure.
  void writeMatrix(const std::string& name, const Matrix& value);
  /// A real double sparse matrix (MATLAB's sparse class; scipy.io.loadmat gives a csc_matrix):
  /// the stored entries as they are, explicit zeros included. Throws InputError on a bad or
  /// repeated name, more than 2^32 - 1 entries or rows (the format's 32-bit indices), or a
  /// write failure.
  void writeSparse(const std::string& name, const SparseMatrix& value);
  /// A 1 x 1 double.
  void writeScalar(const std::string& name, double value);
  /// A 1 x n char array of the UTF-16 code units of UTF-8 `value` ('' as 0 x 0).
  void writeString(const std::string& name, const std::string& value);
  /// An n x 1 cell array of 1 x k char arrays.
  void writeStrings(const std::string& name, const std::vector<std::string>& values);
  /// Closes the file, checks that a MAT 5 file holds every variable written, whole (matio drops
  /// a failed write: a full disk or a file size limit left it cut short), and renames it onto
  /// `path`. Throws InputError naming `path` when a step fails ("the file written is incomplete"
  /// for a cut); nothing is put in place then.
  void close();

  const std::string& path() const { return path_; }

 private:
  struct Impl;
  void checkName(const std::string& name);
  std::unique_ptr<Impl> impl_;
  std::string path_;
};

/// Reads a MAT file (MAT 5 or 7.3). Every read checks presence, class (real double or char),
/// dimensions and finiteness, and throws InputError with a message that starts with the file
/// name and names the variable, e.g. "cache.mat: variable 'K_R' is 12x11, expected 12x12".
class MatReader {
 public:
  /// Throws InputError when the file does not exist, cannot be read, is not a MAT file, or (MAT
  /// 5) its variable records run past the end of the file (a truncated file).
  explicit MatReader(const std::string& path);
  ~MatReader();
  MatReader(const MatReader&) = delete;
  MatReader& operator=(const MatReader&) = delete;

  const std::string& path() const { return path_; }
  /// Names of the variables in file order (MATLAB class objects, e.g. strings, left out: matio
  /// cannot read them).
  const std::vector<std::string>& names() const { return names_; }
  bool has(const std::string& name) const;
  /// A variable's class as MATLAB names it: "double", "single", "int32", "char", "cell",
  /// "struct", "sparse", "logical", "complex double", ... (InputError when there is none).
  std::string className(const std::string& name) const;

  /// A real, finite double matrix; `rows`/`cols` are checked unless kAnySize.
  Matrix readMatrix(const std::string& name, DofIndex rows = kAnySize,
                    DofIndex cols = kAnySize) const;
  /// A finite 1 x 1 double.
  double readScalar(const std::string& name) const;
  /// A char array with at most one row (UTF-8; UTF-16 data are converted).
  std::string readString(const std::string& name) const;
  /// A cell array (any shape, read in column order) of strings; `count` is checked unless
  /// kAnySize.
  std::vector<std::string> readStrings(const std::string& name, DofIndex count = kAnySize) const;

 private:
  /// The header of a variable read when the file was opened (InputError when there is none),
  /// with its data read when `with_data` (once).
  const matvar_t* header(const std::string& name, bool with_data) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_;
  std::vector<std::string> names_;
  int objects_passed_over_ = 0;  // MATLAB class objects and function handles, not listed
};

}  // namespace io
}  // namespace tracked_vehicle_dynamics

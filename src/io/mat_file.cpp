#include "tracked_vehicle_dynamics/io/mat_file.h"

#include <hdf5.h>
#include <matio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <new>
#include <set>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/atomic_file.h"
#include "tracked_vehicle_dynamics/io/mat_structure.h"
#include "tracked_vehicle_dynamics/io/staged_files.h"
#include "tracked_vehicle_dynamics/io/utf8.h"

namespace tracked_vehicle_dynamics {
namespace io {

namespace {

constexpr const char* kMat5HeaderText = "MATLAB 5.0 MAT-file, written by tracked_vehicle_dynamics";

std::string dims(std::size_t rows, std::size_t cols) {
  return std::to_string(rows) + "x" + std::to_string(cols);
}

struct VarDeleter {
  void operator()(matvar_t* v) const {
    if (v)
      Mat_VarFree(v);
  }
};
using VarPtr = std::unique_ptr<matvar_t, VarDeleter>;

}  // namespace

// ---------------------------------------------------------------------------------------------
// MatWriter
// ---------------------------------------------------------------------------------------------

struct MatWriter::Impl {
  mat_t* mat = nullptr;
  bool mat5 = true;
  std::string temporary;
  matio_compression compression = MAT_COMPRESSION_NONE;
  std::set<std::string> names;

  void write(matvar_t* var, const std::string& name, const std::string& path) {
    if (!var)
      throw InputError(path + ": cannot create variable '" + name + "' (matio)");
    VarPtr owned(var);
    if (Mat_VarWrite(mat, var, compression) != 0)
      throw InputError(path + ": cannot write variable '" + name +
                       "' (disk full or not writable?)");
  }
};

MatWriter::MatWriter(const std::string& path, MatFormat format, bool compress)
    : impl_(std::make_unique<Impl>()), path_(path) {
  impl_->temporary = createTemporaryBeside(path);  // matio reopens (truncates) the empty file
  impl_->compression = compress ? MAT_COMPRESSION_ZLIB : MAT_COMPRESSION_NONE;
  impl_->mat5 = format != MatFormat::Mat73;
  impl_->mat = Mat_CreateVer(impl_->temporary.c_str(), kMat5HeaderText,
                             format == MatFormat::Mat73 ? MAT_FT_MAT73 : MAT_FT_MAT5);
  if (!impl_->mat) {
    removeStagedFile(impl_->temporary);
    throw InputError(path + ": cannot create the file (directory missing or not writable?)");
  }
}

MatWriter::~MatWriter() {
  if (impl_->mat) {
    Mat_Close(impl_->mat);
    removeStagedFile(impl_->temporary);
  }
}

void MatWriter::checkName(const std::string& name) {
  if (!impl_->mat)
    throw InputError(path_ + ": write after close()");
  if (!isMatIdentifier(name))
    throw InputError(path_ + ": '" + name +
                     "' is not a valid MAT variable name (a letter, then letters, digits or _, "
                     "at most 63 characters)");
  if (!impl_->names.insert(name).second)
    throw InputError(path_ + ": variable '" + name + "' written twice");
}

void MatWriter::writeMatrix(const std::string& name, const Matrix& value) {
  checkName(name);
  std::size_t d[2] = {static_cast<std::size_t>(value.rows()),
                      static_cast<std::size_t>(value.cols())};
  void* data = value.size() ? const_cast<double*>(value.data()) : nullptr;
  impl_->write(
      Mat_VarCreate(name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, d, data, MAT_F_DONT_COPY_DATA),
      name, path_);
}

void MatWriter::writeSparse(const std::string& name, const SparseMatrix& value) {
  checkName(name);
  // MAT 5 keeps compressed columns with 32-bit row indices (ir) and column starts (jc).
  constexpr auto kMaxIndex = static_cast<Eigen::Index>(std::numeric_limits<mat_uint32_t>::max());
  if (value.nonZeros() > kMaxIndex || value.rows() > kMaxIndex || value.cols() >= kMaxIndex)
    throw InputError(path_ + ": variable '" + name + "' is too large for a MAT file's sparse " +
                     "matrix (" + std::to_string(value.nonZeros()) + " entries)");
  std::vector<mat_uint32_t> ir, jc(static_cast<std::size_t>(value.cols()) + 1, 0);
  std::vector<double> data;
  ir.reserve(static_cast<std::size_t>(value.nonZeros()));
  data.reserve(ir.capacity());
  for (Eigen::Index c = 0; c < value.outerSize(); ++c) {
    for (SparseMatrix::InnerIterator it(value, c); it; ++it) {
      ir.push_back(static_cast<mat_uint32_t>(it.row()));
      data.push_back(it.value());
    }
    jc[static_cast<std::size_t>(c) + 1] = static_cast<mat_uint32_t>(ir.size());
  }
  // MATLAB allocates at least one entry (nzmax >= 1), also for an all-zero matrix.
  if (ir.empty()) {
    ir.push_back(0);
    data.push_back(0.0);
  }
  mat_sparse_t sparse{};
  sparse.nzmax = static_cast<mat_uint32_t>(ir.size());
  sparse.ir = ir.data();
  sparse.nir = jc.back();
  sparse.jc = jc.data();
  sparse.njc = static_cast<mat_uint32_t>(jc.size());
  sparse.ndata = jc.back();
  sparse.data = data.data();
  std::size_t d[2] = {static_cast<std::size_t>(value.rows()),
                      static_cast<std::size_t>(value.cols())};
  impl_->write(
      Mat_VarCreate(name.c_str(), MAT_C_SPARSE, MAT_T_DOUBLE, 2, d, &sparse, MAT_F_DONT_COPY_DATA),
      name, path_);
}

void MatWriter::writeScalar(const std::string& name, double value) {
  writeMatrix(name, Matrix::Constant(1, 1, value));
}

namespace {
// A 1 x n char array of UTF-16 code units, as MATLAB writes text (utf8.h): n counts characters
// (code units), not bytes, so accented names and paths read back whole in MATLAB, Octave and
// SciPy. The units are copied into the variable (they live only in this call).
matvar_t* charVariable(const char* name, const std::string& value) {
  std::vector<std::uint16_t> units = utf8ToUtf16(value);
  // MATLAB writes '' as 0x0; a 1x0 char would read back as a 1x0 array.
  std::size_t d[2] = {units.empty() ? 0u : 1u, units.size()};
  void* data = units.empty() ? nullptr : units.data();
  return Mat_VarCreate(name, MAT_C_CHAR, MAT_T_UINT16, 2, d, data, 0);
}
}  // namespace

void MatWriter::writeString(const std::string& name, const std::string& value) {
  checkName(name);
  impl_->write(charVariable(name.c_str(), value), name, path_);
}

void MatWriter::writeStrings(const std::string& name, const std::vector<std::string>& values) {
  checkName(name);
  std::size_t d[2] = {values.size(), 1};
  matvar_t* cell = Mat_VarCreate(name.c_str(), MAT_C_CELL, MAT_T_CELL, 2, d, nullptr, 0);
  if (!cell)
    throw InputError(path_ + ": cannot create variable '" + name + "' (matio)");
  VarPtr owned(cell);
  for (std::size_t i = 0; i < values.size(); ++i) {
    // Copied: the cell owns its elements and frees them with itself.
    matvar_t* element = charVariable(nullptr, values[i]);
    if (!element)
      throw InputError(path_ + ": cannot create '" + name + "'{" + std::to_string(i + 1) + "}");
    Mat_VarSetCell(cell, static_cast<int>(i), element);
  }
  impl_->write(owned.release(), name, path_);
}

void MatWriter::close() {
  if (!impl_->mat)
    throw InputError(path_ + ": close() called twice");
  const int status = Mat_Close(impl_->mat);
  impl_->mat = nullptr;
  if (status != 0) {
    removeStagedFile(impl_->temporary);
    throw InputError(path_ + ": error while closing the file (disk full?)");
  }
  // matio reports no failed write (fwrite's ENOSPC is dropped and the file closes clean): a full
  // disk put an empty or truncated file in place, status 0 (review 166). Checked here, on the
  // file's own layout; a 7.3 file's HDF5 library reports its errors.
  if (impl_->mat5) {
    // The top-level elements must end at the file's last byte and be as many as the variables.
    std::string why;
    try {
      const std::size_t written = countMat5Variables(impl_->temporary);
      if (written != impl_->names.size())
        why = std::to_string(written) + " of the " + std::to_string(impl_->names.size()) +
              " variables";
    } catch (const InputError&) {
      struct stat info = {};
      const long long size = ::stat(impl_->temporary.c_str(), &info) == 0 ? info.st_size : 0;
      why = std::to_string(size) + " bytes, ending inside a variable";
    }
    if (!why.empty()) {
      removeStagedFile(impl_->temporary);
      throw InputError(path_ + ": the file written is incomplete (" + why +
                       "): disk full or a file size limit? no file written");
    }
  }
  if (renameStagedFile(impl_->temporary, path_) != 0) {
    removeStagedFile(impl_->temporary);
    throw InputError(path_ + ": cannot move the written file into place");
  }
}

// ---------------------------------------------------------------------------------------------
// MatReader
// ---------------------------------------------------------------------------------------------

// HDF5 prints its error stack to stderr on every failed call (a damaged 7.3 file gives dozens of
// lines); the reader reports the failure itself in one message, so the printing is off while
// it calls matio and restored afterwards. The handler is the calling thread's in a thread-safe
// HDF5 build (Debian's), the process's otherwise, where readers on two threads could leave it
// off.
namespace {
class QuietHdf5 {
 public:
  QuietHdf5() {
    saved_ = H5Eget_auto2(H5E_DEFAULT, &function_, &data_) >= 0;
    if (saved_)
      H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() {
    if (saved_)
      H5Eset_auto2(H5E_DEFAULT, function_, data_);
  }
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;

 private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
  bool saved_ = false;
};

// Whether a MAT 7.3 file is a sound HDF5 file whose root group holds nothing: a valid file
// without variables, where a damaged one lists none because HDF5 cannot read it (it does not
// open, or its root group cannot be read).
bool emptyMat73(const std::string& path) {
  const QuietHdf5 quiet;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0)
    return false;
  H5G_info_t root{};
  const bool empty = H5Gget_info(file, &root) >= 0 && root.nlinks == 0;
  H5Fclose(file);
  return empty;
}

}  // namespace

// The variables' headers are read once, in file order, when the file is opened. matio's reads by
// name (Mat_VarRead, Mat_VarReadInfo) rewind and walk every header before the one they look for,
// and a compressed cell's walk inflates the header of each of its elements: loading a reduced model
// (30 variables, three cells of 360-431 strings) that way made 19,000 seeks and 4,600 reads, most
// of the load time. Data is read from the kept header: numeric values into our own buffer on each
// request, text once (kept for a second request).
struct MatReader::Impl {
  mat_t* mat = nullptr;
  std::vector<VarPtr> headers;  // file order, as names_
  std::vector<char> data_read;  // the header's data has been read (text variables)
  ~Impl() {
    const QuietHdf5 quiet;  // closing a damaged 7.3 file fails in HDF5 too
    headers.clear();        // before the file they refer to is closed
    if (mat)
      Mat_Close(mat);
  }
};

MatReader::MatReader(const std::string& path) : impl_(std::make_unique<Impl>()), path_(path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0)
    throw InputError(path + ": file does not exist");
  if (!S_ISREG(info.st_mode))
    throw InputError(path + ": not a regular file");
  const bool mat73 = checkMatStructure(path) == MatFormat::Mat73;
  // A damaged 7.3 file may still open (its MAT header is intact) and then list no variable:
  // said here, not later as "variable '...' is missing". A MAT 5 file is walked above.
  const std::string damaged73 = path + ": a damaged or truncated MAT 7.3 (HDF5) file";
  const QuietHdf5 quiet;
  impl_->mat = Mat_Open(path.c_str(), MAT_ACC_RDONLY);
  if (!impl_->mat)
    throw InputError(mat73 ? damaged73 + " (HDF5 cannot open it)"
                           : path + ": not a readable MAT file");
  if (Mat_Rewind(impl_->mat) != 0)
    throw InputError(path + ": the list of variables cannot be read");
  while (matvar_t* header = Mat_VarReadNextInfo(impl_->mat)) {
    VarPtr owned(header);
    // MATLAB's class objects (string, table, datetime) and function handles: matio lists them,
    // without a name, and cannot read them. They are passed over, and counted for the message
    // of a variable that is then missing (a text saved as a string, not a char array).
    if (header->class_type == MAT_C_OPAQUE || header->class_type == MAT_C_FUNCTION) {
      ++objects_passed_over_;
      continue;
    }
    if (!header->name)
      throw InputError(path + ": variable " + std::to_string(names_.size() + 1) +
                       " has no name (corrupted file)");
    names_.emplace_back(header->name);
    impl_->headers.push_back(std::move(owned));
  }
  if (mat73 && names_.empty() && !emptyMat73(path))
    throw InputError(damaged73 + " (no variable can be listed)");
  impl_->data_read.assign(impl_->headers.size(), 0);
}

MatReader::~MatReader() = default;

bool MatReader::has(const std::string& name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

std::string MatReader::className(const std::string& name) const {
  static const char* const kNames[] = {
      "empty",  "cell",   "struct",          "object", "char",   "sparse", "double",
      "single", "int8",   "uint8",           "int16",  "uint16", "int32",  "uint32",
      "int64",  "uint64", "function_handle", "opaque"};
  const matvar_t* var = header(name, false);
  const auto k = static_cast<std::size_t>(var->class_type);
  const std::string base = k < std::size(kNames) ? kNames[k] : "unknown";
  // logical arrays are stored as uint8 with a flag; complex ones as their class with a flag.
  return var->isLogical ? "logical" : var->isComplex ? "complex " + base : base;
}

const matvar_t* MatReader::header(const std::string& name, bool with_data) const {
  const auto found = std::find(names_.begin(), names_.end(), name);
  if (found == names_.end())
    throw InputError(path_ + ": variable '" + name + "' is missing" +
                     (objects_passed_over_ > 0
                          ? " (the file holds " + std::to_string(objects_passed_over_) +
                                " MATLAB class object(s), e.g. strings, which are not read: save "
                                "texts as char arrays, 'text' rather than \"text\")"
                          : std::string()));
  const auto i = static_cast<std::size_t>(found - names_.begin());
  matvar_t* var = impl_->headers[i].get();
  if (with_data && !impl_->data_read[i]) {
    const QuietHdf5 quiet;
    if (Mat_VarReadDataAll(impl_->mat, var) != 0)
      throw InputError(path_ + ": variable '" + name + "' cannot be read (corrupted file)");
    impl_->data_read[i] = 1;
  }
  return var;
}

namespace {

// The text of a char variable (or cell element); an empty double array ([]) counts as ''.
std::string charData(const matvar_t* var, const std::string& where) {
  const std::size_t rows = var->rank >= 1 ? var->dims[0] : 0;
  const std::size_t cols = var->rank >= 2 ? var->dims[1] : 0;
  // An empty text may come as '' (0 x 0 char) or, from MATLAB, as []; an empty cell or struct
  // is not a text (an empty list of warnings must not read as one empty string).
  const bool empty_double = rows * cols == 0 && var->class_type == MAT_C_DOUBLE;
  if (var->class_type != MAT_C_CHAR && !empty_double)
    throw InputError(where + " is not a character array");
  if (rows * cols == 0)
    return {};
  if (var->rank != 2 || rows != 1)
    throw InputError(where + " is a " + dims(rows, cols) + " character array, expected one row");
  if (!var->data)
    throw InputError(where + " has no data (corrupted file)");
  std::string out;
  switch (var->data_type) {
    case MAT_T_UTF8:
    case MAT_T_UINT8:
    case MAT_T_INT8:
      out.assign(static_cast<const char*>(var->data), var->nbytes);
      // matio counts a terminating NUL in nbytes of UTF-8 data; no text of ours contains NUL.
      out.erase(std::find(out.begin(), out.end(), '\0'), out.end());
      break;
    case MAT_T_UINT16:
    case MAT_T_UTF16:
    case MAT_T_INT16: {
      out = utf16ToUtf8(static_cast<const std::uint16_t*>(var->data), var->nbytes / 2);
      break;
    }
    default:
      throw InputError(where + " has an unsupported character encoding");
  }
  return out;
}

}  // namespace

Matrix MatReader::readMatrix(const std::string& name, DofIndex rows, DofIndex cols) const {
  // The header, then the values into our own zeroed buffer: matio does not report a zlib stream
  // that ends early from Mat_VarRead and would leave part of its buffer unwritten.
  const matvar_t* var = header(name, false);
  const std::string where = path_ + ": variable '" + name + "'";
  if (var->class_type != MAT_C_DOUBLE || var->isComplex || var->isLogical)
    throw InputError(where + " is of class " + className(name) + ", expected a real double matrix");
  if (var->rank != 2)
    throw InputError(where + " has " + std::to_string(var->rank) + " dimensions, expected 2");
  const auto r = static_cast<DofIndex>(var->dims[0]);
  const auto c = static_cast<DofIndex>(var->dims[1]);
  if ((rows != kAnySize && r != rows) || (cols != kAnySize && c != cols)) {
    // A row where a column is expected: what SciPy's savemat writes for a 1-D array (and
    // loadmat(squeeze_me=True) makes 1-D arrays of columns), unless told oned_as='column'.
    const bool row_for_column = cols == 1 && r == 1 && c != 1 && (rows == kAnySize || c == rows);
    throw InputError(where + " is " + dims(r, c) + ", expected " +
                     (rows == kAnySize ? std::string("n") : std::to_string(rows)) + "x" +
                     (cols == kAnySize ? std::string("n") : std::to_string(cols)) +
                     (row_for_column ? " (a row saved for a column: SciPy's savemat writes 1-D "
                                       "arrays as rows unless given oned_as='column')"
                                     : ""));
  }
  // The dimensions come from the file: a damaged header may claim more than memory holds (or,
  // read as signed, a negative count), which must read as a damaged file, not end the program.
  if (r < 0 || c < 0 || r > std::numeric_limits<int>::max() || c > std::numeric_limits<int>::max())
    throw InputError(where + " claims " + dims(var->dims[0], var->dims[1]) +
                     " entries (corrupted file)");
  Matrix out;
  try {
    out = Matrix::Zero(r, c);
  } catch (const std::bad_alloc&) {
    throw InputError(where + " claims " + dims(var->dims[0], var->dims[1]) +
                     " entries, more than memory holds (corrupted file)");
  }
  if (out.size() == 0)
    return out;
  int start[2] = {0, 0};
  int stride[2] = {1, 1};
  int edge[2] = {static_cast<int>(r), static_cast<int>(c)};
  const QuietHdf5 quiet;
  if (Mat_VarReadData(impl_->mat, const_cast<matvar_t*>(var), out.data(), start, stride, edge) != 0)
    throw InputError(where + " cannot be read (corrupted file)");
  for (DofIndex j = 0; j < c; ++j)
    for (DofIndex i = 0; i < r; ++i)
      if (!std::isfinite(out(i, j)))
        throw InputError(where + " has a non-finite entry at (" + std::to_string(i + 1) + ", " +
                         std::to_string(j + 1) + ")");
  return out;
}

double MatReader::readScalar(const std::string& name) const {
  return readMatrix(name, 1, 1)(0, 0);
}

std::string MatReader::readString(const std::string& name) const {
  return charData(header(name, true), path_ + ": variable '" + name + "'");
}

std::vector<std::string> MatReader::readStrings(const std::string& name, DofIndex count) const {
  const matvar_t* var = header(name, true);
  const std::string where = path_ + ": variable '" + name + "'";
  if (var->class_type != MAT_C_CELL)
    throw InputError(where + " is not a cell array of strings");
  std::size_t total = 1;
  for (int d = 0; d < var->rank; ++d)
    total *= var->dims[d];
  if (count != kAnySize && static_cast<DofIndex>(total) != count)
    throw InputError(where + " has " + std::to_string(total) + " entries, expected " +
                     std::to_string(count));
  std::vector<std::string> out;
  // A damaged header may claim any count; the cells are read one by one and checked below.
  out.reserve(std::min<std::size_t>(total, 1u << 16));
  for (std::size_t i = 0; i < total; ++i) {
    const matvar_t* element = Mat_VarGetCell(const_cast<matvar_t*>(var), static_cast<int>(i));
    const std::string element_where = where + "{" + std::to_string(i + 1) + "}";
    if (!element)
      throw InputError(element_where + " cannot be read (corrupted file)");
    out.push_back(charData(element, element_where));
  }
  return out;
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics

// The reduced model and its .mat cache: building it from a beam (labels, output rows through a
// rigid joint), the MAT wrapper, save -> load round trip, and the refusal of stale, truncated,
// corrupted or foreign files.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <matio.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "expect_input_error.h"
#include "file_bytes.h"
#include "steel_cantilever.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/io/mat_file.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model_file.h"

namespace tracked_vehicle_dynamics {
namespace reduction {
namespace {

constexpr double kExactTolerance = 1e-10;
constexpr const char* kHash = "sha256:0123abcd";

std::string tempPath(const std::string& name) {
  return testing::TempDir() + "tvd_test_reduced_model_" + name;
}

// The message of the InputError that opening `path` and reading it with `read` throws; "" when
// none is thrown.
std::string readError(const std::string& path,
                      const std::function<void(const io::MatReader&)>& read) {
  try {
    const io::MatReader in(path);
    read(in);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Expects a StaleCacheError whose message names the file and contains `what`.
void expectStale(const std::string& path, const std::string& hash, const std::string& what,
                 const ReducedModelLoadOptions& options = {}) {
  try {
    loadReducedModel(path, hash, options);
    ADD_FAILURE() << "loaded " << path << ", expected a StaleCacheError about '" << what << "'";
  } catch (const StaleCacheError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path, 0), 0u) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  }
}

// Copies the MAT file `from` to `to` variable by variable, as a hand edit would: `edit(name, in,
// out)` may write (or drop) a variable itself and returns true then; every other variable is
// copied as it is (a matrix, a text or a list of texts), the checksum included.
void copyEdited(
    const std::string& from, const std::string& to,
    const std::function<bool(const std::string&, const io::MatReader&, io::MatWriter&)>& edit) {
  const io::MatReader in(from);
  io::MatWriter out(to);
  for (const std::string& name : in.names()) {
    if (edit(name, in, out))
      continue;
    try {
      out.writeMatrix(name, in.readMatrix(name));
    } catch (const InputError&) {
      try {
        out.writeString(name, in.readString(name));
      } catch (const InputError&) {
        out.writeStrings(name, in.readStrings(name));
      }
    }
  }
  out.close();
}

// ---------------------------------------------------------------------------------------------
// MAT wrapper
// ---------------------------------------------------------------------------------------------

class MatFileTest : public testing::TestWithParam<io::MatFormat> {};

TEST_P(MatFileTest, RoundTripOfEveryKind) {
  const std::string path = tempPath("wrapper.mat");
  const Matrix a = Matrix::Random(7, 3);
  {
    io::MatWriter out(path, GetParam());
    out.writeMatrix("A", a);
    out.writeMatrix("empty", Matrix(0, 4));
    out.writeMatrix("nil", Matrix(0, 0));  // MATLAB's []
    out.writeScalar("s", -2.5);
    out.writeString("text", "mode 3 (12.4 Hz), zeta \xce\xb6");
    out.writeString("nothing", "");
    out.writeStrings("names", {"hull uz", "", "node 12 uz"});
    out.writeStrings("no_names", {});
    // Beyond U+FFFF (a surrogate pair in the file) and a Latin-1 byte (no UTF-8 character: it
    // is stored, and reads back, as U+FFFD).
    out.writeStrings("wide", {"v\xc3\xa9hicule \xf0\x9f\x9a\x9c", "caf\xe9"});
    out.close();
  }
  const io::MatReader in(path);
  EXPECT_EQ(in.names().size(), 9u);
  EXPECT_EQ(in.readStrings("wide", 2),
            (std::vector<std::string>{"v\xc3\xa9hicule \xf0\x9f\x9a\x9c", "caf\xef\xbf\xbd"}));
  EXPECT_EQ(in.readMatrix("A", 7, 3), a);
  EXPECT_EQ(in.readMatrix("empty").cols(), 4);
  EXPECT_EQ(in.readMatrix("empty").rows(), 0);
  EXPECT_EQ(in.readScalar("s"), -2.5);
  EXPECT_EQ(in.readString("text"), "mode 3 (12.4 Hz), zeta \xce\xb6");
  EXPECT_EQ(in.readString("nothing"), "");
  EXPECT_EQ(in.readStrings("names", 3), (std::vector<std::string>{"hull uz", "", "node 12 uz"}));
  EXPECT_TRUE(in.readStrings("no_names").empty());
  EXPECT_THROW(in.readMatrix("A", 7, 4), InputError);
  EXPECT_THROW(in.readMatrix("A", 8, 3), InputError);  // the rows are checked as the columns
  EXPECT_THROW(in.readMatrix("missing"), InputError);
  EXPECT_THROW(in.readMatrix("text"), InputError);
  EXPECT_THROW(in.readString("A"), InputError);
  EXPECT_EQ(in.readString("nil"), "");  // MATLAB's [] as an empty text
  EXPECT_EQ(in.readString("empty"), "");
  EXPECT_THROW(in.readString("no_names"), InputError);  // an empty cell is not a text
  EXPECT_THROW(in.readStrings("names", 2), InputError);
  std::remove(path.c_str());
}

// What MATLAB, Octave and SciPy see, read with matio itself rather than through our reader
// (which read back the old miUTF8 text, dimensions counted in bytes, that Octave refused): a char
// array of UTF-16 code units, its dimensions counting those units.
TEST(MatFile, TextIsStoredAsUtf16CodeUnitsCountedByUnit) {
  const std::string path = tempPath("utf16.mat");
  {
    io::MatWriter out(path);
    out.writeString("name", "v\xc3\xa9hicule \xf0\x9f\x9a\x9c");  // 9 characters, then U+1F69C
    out.close();
  }
  mat_t* mat = Mat_Open(path.c_str(), MAT_ACC_RDONLY);
  ASSERT_NE(mat, nullptr);
  matvar_t* var = Mat_VarRead(mat, "name");
  ASSERT_NE(var, nullptr);
  EXPECT_EQ(var->class_type, MAT_C_CHAR);
  EXPECT_EQ(var->data_type, MAT_T_UINT16);
  ASSERT_EQ(var->rank, 2);
  EXPECT_EQ(var->dims[0], 1u);
  EXPECT_EQ(var->dims[1], 11u);  // the emoji is a surrogate pair
  ASSERT_EQ(var->nbytes, 22u);
  const auto* units = static_cast<const std::uint16_t*>(var->data);
  const std::vector<std::uint16_t> expected = {0x76, 0xE9, 0x68, 0x69,   0x63,  0x75,
                                               0x6C, 0x65, 0x20, 0xD83D, 0xDE9C};
  EXPECT_EQ(std::vector<std::uint16_t>(units, units + 11), expected);
  Mat_VarFree(var);
  Mat_Close(mat);
  std::remove(path.c_str());
}

// What MATLAB, Octave and SciPy see (matio reads the file): an empty text is '' (0x0, as MATLAB
// writes it), a list of texts an n x 1 cell.
TEST(MatFile, EmptyTextAndTextListsHaveMatlabsShapes) {
  const std::string path = tempPath("shapes.mat");
  {
    io::MatWriter out(path);
    out.writeString("nothing", "");
    out.writeStrings("names", {"a", "bb", "ccc"});
    out.close();
  }
  mat_t* mat = Mat_Open(path.c_str(), MAT_ACC_RDONLY);
  ASSERT_NE(mat, nullptr);
  matvar_t* empty = Mat_VarReadInfo(mat, "nothing");
  ASSERT_NE(empty, nullptr);
  EXPECT_EQ(empty->dims[0], 0u);
  EXPECT_EQ(empty->dims[1], 0u);
  Mat_VarFree(empty);
  matvar_t* names = Mat_VarReadInfo(mat, "names");
  ASSERT_NE(names, nullptr);
  EXPECT_EQ(names->class_type, MAT_C_CELL);
  EXPECT_EQ(names->dims[0], 3u);
  EXPECT_EQ(names->dims[1], 1u);
  Mat_VarFree(names);
  Mat_Close(mat);
  std::remove(path.c_str());
}

// A MAT 5 file written on a big-endian machine (header "MI", every field byte-swapped) reads back.
TEST(MatFile, BigEndianMat5FileReads) {
  const auto be32 = [](std::string& s, std::uint32_t v) {
    for (int i = 3; i >= 0; --i)
      s.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
  };
  std::string f(116, ' ');
  std::memcpy(&f[0], "MATLAB 5.0 MAT-file, big-endian", 31);
  f += std::string(8, '\0');        // subsystem data offset
  f += std::string("\x01\x00", 2);  // version 0x0100, big-endian
  f += "MI";
  be32(f, 14);  // miMATRIX
  be32(f, 64);
  be32(f, 6);  // array flags: mxDOUBLE_CLASS
  be32(f, 8);
  be32(f, 6);
  be32(f, 0);
  be32(f, 5);  // dimensions 1 x 1
  be32(f, 8);
  be32(f, 1);
  be32(f, 1);
  be32(f, 1);  // name "a"
  be32(f, 1);
  f += std::string("a\0\0\0\0\0\0\0", 8);
  be32(f, 9);  // miDOUBLE, 8 bytes
  be32(f, 8);
  const double value = 2.5;
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, 8);
  for (int i = 7; i >= 0; --i)
    f.push_back(static_cast<char>((bits >> (8 * i)) & 0xFF));
  const std::string path = tempPath("big_endian.mat");
  writeBytes(path, f);
  EXPECT_EQ(io::MatReader(path).readScalar("a"), 2.5);
  std::remove(path.c_str());
}

// A MAT 5 file cut inside its last element, even by a few bytes of its data, is "truncated".
TEST(MatFile, AFileCutByAFewBytesIsTruncated) {
  const std::string path = tempPath("cut.mat");
  {
    io::MatWriter out(path, io::MatFormat::Mat5, false);
    out.writeMatrix("A", Matrix::Ones(3, 3));
    out.close();
  }
  const std::string bytes = readBytes(path);
  writeBytes(path, bytes.substr(0, bytes.size() - 4));
  expectInputError([&] { io::MatReader(path).readMatrix("A"); }, "truncated");
  std::remove(path.c_str());
}

INSTANTIATE_TEST_SUITE_P(Formats, MatFileTest,
                         testing::Values(io::MatFormat::Mat5, io::MatFormat::Mat73));

// A MAT 7.3 (HDF5) file damaged after its 128-byte MAT header: matio opens it, but HDF5 lists
// no variable; the reader says the file is damaged instead of "variable 'A' is missing", and
// HDF5's error stack does not reach stderr.
TEST(MatFile, DamagedMat73FileIsNamedAsSuch) {
  const std::string path = tempPath("damaged73.mat");
  {
    io::MatWriter out(path, io::MatFormat::Mat73);
    out.writeMatrix("A", Matrix::Ones(40, 40));
    out.writeString("text", "kept");
    out.close();
  }
  const std::string bytes = readBytes(path);
  ASSERT_GT(bytes.size(), 1024u);
  H5E_auto2_t handler_before = nullptr;
  void* data_before = nullptr;
  ASSERT_GE(H5Eget_auto2(H5E_DEFAULT, &handler_before, &data_before), 0);
  ASSERT_NE(handler_before, nullptr);  // HDF5 prints by default
  struct Damage {
    std::string what;
    std::string bytes;
  };
  std::string superblock = bytes;  // HDF5's superblock follows the 512-byte user block
  for (std::size_t i = 512; i < 512 + 48; ++i)
    superblock[i] = static_cast<char>(~superblock[i]);
  const Damage damages[] = {{"superblock", superblock},
                            {"truncated to half", bytes.substr(0, bytes.size() / 2)},
                            {"truncated after the user block", bytes.substr(0, 600)}};
  for (const Damage& d : damages) {
    writeBytes(path, d.bytes);
    std::string what;
    testing::internal::CaptureStderr();  // one message: HDF5's own error stack is not printed
    try {
      const io::MatReader in(path);
      in.readMatrix("A");
    } catch (const InputError& e) {
      what = e.what();
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << d.what;
    ASSERT_FALSE(what.empty()) << d.what << ": read";
    EXPECT_EQ(what.find("is missing"), std::string::npos) << d.what << ": " << what;
    EXPECT_NE(what.find("MAT 7.3"), std::string::npos) << d.what << ": " << what;
    EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << d.what << ": " << what;
    // The reader silenced HDF5 only while it called it.
    H5E_auto2_t handler = nullptr;
    void* data = nullptr;
    H5Eget_auto2(H5E_DEFAULT, &handler, &data);
    EXPECT_EQ(handler, handler_before) << d.what;
    EXPECT_EQ(data, data_before) << d.what;
  }
  std::remove(path.c_str());
}

// A valid MAT 7.3 file without variables is no damaged file: it lists none, and a variable asked
// for is missing, for both formats alike.
TEST(MatFile, EmptyFileHasNoVariablesInEitherFormat) {
  for (const io::MatFormat format : {io::MatFormat::Mat5, io::MatFormat::Mat73}) {
    const std::string path = tempPath("empty.mat");
    {
      io::MatWriter out(path, format);
      out.close();
    }
    testing::internal::CaptureStderr();
    const io::MatReader in(path);
    EXPECT_TRUE(in.names().empty());
    EXPECT_FALSE(in.has("A"));
    std::string what;
    try {
      in.readMatrix("A");
    } catch (const InputError& e) {
      what = e.what();
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    EXPECT_EQ(what, path + ": variable 'A' is missing");
    std::remove(path.c_str());
  }
}

// A damaged header's dimensions (MAT 5, uncompressed: the 128-byte file header, the matrix tag
// (8), its array flags (16) and its dimensions' tag (8), then the int32 row and column counts)
// read as a damaged file, not as an allocation that ends the program: negative counts, and
// counts whose product no memory holds.
TEST(MatFile, ImpossibleDimensionsReadAsACorruptedFile) {
  const std::string path = tempPath("dims.mat");
  {
    io::MatWriter out(path, io::MatFormat::Mat5, /*compress=*/false);
    out.writeMatrix("A", Matrix::Ones(2, 3));
    out.close();
  }
  const std::string bytes = readBytes(path);
  constexpr std::size_t kDims = 128 + 8 + 16 + 8;
  std::int32_t stored[2];
  std::memcpy(stored, bytes.data() + kDims, sizeof(stored));
  ASSERT_EQ(stored[0], 2);  // the layout above
  ASSERT_EQ(stored[1], 3);
  for (const std::int32_t huge : {std::int32_t{-1}, std::numeric_limits<std::int32_t>::max()}) {
    SCOPED_TRACE(huge);
    std::string damaged = bytes;
    const std::int32_t claimed[2] = {huge, huge};
    std::memcpy(damaged.data() + kDims, claimed, sizeof(claimed));
    writeBytes(path, damaged);
    const std::string what = readError(path, [](const io::MatReader& in) { in.readMatrix("A"); });
    EXPECT_EQ(what.rfind(path + ": variable 'A' ", 0), 0u) << what;
    EXPECT_NE(what.find("(corrupted file)"), std::string::npos) << what;
  }
  std::remove(path.c_str());
}

// matio allocates what an array's header claims before it reads: a cell of texts claiming 1e9
// entries (8 GB and 44 s) or a name of 2^31 bytes (2 GB) is refused from the element's own size
// first, naming the variable, or where it starts when its name cannot be read.
TEST(MatFile, HeadersClaimingMoreThanTheirElementHoldsAreCorrupted) {
  const std::string path = tempPath("cell_dims.mat");
  {
    io::MatWriter out(path, io::MatFormat::Mat5, /*compress=*/false);
    out.writeStrings("names", {"a", "bb", "ccc"});
    out.close();
  }
  const std::string bytes = readBytes(path);
  // miMATRIX tag (8), array flags (8 + 8), dimensions tag (8), then the dimensions.
  constexpr std::size_t kDims = 128 + 8 + 16 + 8;
  constexpr std::size_t kName = kDims + 8;
  std::int32_t stored[2];
  std::memcpy(stored, bytes.data() + kDims, sizeof(stored));
  ASSERT_EQ(stored[0], 3);  // the layout above
  ASSERT_EQ(stored[1], 1);
  const auto refusal = [&](const std::string& damaged) {
    writeBytes(path, damaged);
    return readError(path, [](const io::MatReader& in) { in.readStrings("names"); });
  };
  std::string damaged = bytes;
  const std::int32_t claimed[2] = {1000000000, 1};
  std::memcpy(damaged.data() + kDims, claimed, sizeof(claimed));
  const std::uint64_t element_bytes = bytes.size() - 128 - 8;  // the one variable's data
  EXPECT_EQ(refusal(damaged),
            path + ": variable 'names' claims 1000000000x1 elements, more than its " +
                std::to_string(element_bytes) + " bytes hold (corrupted file)");
  // One entry more than written: the fourth lies beyond the variable.
  damaged = bytes;
  const std::int32_t one_more[2] = {4, 1};
  std::memcpy(damaged.data() + kDims, one_more, sizeof(one_more));
  EXPECT_EQ(refusal(damaged),
            path + ": variable 'names' has its cell element 4 beyond its end (corrupted file)");
  // The name: a full tag (type miINT8, count) whose count is 2^31.
  damaged = bytes;
  const std::uint32_t name_tag[2] = {1, 0x80000000u};
  std::memcpy(damaged.data() + kName, name_tag, sizeof(name_tag));
  EXPECT_EQ(refusal(damaged), path +
                                  ": the variable at byte 128 has its name claiming 2147483648 "
                                  "bytes, beyond its end (corrupted file)");
  // Untouched, it reads back.
  writeBytes(path, bytes);
  EXPECT_EQ(io::MatReader(path).readStrings("names"), (std::vector<std::string>{"a", "bb", "ccc"}));
  std::remove(path.c_str());
}

TEST(MatFile, RefusesNonFiniteValuesNamingTheEntry) {
  const std::string path = tempPath("nan.mat");
  Matrix a = Matrix::Ones(3, 3);
  a(2, 1) = std::numeric_limits<double>::quiet_NaN();
  io::MatWriter out(path);
  out.writeMatrix("A", a);
  out.close();
  try {
    io::MatReader(path).readMatrix("A");
    ADD_FAILURE() << "NaN accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("non-finite entry at (3, 2)"), std::string::npos)
        << e.what();
  }
  std::remove(path.c_str());
}

TEST(MatFile, WriterChecksNamesAndLeavesNothingWithoutClose) {
  const std::string path = tempPath("unclosed.mat");
  std::remove(path.c_str());
  {
    io::MatWriter out(path);
    EXPECT_THROW(out.writeScalar("1abc", 1.0), InputError);
    EXPECT_THROW(out.writeScalar("a b", 1.0), InputError);
    // MATLAB's namelengthmax: 63 characters, not 64.
    EXPECT_NO_THROW(out.writeScalar(std::string(63, 'a'), 1.0));
    EXPECT_THROW(out.writeScalar(std::string(64, 'b'), 1.0), InputError);
    out.writeScalar("x", 1.0);
    EXPECT_THROW(out.writeScalar("x", 2.0), InputError);
  }
  EXPECT_FALSE(std::ifstream(path).good());
  EXPECT_THROW(io::MatWriter("/nonexistent_directory/x.mat"), InputError);
}

// ---------------------------------------------------------------------------------------------
// Reduced model
// ---------------------------------------------------------------------------------------------

// A 2 m steel cantilever (10 beams, clamped at node 0) on a spring-damper under the tip (one road
// input), with a mount point (node 100) 0.5 m above the tip, rigidly attached to it.
fem::System beamOnSupport() {
  const int elements = 10;
  fem::Model model = test::steelCantilever(elements);
  model.addNode(100, Vector3(2.0, 0.0, 0.5));
  fem::Spring support;
  support.n1 = elements;
  support.stiffness(2) = 2e5;
  support.damping(2) = 800.0;
  model.springs.push_back(support);
  fem::Mass mount;
  mount.node = 100;
  mount.mass = 5.0;
  model.masses.push_back(mount);
  fem::RigidJoint joint;
  joint.master = elements;
  joint.slaves = {100};
  model.rigid_joints.push_back(joint);
  return fem::assemble(model);
}

ReductionRequest request(const fem::System& system) {
  ReductionRequest r;
  r.masters = {system.dofs.requireActive(10, 2), system.dofs.requireActive(5, 2),
               system.dofs.requireActive(10, 1)};
  r.master_groups = {"road input", "support", "MoGeSeC 1"};
  r.craig_bampton.fixed_interface.count = 4;
  r.craig_bampton.damping.model = DampingModel::Rayleigh;
  r.craig_bampton.damping.beta = 1e-4;
  r.outputs = {{"tip uz", {10, 2}}, {"", {5, 2}}, {"mount ux", {100, 0}}, {"root uz", {0, 2}}};
  r.selection.modes = {{0, 10.2, "MAC 0.97 with un-tracked mode 1 (9.8 Hz)"},
                       {2, 64.1, "MAC 0.81 with un-tracked mode 3 (60 Hz)"}};
  r.description_hash = kHash;
  r.reduction = "variant tracked; modes 4";
  r.creator = "test_reduced_model";
  return r;
}

TEST(ReducedModel, BuildsLabelsOutputsAndInputs) {
  const fem::System system = beamOnSupport();
  const ReductionRequest req = request(system);
  const ReducedModel model = buildReducedModel(system, req);
  ASSERT_EQ(model.size(), 7);
  EXPECT_EQ(model.dof_labels[0], "node 10 uz");
  EXPECT_EQ(model.dof_labels[2], "node 10 uy");
  EXPECT_EQ(model.dof_labels[3].rfind("mode 1 (", 0), 0u) << model.dof_labels[3];
  EXPECT_EQ(model.system.output_names,
            (std::vector<std::string>{"tip uz", "node 5 uz", "mount ux", "root uz"}));
  EXPECT_EQ(model.input_labels, (std::vector<std::string>{"node 10 uz"}));
  ASSERT_EQ(model.system.input_stations.size(), 1);
  EXPECT_EQ(model.system.input_stations(0), 2.0);
  EXPECT_EQ(model.full_dof_count, system.size());
  EXPECT_EQ(model.version, softwareVersion());
  EXPECT_EQ(model.selected_modes.size(), 2u);
  // The damping line names the discrete dampers only when the system has some (the support's).
  EXPECT_EQ(model.damping, "Rayleigh alpha=0 1/s beta=0.0001 s + discrete dampers");
  fem::System undamped = system;
  undamped.damping.setZero();
  EXPECT_EQ(buildReducedModel(undamped, req).damping, "Rayleigh alpha=0 1/s beta=0.0001 s");
  // Where each master is and why, in the request's order.
  ASSERT_EQ(model.master_positions.rows(), 3);
  ASSERT_EQ(model.master_positions.cols(), 3);
  for (DofIndex i = 0; i < 3; ++i)
    EXPECT_EQ(model.master_positions.row(i).transpose(),
              system.dofs.positionOf(req.masters[static_cast<std::size_t>(i)]));
  EXPECT_EQ(model.master_positions(0, 0), 2.0);  // node 10: the beam's tip, 2 m along x
  EXPECT_EQ(model.master_groups, req.master_groups);
  ReductionRequest ungrouped = req;
  ungrouped.master_groups.clear();
  EXPECT_EQ(buildReducedModel(system, ungrouped).master_groups,
            (std::vector<std::string>(3, "master")));
  ungrouped.master_groups = {"one"};
  EXPECT_THROW(buildReducedModel(system, ungrouped), std::logic_error);

  // H rows are rows of T_CMS: a master gives a unit row, a fixed DOF a zero row, and the
  // rigid-joint slave u_x(100) = u_x(10) + 0.5 theta_y(10) combines two rows.
  CraigBamptonOptions options = req.craig_bampton;
  options.keep_transformation = true;
  const CraigBamptonResult cb = craigBampton(system, req.masters, options);
  const Matrix& h = model.system.output;
  EXPECT_EQ(h.row(0), Matrix::Identity(7, 7).row(0));
  EXPECT_EQ(h.row(1), Matrix::Identity(7, 7).row(1));
  EXPECT_EQ(h.row(3).norm(), 0.0);
  const Vector mount = cb.transformation.row(system.dofs.requireActive(10, 0)).transpose() +
                       0.5 * cb.transformation.row(system.dofs.requireActive(10, 4)).transpose();
  EXPECT_LT((h.row(2).transpose() - mount).norm(), kExactTolerance * mount.norm());
  EXPECT_EQ(model.system.stiffness, cb.stiffness);

  ReductionRequest twice = req;
  twice.outputs.push_back({"tip uz", {10, 2}});
  EXPECT_THROW(buildReducedModel(system, twice), InputError);
  ReductionRequest unknown = req;
  unknown.outputs.push_back({"ghost", {999, 2}});
  EXPECT_THROW(buildReducedModel(system, unknown), InputError);
}

class ReducedModelFileTest : public testing::Test {
 protected:
  void SetUp() override {
    system_ = beamOnSupport();
    model_ = buildReducedModel(system_, request(system_));
    path_ = tempPath(std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) +
                     ".mat");
    saveReducedModel(model_, path_);
  }
  void TearDown() override { std::remove(path_.c_str()); }

  fem::System system_;
  ReducedModel model_;
  std::string path_;
};

TEST_F(ReducedModelFileTest, SaveLoadRoundTripIsExact) {
  const ReducedModel loaded = loadReducedModel(path_, kHash);
  const dynamics::SecondOrderSystem& a = model_.system;
  const dynamics::SecondOrderSystem& b = loaded.system;
  EXPECT_EQ(b.mass, a.mass);
  EXPECT_EQ(b.stiffness, a.stiffness);
  EXPECT_EQ(b.damping, a.damping);
  EXPECT_EQ(b.input_stiffness, a.input_stiffness);
  EXPECT_EQ(b.input_damping, a.input_damping);
  EXPECT_EQ(b.output, a.output);
  EXPECT_EQ(b.output_names, a.output_names);
  EXPECT_EQ(b.input_stations, a.input_stations);
  EXPECT_EQ(b.input_lateral, a.input_lateral);
  EXPECT_EQ(loaded.gravity_load, model_.gravity_load);
  ASSERT_EQ(model_.travel_load.size(), model_.size());
  EXPECT_GT(model_.travel_load.norm(), 0.0);
  EXPECT_EQ(loaded.travel_load, model_.travel_load);
  EXPECT_EQ(loaded.dof_labels, model_.dof_labels);
  EXPECT_EQ(loaded.input_labels, model_.input_labels);
  EXPECT_EQ(loaded.masters, model_.masters);
  EXPECT_EQ(loaded.master_positions, model_.master_positions);
  EXPECT_EQ(loaded.master_groups, model_.master_groups);
  EXPECT_EQ(loaded.fixed_interface_frequencies_hz, model_.fixed_interface_frequencies_hz);
  ASSERT_EQ(loaded.selected_modes.size(), model_.selected_modes.size());
  for (std::size_t i = 0; i < loaded.selected_modes.size(); ++i) {
    EXPECT_EQ(loaded.selected_modes[i].mode, model_.selected_modes[i].mode);
    EXPECT_EQ(loaded.selected_modes[i].frequency_hz, model_.selected_modes[i].frequency_hz);
    EXPECT_EQ(loaded.selected_modes[i].reason, model_.selected_modes[i].reason);
  }
  EXPECT_EQ(loaded.damping, model_.damping);
  EXPECT_EQ(loaded.description_hash, kHash);
  EXPECT_EQ(loaded.version, model_.version);
  EXPECT_EQ(loaded.created_utc, model_.created_utc);
  EXPECT_EQ(loaded.creator, "test_reduced_model");
  EXPECT_EQ(loaded.full_dof_count, model_.full_dof_count);
}

// A cached model warns as the run that reduced it did (reduction::modeCountCut's warnings): the
// warnings are saved, read back in order and covered by the checksum.
TEST_F(ReducedModelFileTest, WarningsAreSavedCheckedAndReadBack) {
  EXPECT_TRUE(model_.warnings.empty());
  EXPECT_TRUE(loadReducedModel(path_, kHash).warnings.empty());  // a 0 x 1 cell
  ReducedModel warned = model_;
  warned.warnings = {"global_modes 40 cuts a repeated eigenvalue", "second, with a comma"};
  saveReducedModel(warned, path_);
  EXPECT_EQ(loadReducedModel(path_, kHash).warnings, warned.warnings);
  // The same file with one warning dropped and the old checksum: refused.
  const std::string other = tempPath("edited_warnings.mat");
  copyEdited(path_, other, [&](const std::string& name, const io::MatReader&, io::MatWriter& out) {
    if (name != "reduction_warnings")
      return false;
    out.writeStrings(name, {warned.warnings[0]});
    return true;
  });
  expectStale(other, kHash, "checksum");
  std::remove(other.c_str());
}

TEST_F(ReducedModelFileTest, DifferentHashIsStale) {
  expectStale(path_, "sha256:ffff", "reduced from another description (description hash ");
}

// The same description reduced for another variant or with other options is another model.
TEST_F(ReducedModelFileTest, OtherReductionIsStaleWhenOneIsExpected) {
  EXPECT_EQ(loadReducedModel(path_, kHash).reduction, "variant tracked; modes 4");
  ReducedModelLoadOptions options;
  options.expected_reduction = "variant tracked; modes 4";
  EXPECT_EQ(loadReducedModel(path_, kHash, options).size(), model_.size());
  options.expected_reduction = "variant untracked; modes 4";
  try {
    loadReducedModel(path_, kHash, options);
    ADD_FAILURE() << "a tracked model was loaded as an untracked one";
  } catch (const StaleCacheError& e) {
    EXPECT_NE(std::string(e.what()).find("reduced as 'variant tracked; modes 4', expected "
                                         "'variant untracked; modes 4'"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(ReducedModelFileTest, OtherSoftwareVersionIsStaleUnlessAllowed) {
  ReducedModel old = model_;
  old.version = "0.0.1";
  saveReducedModel(old, path_);
  expectStale(path_, kHash, "written by version 0.0.1");
  ReducedModelLoadOptions options;
  options.require_same_version = false;
  // Another release: refused unless that is allowed too.
  expectStale(path_, kHash, "written by version 0.0.1", options);
  options.require_same_release = false;
  const ReducedModel other_release = loadReducedModel(path_, kHash, options);
  EXPECT_EQ(other_release.version, "0.0.1");
  ASSERT_EQ(other_release.warnings.size(), model_.warnings.size() + 1);
  EXPECT_NE(other_release.warnings.back().find("written by version 0.0.1, this is "),
            std::string::npos)
      << other_release.warnings.back();

  // Another build of this release (the commit after '+'): taken, with a warning, when only the
  // release must match; refused when the version must.
  const std::string current = softwareVersion();
  old.version = current.substr(0, current.find('+')) + "+0123456789ab";
  ASSERT_NE(old.version, current);
  saveReducedModel(old, path_);
  expectStale(path_, kHash, "written by version " + old.version);
  options.require_same_release = true;
  const ReducedModel other_build = loadReducedModel(path_, kHash, options);
  ASSERT_EQ(other_build.warnings.size(), model_.warnings.size() + 1);
  EXPECT_NE(other_build.warnings.back().find("written by build " + old.version +
                                             " of this release, this is " + current + ": taken"),
            std::string::npos)
      << other_build.warnings.back();
}

TEST_F(ReducedModelFileTest, TruncatedFilesAreRefused) {
  const std::string bytes = readBytes(path_);
  for (const double fraction : {0.99, 0.75, 0.5, 0.1}) {
    writeBytes(path_, bytes.substr(0, static_cast<std::size_t>(fraction * bytes.size())));
    expectStale(path_, kHash, "truncated");
  }
  // Cut right after the 128-byte header: a valid MAT file that holds nothing.
  writeBytes(path_, bytes.substr(0, 128));
  expectStale(path_, kHash, "holds no variables");
  writeBytes(path_, bytes.substr(0, 60));
  expectStale(path_, kHash,
              "not a MAT 5 or 7.3 file (60 bytes, shorter than their 128-byte header: a MAT 4 "
              "file, -v4, or no MAT file at all)");
}

// MATLAB's and Octave's `m = load(F); save(F2, 'm')` keep the model as one struct: the message
// says so and how to save its fields instead.
TEST_F(ReducedModelFileTest, AModelSavedAsOneStructIsNamedAsSuch) {
  {
    mat_t* mat = Mat_CreateVer(path_.c_str(), nullptr, MAT_FT_MAT5);
    ASSERT_NE(mat, nullptr);
    std::size_t one[2] = {1, 1};
    const char* fields[] = {"format_version"};
    matvar_t* m = Mat_VarCreateStruct("m", 2, one, fields, 1);
    double version = 1;
    Mat_VarSetStructFieldByName(
        m, "format_version", 0,
        Mat_VarCreate("format_version", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, one, &version, 0));
    ASSERT_EQ(Mat_VarWrite(mat, m, MAT_COMPRESSION_NONE), 0);
    Mat_VarFree(m);
    Mat_Close(mat);
  }
  expectStale(path_, kHash,
              ": holds one struct 'm' and no variable 'format_version': saved without -struct? "
              "Save its fields as variables: save(FILE, '-struct', 'm', '-v7')");
}

TEST_F(ReducedModelFileTest, CorruptedBytesAreRefused) {
  const std::string bytes = readBytes(path_);
  // Overwrite 16 bytes in the middle (inside the compressed matrices).
  std::string corrupted = bytes;
  for (std::size_t i = bytes.size() / 2; i < bytes.size() / 2 + 16; ++i)
    corrupted[i] = static_cast<char>(~corrupted[i]);
  writeBytes(path_, corrupted);
  EXPECT_THROW(loadReducedModel(path_, kHash), StaleCacheError);
}

TEST_F(ReducedModelFileTest, ChangedValuesFailTheChecksum) {
  // A file rewritten with one value changed and the old checksum: only the checksum tells.
  const std::string other = tempPath("edited.mat");
  copyEdited(path_, other,
             [](const std::string& name, const io::MatReader& in, io::MatWriter& out) {
               if (name != "K_R")
                 return false;
               Matrix k = in.readMatrix(name);
               k(0, 0) *= 1.0 + 1e-12;
               out.writeMatrix(name, k);
               return true;
             });
  expectStale(other, kHash, "checksum");
  std::remove(other.c_str());
}

TEST_F(ReducedModelFileTest, FileWithoutTheTravelLoadIsRefusedNamingIt) {
  // A file of this layout that lacks travel_load (every other variable copied as it is).
  const std::string other = tempPath("no_travel_load.mat");
  copyEdited(path_, other, [](const std::string& name, const io::MatReader&, io::MatWriter&) {
    return name == "travel_load";  // dropped
  });
  expectStale(other, kHash, "'travel_load' is missing");
  std::remove(other.c_str());
}

TEST_F(ReducedModelFileTest, GarbageMissingAndForeignFilesAreRefused) {
  writeBytes(path_, std::string(4096, 'x'));
  expectStale(path_, kHash, "not a MAT");
  expectStale(tempPath("does_not_exist.mat"), kHash, "does not exist");
  {
    io::MatWriter out(path_);
    out.writeScalar("format_version", 99);
    out.close();
  }
  expectStale(path_, kHash, "format version");
  {
    io::MatWriter out(path_);
    out.writeScalar("format_version", kReducedModelFormatVersion);
    out.writeString("version", softwareVersion());
    out.writeString("description_hash", kHash);
    out.close();
  }
  expectStale(path_, kHash, "checksum");
}

// Symmetry is judged against the matrix's size: round-off asymmetry of a stiff model (here
// 1e-13 of its largest entry, far above any absolute bound for a K_R of ground ties at 2e10 N/m)
// saves and loads; 1e-3 of it does not (below).
TEST_F(ReducedModelFileTest, RoundOffAsymmetryIsJudgedAgainstTheMatrixSize) {
  ReducedModel rounded = model_;
  const double scale = rounded.system.stiffness.cwiseAbs().maxCoeff();
  ASSERT_GT(1e-13 * scale, 1e-9) << "the test model must be stiff enough to tell";
  rounded.system.stiffness(0, 1) += 1e-13 * scale;
  ASSERT_NO_THROW(saveReducedModel(rounded, path_));
  EXPECT_EQ(loadReducedModel(path_, kHash).system.stiffness(0, 1), rounded.system.stiffness(0, 1));
}

TEST_F(ReducedModelFileTest, InconsistentModelsAreNotSaved) {
  ReducedModel asymmetric = model_;
  asymmetric.system.stiffness(0, 1) += 1e-3 * asymmetric.system.stiffness.cwiseAbs().maxCoeff();
  EXPECT_THROW(saveReducedModel(asymmetric, path_), InputError);
  ReducedModel labels = model_;
  labels.dof_labels.pop_back();
  EXPECT_THROW(saveReducedModel(labels, path_), InputError);
  ReducedModel outputs = model_;
  outputs.system.output_names.push_back("extra");
  EXPECT_THROW(saveReducedModel(outputs, path_), InputError);
  // The same checks guard a load: a file whose checksum holds over a K_R or C_R of the wrong
  // sign is named, not left to the solver that meets it.
  ReducedModel loose = model_;
  loose.system.stiffness = -loose.system.stiffness;
  expectInputError([&] { saveReducedModel(loose, path_); }, "K_R is not positive definite");
  ReducedModel active = model_;
  active.system.damping = -active.system.damping;
  expectInputError([&] { saveReducedModel(active, path_); }, "C_R is not positive semi-definite");
  // The file on disk is still the good one (saving is atomic).
  EXPECT_NO_THROW(loadReducedModel(path_, kHash));
}

}  // namespace
}  // namespace reduction
}  // namespace tracked_vehicle_dynamics

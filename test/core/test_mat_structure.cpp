// The MAT structure check on compressed variables (MATLAB's default save -v7, scipy.io.savemat
// with do_compression=True): the array headers inside the zlib stream are checked as an
// uncompressed element's are, before matio allocates what they claim, and a damaged or short
// stream is named as such.
#include <gtest/gtest.h>
#include <matio.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "file_bytes.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/mat_file.h"
#include "tracked_vehicle_dynamics/io/mat_structure.h"

namespace tracked_vehicle_dynamics {
namespace io {
namespace {

constexpr std::size_t kHeader = 128;         // the MAT 5 file header
constexpr std::uint32_t kMiCompressed = 15;  // a top-level element's type

std::string tempPath(const std::string& name) {
  return testing::TempDir() + "tvd_test_mat_structure_" + name;
}

std::uint32_t u32(const std::string& bytes, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

void setU32(std::string& bytes, std::size_t at, std::uint32_t v) {
  std::memcpy(bytes.data() + at, &v, 4);
}

std::string inflateAll(const std::string& z) {
  z_stream s{};
  EXPECT_EQ(inflateInit(&s), Z_OK);
  std::string out;
  char buffer[4096];
  s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(z.data()));
  s.avail_in = static_cast<uInt>(z.size());
  int status = Z_OK;
  while (status == Z_OK) {
    s.next_out = reinterpret_cast<Bytef*>(buffer);
    s.avail_out = sizeof(buffer);
    status = inflate(&s, Z_NO_FLUSH);
    out.append(buffer, sizeof(buffer) - s.avail_out);
  }
  EXPECT_EQ(status, Z_STREAM_END);
  inflateEnd(&s);
  return out;
}

std::string deflateAll(const std::string& raw) {
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string out(size, '\0');
  EXPECT_EQ(compress(reinterpret_cast<Bytef*>(out.data()), &size,
                     reinterpret_cast<const Bytef*>(raw.data()), static_cast<uLong>(raw.size())),
            Z_OK);
  out.resize(size);
  return out;
}

// A file holding one compressed variable: its header, and the zlib stream of its one element.
struct OneVariable {
  std::string header;
  std::string stream;
  // The file with `stream` as the element's data (its tag's byte count set to the stream's).
  std::string file() const {
    std::string bytes = header;
    bytes.append(8, '\0');
    setU32(bytes, kHeader, kMiCompressed);
    setU32(bytes, kHeader + 4, static_cast<std::uint32_t>(stream.size()));
    return bytes + stream;
  }
};

OneVariable split(const std::string& bytes) {
  EXPECT_EQ(u32(bytes, kHeader), kMiCompressed);
  EXPECT_EQ(kHeader + 8 + u32(bytes, kHeader + 4), bytes.size());  // one variable only
  return {bytes.substr(0, kHeader), bytes.substr(kHeader + 8)};
}

// The message of the InputError the structure check throws on `bytes` ("" when none is), and
// that MatReader throws the same one.
std::string refusal(const std::string& path, const std::string& bytes) {
  writeBytes(path, bytes);
  std::string what;
  try {
    checkMatStructure(path);
  } catch (const InputError& e) {
    what = e.what();
  }
  try {
    MatReader reader(path);
    EXPECT_EQ("", what) << "MatReader opened what the check refused";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), what);
  }
  return what;
}

std::string writeCompressed(const std::string& path, const std::vector<std::string>& names) {
  MatWriter out(path, MatFormat::Mat5, /*compress=*/true);
  out.writeStrings("names", names);
  out.close();
  return readBytes(path);
}

TEST(MatStructure, CompressedVariablesReadBack) {
  const std::string path = tempPath("round_trip.mat");
  Matrix a(37, 23);
  for (Eigen::Index k = 0; k < a.size(); ++k)
    a.data()[k] = std::sin(0.37 * static_cast<double>(k)) * 1e3;
  const std::vector<std::string> names = {"hull_heave", "", "road_wheel_left_1"};
  {
    MatWriter out(path, MatFormat::Mat5, /*compress=*/true);
    out.writeMatrix("A", a);
    out.writeStrings("names", names);
    out.writeString("text", "Dimauro et al.");
    out.close();
  }
  const std::string bytes = readBytes(path);
  ASSERT_EQ(u32(bytes, kHeader), kMiCompressed);  // the variables are compressed
  EXPECT_EQ(checkMatStructure(path), MatFormat::Mat5);
  const MatReader in(path);
  EXPECT_EQ(in.readMatrix("A"), a);
  EXPECT_EQ(in.readStrings("names"), names);
  EXPECT_EQ(in.readString("text"), "Dimauro et al.");
  std::remove(path.c_str());
}

// A cell of texts claiming 1e9 entries: matio allocates 8 GB for their pointers before it reads
// one (4e8 took 3.1 GB and 9 s). The inflated headers are checked against the element's bytes
// first, and the message names the variable as for an uncompressed one.
TEST(MatStructure, ACompressedCellClaimingMoreThanItsBytesIsRefusedFirst) {
  const std::string path = tempPath("cell_dims.mat");
  const OneVariable original = split(writeCompressed(path, {"a", "bb", "ccc"}));
  const std::string element = inflateAll(original.stream);
  // The inflated element: its miMATRIX tag (8), array flags (16), dimensions tag (8), dims.
  constexpr std::size_t kDims = 8 + 16 + 8;
  ASSERT_EQ(u32(element, 0), 14u);
  ASSERT_EQ(u32(element, kDims), 3u);
  const std::uint32_t claimed = u32(element, 4);
  const auto withRows = [&](std::uint32_t rows) {
    std::string damaged = element;
    setU32(damaged, kDims, rows);
    return OneVariable{original.header, deflateAll(damaged)}.file();
  };
  EXPECT_EQ(refusal(path, withRows(1000000000)),
            path + ": variable 'names' claims 1000000000x1 elements, more than its " +
                std::to_string(claimed) + " bytes hold (corrupted file)");
  EXPECT_EQ(refusal(path, withRows(4)),
            path + ": variable 'names' has its cell element 4 beyond its end (corrupted file)");
  EXPECT_EQ(refusal(path, withRows(3)), "");
  EXPECT_EQ(MatReader(path).readStrings("names"), (std::vector<std::string>{"a", "bb", "ccc"}));
  std::remove(path.c_str());
}

TEST(MatStructure, AStreamShorterThanItsHeadersClaimIsNamed) {
  const std::string path = tempPath("short.mat");
  const OneVariable original = split(writeCompressed(path, {"a", "bb", "ccc"}));
  std::string element = inflateAll(original.stream);
  const std::uint32_t claimed = u32(element, 4);
  setU32(element, 4, claimed + 4096);
  EXPECT_EQ(refusal(path, OneVariable{original.header, deflateAll(element)}.file()),
            path + ": variable 'names' has compressed data that ends after " +
                std::to_string(element.size()) +
                " bytes, 4096 short of what its headers claim (corrupted file)");
  std::remove(path.c_str());
}

// zlib's own faults: a header that is not zlib's, a check value that does not match the data,
// a stream cut before its end; and an inflated element that is not an array.
TEST(MatStructure, DamagedStreamsAreNamedAsSuch) {
  const std::string path = tempPath("damaged.mat");
  const OneVariable original = split(writeCompressed(path, {"a", "bb", "ccc"}));
  const std::string where = path + ": the compressed variable at byte 128 ";
  OneVariable damaged = original;
  damaged.stream[0] = '\0';  // CMF 0: not a multiple of 31 with FLG
  EXPECT_EQ(refusal(path, damaged.file()),
            where + "has damaged compressed data (zlib: incorrect header check) (corrupted file)");
  // The Adler-32 value of the inflated bytes closes the stream: checked once the headers are,
  // so the variable has its name.
  damaged = original;
  damaged.stream.back() = static_cast<char>(damaged.stream.back() ^ 1);
  EXPECT_EQ(refusal(path, damaged.file()),
            path +
                ": variable 'names' has damaged compressed data (zlib: incorrect data check) "
                "(corrupted file)");
  damaged = original;
  damaged.stream.resize(damaged.stream.size() - 2);
  EXPECT_EQ(refusal(path, damaged.file()),
            path +
                ": variable 'names' has its compressed data cut short (the zlib stream does "
                "not end within its element) (corrupted file)");
  damaged = original;
  damaged.stream.resize(4);
  EXPECT_EQ(refusal(path, damaged.file()),
            where +
                "has its compressed data cut short (the zlib stream does not end within its "
                "element) (corrupted file)");
  std::string element = inflateAll(original.stream);
  setU32(element, 0, 9);  // miDOUBLE
  EXPECT_EQ(refusal(path, OneVariable{original.header, deflateAll(element)}.file()),
            where + "holds data of type 9, not a matrix (corrupted file)");
  EXPECT_EQ(refusal(path, original.file()), "");
  std::remove(path.c_str());
}

// Bytes inflated past what the element's tag claims are left alone, as matio leaves them.
TEST(MatStructure, BytesPastTheClaimedElementAreIgnored) {
  const std::string path = tempPath("trailing.mat");
  const OneVariable original = split(writeCompressed(path, {"a", "bb"}));
  const std::string element = inflateAll(original.stream) + std::string(24, '\0');
  EXPECT_EQ(refusal(path, OneVariable{original.header, deflateAll(element)}.file()), "");
  EXPECT_EQ(MatReader(path).readStrings("names"), (std::vector<std::string>{"a", "bb"}));
  std::remove(path.c_str());
}

// A cell of 6,000 texts (480 kB inflated) read through the check's two 64 KiB buffers: the header
// walk and the skip to its end cross many refills.
TEST(MatStructure, LargeCompressedVariablesAreCheckedAcrossBuffers) {
  const std::string path = tempPath("large.mat");
  std::vector<std::string> names;
  for (int k = 0; k < 6000; ++k)
    names.push_back("name_" + std::to_string(k * 7919 % 100003));
  const OneVariable original = split(writeCompressed(path, names));
  EXPECT_EQ(refusal(path, original.file()), "");
  EXPECT_EQ(MatReader(path).readStrings("names"), names);
  // One entry more claimed: found only after inflating every one before it.
  std::string element = inflateAll(original.stream);
  ASSERT_GT(element.size(), 4u * 65536u);
  setU32(element, 8 + 16 + 8, 6001);
  EXPECT_EQ(refusal(path, OneVariable{original.header, deflateAll(element)}.file()),
            path + ": variable 'names' has its cell element 6001 beyond its end (corrupted file)");
  std::remove(path.c_str());
}

// The other formats MATLAB and Octave save in are named from their first bytes, and a MAT
// version that is neither 5 nor 7.3 is shown as the header writes it.
TEST(MatStructure, OtherFormatsAreNamedFromTheirFirstBytes) {
  const std::string path = tempPath("other.mat");
  const std::string padding(300, '\0');
  const auto check = [&](const std::string& start, const std::string& what) {
    writeBytes(path, start + padding);
    try {
      checkMatStructure(path);
      ADD_FAILURE() << what << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), path + ": " + what);
    }
  };
  const std::string save = ": save with -v7 or -v6 (MATLAB, Octave)";
  check(std::string("\x89HDF\r\n\x1a\n", 8),
        "not a MAT 5 or 7.3 file but an HDF5 file without the MAT header (Octave's -hdf5 "
        "format?)" +
            save);
  check("Octave-1-L", "not a MAT 5 or 7.3 file but Octave's binary format (-binary)" + save);
  check(std::string("\x1f\x8b\x08", 3),
        "not a MAT 5 or 7.3 file but a gzip file (Octave's -zip): save with -v7, or with -v6 "
        "without -zip");
  check("# Created by Octave 7.3.0, Mon Dec 07 18:40:00 2026 UTC <root@host>\n",
        "not a MAT 5 or 7.3 file but Octave's text format (its default)" + save);
  // A MAT 4 file starts with its first matrix's type and sizes: no MAT 5 header.
  check(std::string("\x00\x00\x00\x00\x01\x00\x00\x00", 8),
        "not a MAT 5 or 7.3 file (no endian indicator in its header: a MAT 4 file, -v4, or no "
        "MAT file at all): save with -v7 or -v6 (MATLAB, Octave)");
  std::string header(128, ' ');
  header.replace(124, 4, std::string("\x00\x03IM", 4));
  check(header, "unsupported MAT file version 0x0300 (MAT 5 files have 0x0100, 7.3 ones 0x0200)");
  std::remove(path.c_str());
}

// A number saved as another class is refused naming the class found (MATLAB may store whole
// numbers as integers; SciPy's loadmat then returns them so unless mat_dtype=True).
TEST(MatStructure, AVariableOfAnotherClassIsNamedByIt) {
  const std::string path = tempPath("classes.mat");
  {
    mat_t* mat = Mat_CreateVer(path.c_str(), nullptr, MAT_FT_MAT5);
    ASSERT_NE(mat, nullptr);
    std::size_t d[2] = {2, 1};
    std::int32_t integers[2] = {1, 2};
    float singles[2] = {1.5f, 2.5f};
    double reals[2] = {1, 2}, imaginaries[2] = {0, 1};
    std::uint8_t flags[2] = {1, 0};
    mat_complex_split_t complex{reals, imaginaries};
    matvar_t* vars[] = {
        Mat_VarCreate("a", MAT_C_INT32, MAT_T_INT32, 2, d, integers, 0),
        Mat_VarCreate("b", MAT_C_SINGLE, MAT_T_SINGLE, 2, d, singles, 0),
        Mat_VarCreate("c", MAT_C_UINT8, MAT_T_UINT8, 2, d, flags, MAT_F_LOGICAL),
        Mat_VarCreate("d", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, d, &complex, MAT_F_COMPLEX),
        Mat_VarCreate("e", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, d, reals, 0)};
    for (matvar_t* v : vars) {
      ASSERT_NE(v, nullptr);
      ASSERT_EQ(Mat_VarWrite(mat, v, MAT_COMPRESSION_NONE), 0);
      Mat_VarFree(v);
    }
    Mat_Close(mat);
  }
  const MatReader in(path);
  const std::vector<std::pair<std::string, std::string>> classes = {
      {"a", "int32"}, {"b", "single"}, {"c", "logical"}, {"d", "complex double"}};
  for (const auto& [name, class_name] : classes) {
    EXPECT_EQ(in.className(name), class_name);
    try {
      in.readMatrix(name);
      ADD_FAILURE() << name << " read as a real double matrix";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), path + ": variable '" + name + "' is of class " +
                                           class_name + ", expected a real double matrix");
    }
  }
  EXPECT_EQ(in.className("e"), "double");
  EXPECT_EQ(in.readMatrix("e", kAnySize, 1), (Matrix(2, 1) << 1, 2).finished());
  try {
    in.readMatrix("e", 1, kAnySize);
    ADD_FAILURE() << "a column read as a row";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": variable 'e' is 2x1, expected 1xn");
  }
  std::remove(path.c_str());
}

// MAT 5 elements built byte by byte (little-endian), for the layouts no writer here makes.
std::string le32(std::uint32_t v) {
  std::string bytes(4, '\0');
  setU32(bytes, 0, v);
  return bytes;
}

// A full data element: tag (type, byte count) and its data padded to 8 bytes.
std::string element(std::uint32_t type, const std::string& data) {
  std::string bytes = le32(type) + le32(static_cast<std::uint32_t>(data.size())) + data;
  return bytes + std::string((8 - bytes.size() % 8) % 8, '\0');
}

// An array element (miMATRIX): flags with its class, dimensions (miINT32 unless given), name,
// then `rest` (its data, a struct's field names and fields, a cell's elements).
std::string array(std::uint32_t array_class, const std::vector<std::uint32_t>& dims,
                  const std::string& name, const std::string& rest, std::uint32_t dims_type = 5) {
  std::string d;
  for (const std::uint32_t n : dims)
    d += le32(n);
  return element(14, element(6, le32(array_class) + le32(0)) + element(dims_type, d) +
                         element(1, name) + rest);
}

std::string oneDouble(const std::string& name, double value) {
  std::string data(8, '\0');
  std::memcpy(data.data(), &value, 8);
  return array(6, {1, 1}, name, element(9, data));
}

// A struct's field-name length (8) and names, then its fields.
std::string structFields(const std::vector<std::string>& names, const std::string& fields) {
  std::string text;
  for (const std::string& name : names)
    text += name + std::string(8 - name.size(), '\0');
  return element(5, le32(8)) + element(1, text) + fields;
}

std::string matFile(const std::vector<std::string>& elements) {
  std::string bytes(116, ' ');
  bytes.replace(0, 19, "MATLAB 5.0 MAT-file");
  bytes += std::string(8, '\0') + std::string("\x00\x01IM", 4);
  for (const std::string& e : elements)
    bytes += e;
  return bytes;
}

// The element compressed (no padding after a compressed element).
std::string compressed(const std::string& element) {
  const std::string z = deflateAll(element);
  return le32(kMiCompressed) + le32(static_cast<std::uint32_t>(z.size())) + z;
}

// A struct's fields are arrays of their own, checked as a cell's elements are (a field claiming
// 2e8 entries took 4.6 s and 1.5 GB in matio); a struct's elements store a tag per field, and
// one without fields stores nothing per element.
TEST(MatStructure, StructFieldsAreCheckedAsCellElementsAre) {
  const std::string path = tempPath("struct.mat");
  const std::string bad_field = array(1, {200000000, 1}, "", "");
  const std::string bad = array(2, {1, 1}, "s", structFields({"f"}, bad_field));
  const std::string claimed = std::to_string(u32(bad_field, 4));
  for (const std::string& variable : {bad, compressed(bad)})
    EXPECT_EQ(refusal(path, matFile({variable})),
              path +
                  ": variable 's' (field 1 of element 1) claims 200000000x1 elements, more "
                  "than its " +
                  claimed + " bytes hold (corrupted file)");
  const std::string good =
      array(2, {1, 2}, "s",
            structFields({"a", "bb"}, oneDouble("", 1) + oneDouble("", 2) + oneDouble("", 3) +
                                          oneDouble("", 4)));
  EXPECT_EQ(refusal(path, matFile({good, compressed(oneDouble("t", 5))})), "");
  EXPECT_EQ(MatReader(path).className("s"), "struct");
  // Three elements of two fields need six field arrays.
  const std::string short_of_fields =
      array(2, {3, 1}, "s", structFields({"a", "bb"}, oneDouble("", 1) + oneDouble("", 2)));
  EXPECT_EQ(refusal(path, matFile({short_of_fields})),
            path + ": variable 's' has its field 1 of element 2 beyond its end (corrupted file)");
  const std::string many = array(2, {1000, 1}, "s", structFields({"a", "bb"}, oneDouble("", 1)));
  EXPECT_EQ(refusal(path, matFile({many})),
            path + ": variable 's' claims 1000x1 elements, more than its " +
                std::to_string(u32(many, 4)) + " bytes hold (corrupted file)");
  // Octave's repmat(struct(), 100, 1): no fields, nothing stored per element.
  EXPECT_EQ(refusal(path, matFile({array(2, {100, 1}, "s", structFields({}, ""))})), "");
  std::remove(path.c_str());
}

// MATLAB's class objects (a string, a table) are listed by matio without a name and not read:
// they are passed over, and a variable then missing says why it may be.
TEST(MatStructure, MatlabClassObjectsArePassedOver) {
  const std::string path = tempPath("opaque.mat");
  const std::string object = element(
      14, element(6, le32(17) + le32(0)) + element(1, "s") + element(1, "MCOS") +
              element(1, "string") + array(13, {6, 1}, "", element(6, std::string(24, '\1'))));
  for (const std::string& variable : {object, compressed(object)}) {
    EXPECT_EQ(refusal(path, matFile({oneDouble("a", 2.5), variable})), "");
    const MatReader in(path);
    EXPECT_EQ(in.names(), std::vector<std::string>{"a"});
    EXPECT_EQ(in.readScalar("a"), 2.5);
    try {
      in.readString("s");
      ADD_FAILURE() << "a MATLAB string read";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                path +
                    ": variable 's' is missing (the file holds 1 MATLAB class object(s), e.g. "
                    "strings, which are not read: save texts as char arrays, 'text' rather "
                    "than \"text\")");
    }
  }
  std::remove(path.c_str());
}

// Dimensions stored as miUINT32 (a writer SciPy's tests keep) are refused: matio 1.5 stops
// listing there, and the variables from that one on would vanish. More than 64 dimensions, or
// arrays nested more than 32 deep, are refused before matio allocates for them (12 bytes a
// dimension: a compressed run of ones costs gigabytes from kilobytes).
TEST(MatStructure, DimensionsAndNestingHaveLimits) {
  const std::string path = tempPath("limits.mat");
  std::string data(8, '\0');
  const double value = 4.25;
  std::memcpy(data.data(), &value, 8);
  EXPECT_EQ(refusal(path, matFile({array(6, {1, 1}, "u", element(9, data), 6)})),
            path +
                ": the variable at byte 128 has dimensions other than two or more 32-bit "
                "integers (corrupted file)");
  EXPECT_EQ(refusal(path, matFile({compressed(array(6, std::vector<std::uint32_t>(64, 1), "d",
                                                    element(9, data)))})),
            "");
  EXPECT_EQ(refusal(path, matFile({compressed(array(6, std::vector<std::uint32_t>(65, 1), "d",
                                                    element(9, data)))})),
            path +
                ": the compressed variable at byte 128 has 65 dimensions (more than 64 are "
                "not read)");
  // n cells, each holding the next, around a double: that double is n deep.
  const auto nested = [&](int n) {
    std::string inner = oneDouble("", 1);
    for (int k = 0; k < n; ++k)
      inner = array(1, {1, 1}, k + 1 == n ? "deep" : "", inner);
    return inner;
  };
  EXPECT_EQ(refusal(path, matFile({nested(32)})), "");
  EXPECT_EQ(refusal(path, matFile({compressed(nested(33))})),
            path + ": variable 'deep' holds arrays nested more than 32 deep (not read)");
  std::remove(path.c_str());
}

}  // namespace
}  // namespace io
}  // namespace tracked_vehicle_dynamics

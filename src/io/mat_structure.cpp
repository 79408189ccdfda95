#include "tracked_vehicle_dynamics/io/mat_structure.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <new>
#include <stdexcept>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace io {

namespace {

// MAT 5 layout (MathWorks, "MAT-File Format", 2023): a 128-byte header whose last four bytes
// hold the version (0x0100, or 0x0200 for a 7.3 HDF5 file) and the endian indicator "IM",
// followed by top-level data elements, each an 8-byte tag (type, byte count) and its data. A
// compressed element (miCOMPRESSED) holds a zlib stream whose inflated bytes are one miMATRIX
// element, tag included.
constexpr std::size_t kMat5HeaderBytes = 128;
constexpr std::uint32_t kMiInt32 = 5;
constexpr std::uint32_t kMiUint32 = 6;
constexpr std::uint32_t kMiMatrix = 14;
constexpr std::uint32_t kMiCompressed = 15;
constexpr std::uint32_t kCellClass = 1;       // mxCELL_CLASS
constexpr std::uint32_t kStructClass = 2;     // mxSTRUCT_CLASS
constexpr std::uint32_t kObjectClass = 3;     // mxOBJECT_CLASS
constexpr std::uint32_t kSparseClass = 5;     // mxSPARSE_CLASS
constexpr std::uint32_t kFunctionClass = 16;  // mxFUNCTION_CLASS
constexpr std::uint32_t kOpaqueClass = 17;    // mxOPAQUE_CLASS (MATLAB's class objects)
// Arrays nested in cells and structs deeper than this are refused rather than walked (ours hold
// texts in cells: one level; matio recurses as deep as the file goes).
constexpr int kMaxDepth = 32;
// More dimensions than any variable needs (MATLAB's own arrays rarely pass 10).
constexpr std::uint64_t kMaxDimensions = 64;
// Dimensions shown in a message; a damaged header may claim millions.
constexpr std::size_t kShownDimensions = 8;
// Bytes read from the file, and inflated, at a time.
constexpr std::size_t kChunkBytes = 1 << 16;

std::uint32_t readU32(const unsigned char* p, bool swap) {
  std::uint32_t v = static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
                    static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
  if (swap)
    v = (v >> 24) | ((v >> 8) & 0xFF00u) | ((v << 8) & 0xFF0000u) | (v << 24);
  return v;
}

// What a stream of array bytes could not give; ArrayHeaderCheck names the variable.
struct StreamFault {
  std::string why;
};

// An array element's bytes by offset: the file's own, or a compressed element's inflated ones.
class ByteSource {
 public:
  virtual ~ByteSource() = default;
  // The n bytes at `offset` into dst. Offsets are those of the element's container (the file, or
  // the inflated stream); the caller has checked them against the element's claimed end.
  virtual void read(std::uint64_t offset, unsigned char* dst, std::size_t n) = 0;
};

// An uncompressed element: the checks before have placed it inside the file.
class FileBytes : public ByteSource {
 public:
  explicit FileBytes(std::ifstream& in) : in_(in) {}
  void read(std::uint64_t offset, unsigned char* dst, std::size_t n) override {
    in_.seekg(static_cast<std::streamoff>(offset));
    in_.read(reinterpret_cast<char*>(dst), static_cast<std::streamsize>(n));
  }

 private:
  std::ifstream& in_;
};

// A compressed element's zlib stream, inflated forward only: a read further on inflates and drops
// the bytes before it, so checking a variable of any size holds two 64 KiB buffers. The header
// walk reads in increasing offsets (ArrayHeaderCheck::check).
class InflatedBytes : public ByteSource {
 public:
  // The stream is the `bytes` bytes at file offset `begin`.
  InflatedBytes(std::ifstream& in, std::uint64_t begin, std::uint64_t bytes)
      : in_(in),
        next_in_(begin),
        end_in_(begin + bytes),
        input_(kChunkBytes),
        output_(kChunkBytes) {
    if (inflateInit(&z_) != Z_OK)
      throw std::bad_alloc();
  }
  ~InflatedBytes() override { inflateEnd(&z_); }
  InflatedBytes(const InflatedBytes&) = delete;
  InflatedBytes& operator=(const InflatedBytes&) = delete;

  void read(std::uint64_t offset, unsigned char* dst, std::size_t n) override {
    if (offset < position_)
      throw std::logic_error("InflatedBytes read backwards");
    take(nullptr, offset - position_);
    take(dst, n);
  }
  // Inflates (and drops) everything up to `offset`: the data the headers claim are there.
  void skipTo(std::uint64_t offset) {
    if (offset > position_)
      take(nullptr, offset - position_);
  }
  // Inflates to the stream's end, where zlib compares its Adler-32 check value. Bytes past what
  // the headers claim are left alone, as matio leaves them.
  void finish() {
    while (!ended_) {
      z_.next_out = output_.data();
      z_.avail_out = static_cast<uInt>(output_.size());
      step();
    }
    ready_ = 0;
  }

 private:
  // The next n inflated bytes, into dst or (nullptr) dropped.
  void take(unsigned char* dst, std::uint64_t n) {
    while (n > 0) {
      if (ready_ == 0)
        inflateMore(n);
      const std::size_t count = static_cast<std::size_t>(std::min<std::uint64_t>(n, ready_));
      if (dst) {
        std::memcpy(dst, output_.data() + first_, count);
        dst += count;
      }
      first_ += count;
      ready_ -= count;
      position_ += count;
      n -= count;
    }
  }
  // Refills the output buffer with at least one byte; `wanted` (bytes still to take) is what a
  // stream ending early could not give.
  void inflateMore(std::uint64_t wanted) {
    first_ = 0;
    z_.next_out = output_.data();
    z_.avail_out = static_cast<uInt>(output_.size());
    while (z_.avail_out == output_.size()) {
      if (ended_)
        throw StreamFault{"has compressed data that ends after " + std::to_string(position_) +
                          " bytes, " + std::to_string(wanted) + " short of what its headers claim"};
      step();
    }
    ready_ = output_.size() - z_.avail_out;
  }
  // One inflate call into the output space set, reading more of the element first if needed.
  void step() {
    if (!fault_.empty())
      throw StreamFault{fault_};
    if (z_.avail_in == 0) {
      if (next_in_ == end_in_)
        throw StreamFault{
            "has its compressed data cut short (the zlib stream does not end within its element)"};
      const auto count =
          static_cast<std::size_t>(std::min<std::uint64_t>(input_.size(), end_in_ - next_in_));
      in_.seekg(static_cast<std::streamoff>(next_in_));
      in_.read(reinterpret_cast<char*>(input_.data()), static_cast<std::streamsize>(count));
      next_in_ += count;
      z_.next_in = input_.data();
      z_.avail_in = static_cast<uInt>(count);
    }
    const uInt space = z_.avail_out;
    const int status = inflate(&z_, Z_NO_FLUSH);
    if (status == Z_STREAM_END) {
      ended_ = true;
    } else if (status == Z_MEM_ERROR) {
      throw std::bad_alloc();
    } else if (status != Z_OK && status != Z_BUF_ERROR) {
      // What this call inflated before the fault is taken first (a small stream's check value
      // fails in the call that inflates all of it): the fault is met where the bytes run out,
      // by then with the variable's name read.
      fault_ = std::string("has damaged compressed data (zlib: ") +
               (z_.msg ? z_.msg : "error " + std::to_string(status)) + ")";
      if (z_.avail_out == space)
        throw StreamFault{fault_};
    }
  }

  std::ifstream& in_;
  std::uint64_t next_in_;  // file offset of the next compressed byte to read
  std::uint64_t end_in_;
  std::vector<unsigned char> input_;
  std::vector<unsigned char> output_;
  std::size_t first_ = 0;  // the output buffer's bytes [first_, first_ + ready_) are not taken
  std::size_t ready_ = 0;
  std::uint64_t position_ = 0;  // inflated offset of output_[first_]
  bool ended_ = false;
  std::string fault_;  // zlib's, once met
  z_stream z_{};
};

// A data element's tag inside an array: the full form (type, byte count; data padded to 8
// bytes) or the small one (byte count in the upper 16 bits of the first word, up to 4 bytes of
// data in the second).
struct SubTag {
  std::uint32_t type = 0;
  std::uint64_t bytes = 0;
  std::uint64_t data = 0;  // offset of the data
  std::uint64_t next = 0;  // offset after the element
};

// The headers inside an array element (type miMATRIX): its dimensions and its name must fit in
// the element's own bytes. matio trusts them and allocates before it reads: a cell claiming 1e9
// elements took 8 GB and 44 s, a name length of 2^31 2 GB, and 4e8 in a compressed cell 3.1 GB
// and 9 s, a struct field claiming 2e8 entries 1.5 GB. Every array but a sparse one (dimensions
// independent of its stored non-zeros) stores at least one byte per element, a cell one 8-byte
// tag, a struct or object one per field; the cell's elements and the struct's fields are arrays
// checked in turn.
class ArrayHeaderCheck {
 public:
  ArrayHeaderCheck(ByteSource& bytes, bool big, const std::string& path)
      : bytes_(bytes), big_(big), path_(path) {}

  // The array whose data (after its miMATRIX tag) spans [begin, end); `where` names it in the
  // messages ("the variable at byte N", a cell's element "variable 'X'{3}", a struct's field
  // "variable 'X' (field 2 of element 1)"), a top-level one (depth 0) by its own name once that
  // is read.
  void check(std::uint64_t begin, std::uint64_t end, int depth, std::string where) {
    if (depth == 0)
      top_ = where;
    try {
      checkArray(begin, end, depth, where);
    } catch (const StreamFault& fault) {
      corrupted(top_, fault.why);
    }
  }

  // The top-level array as named by the last check: its name, once read.
  const std::string& named() const { return top_; }

 private:
  void checkArray(std::uint64_t begin, std::uint64_t end, int depth, std::string where) {
    if (begin == end)
      return;  // an empty element: MATLAB's empty cell entries
    if (depth > kMaxDepth)
      throw InputError(path_ + ": " + top_ + " holds arrays nested more than " +
                       std::to_string(kMaxDepth) + " deep (not read)");
    const SubTag flags = tag(begin, end, where, "array flags");
    if (flags.type != kMiUint32 || flags.bytes != 8)
      corrupted(where, "has array flags other than two 32-bit words");
    const std::uint32_t array_class = word(flags.data) & 0xFFu;
    // MATLAB's class objects (string, table, datetime: opaque) and function handles have no
    // dimensions of this layout; matio lists them without reading their contents.
    if (array_class == kFunctionClass || array_class == kOpaqueClass)
      return;
    const SubTag dims_tag = tag(flags.next, end, where, "dimensions");
    // (miUINT32 dimensions, which a writer in SciPy's tests uses, matio 1.5 stops listing at:
    // the variable and every one after it would vanish.)
    if (dims_tag.type != kMiInt32 || dims_tag.bytes < 8 || dims_tag.bytes % 4 != 0)
      corrupted(where, "has dimensions other than two or more 32-bit integers");
    // matio keeps 12 bytes per dimension: a compressed run of a billion ones would cost 12 GB.
    if (dims_tag.bytes / 4 > kMaxDimensions)
      throw InputError(path_ + ": " + where + " has " + std::to_string(dims_tag.bytes / 4) +
                       " dimensions (more than " + std::to_string(kMaxDimensions) +
                       " are not read)");
    // The dimensions are read before the name that follows them (a compressed stream is read
    // forward), and judged once the name can say whose they are.
    std::uint64_t elements = 1;
    std::string shape;
    bool negative = false;
    const std::uint64_t capacity = end - begin;
    for (std::uint64_t at = dims_tag.data; at < dims_tag.data + dims_tag.bytes; at += 4) {
      const std::uint32_t dim = word(at);
      const std::uint64_t k = (at - dims_tag.data) / 4;
      if (k < kShownDimensions)
        shape += (k == 0 ? "" : "x") + std::to_string(static_cast<std::int32_t>(dim));
      else if (k == kShownDimensions)
        shape += "x...";
      negative = negative || dim > 0x7FFFFFFFu;
      elements =
          dim == 0 || elements == 0 ? 0 : std::min<std::uint64_t>(elements * dim, capacity + 1);
    }
    const SubTag name = tag(dims_tag.next, end, where, "name");
    if (depth == 0 && name.bytes > 0 && name.bytes <= kMaxMatNameLength) {
      std::string text(name.bytes, '\0');
      bytes_.read(name.data, reinterpret_cast<unsigned char*>(text.data()), text.size());
      if (isMatIdentifier(text)) {
        where = "variable '" + text + "'";
        top_ = where;
      }
    }
    if (negative)
      corrupted(where, "has a negative dimension (" + shape + ")");
    // What each element stores at least: a byte of a numeric or text array, a cell's 8-byte
    // tag, a struct's (or object's) tag per field. matio allocates by the dimensions (and a
    // struct's field count by its names) before it reads.
    std::uint64_t at = name.next;
    std::uint64_t fields = 1;
    std::uint64_t per_element = array_class == kCellClass ? 8 : 1;
    if (array_class == kStructClass || array_class == kObjectClass) {
      if (array_class == kObjectClass)
        at = tag(at, end, where, "class name").next;
      const SubTag length = tag(at, end, where, "field name length");
      if (length.type != kMiInt32 || length.bytes != 4)
        corrupted(where, "has a field name length other than one 32-bit integer");
      const std::uint32_t name_length = word(length.data);
      const SubTag names = tag(length.next, end, where, "field names");
      if (name_length == 0 ? names.bytes != 0 : names.bytes % name_length != 0)
        corrupted(where, "has field names of " + std::to_string(names.bytes) +
                             " bytes, not a whole number of " + std::to_string(name_length) +
                             "-byte names");
      fields = name_length == 0 ? 0 : names.bytes / name_length;
      per_element = 8 * fields;
      at = names.next;
    }
    if (array_class != kSparseClass && per_element > 0 && elements > capacity / per_element)
      corrupted(where, "claims " + shape + " elements, more than its " + std::to_string(capacity) +
                           " bytes hold");
    if (array_class != kCellClass && array_class != kStructClass && array_class != kObjectClass)
      return;
    // A cell's elements, or a struct's fields element by element, each an array of its own.
    const bool cell = array_class == kCellClass;
    for (std::uint64_t k = 0; k < elements * fields; ++k) {
      const std::string what = cell ? "cell element " + std::to_string(k + 1)
                                    : "field " + std::to_string(k % fields + 1) + " of element " +
                                          std::to_string(k / fields + 1);
      const std::string element_where =
          cell ? where + "{" + std::to_string(k + 1) + "}" : where + " (" + what + ")";
      const SubTag element = tag(at, end, where, what);
      if (element.type != kMiMatrix)
        corrupted(element_where, "is not an array");
      checkArray(element.data, element.data + element.bytes, depth + 1, element_where);
      at = element.next;
    }
  }

  std::uint32_t word(std::uint64_t offset) {
    unsigned char bytes[4];
    bytes_.read(offset, bytes, 4);
    return readU32(bytes, big_);
  }
  SubTag tag(std::uint64_t offset, std::uint64_t end, const std::string& where,
             const std::string& what) {
    if (offset + 8 > end)
      corrupted(where, "has its " + what + " beyond its end");
    SubTag t;
    const std::uint32_t first = word(offset);
    if (first >> 16 != 0) {  // small data element
      t.type = first & 0xFFFFu;
      t.bytes = first >> 16;
      t.data = offset + 4;
      t.next = offset + 8;
      if (t.bytes > 4)
        corrupted(where, "has its " + what + " as a small element of more than 4 bytes");
      return t;
    }
    t.type = first;
    t.bytes = word(offset + 4);
    t.data = offset + 8;
    if (t.data + t.bytes > end)
      corrupted(where, "has its " + what + " claiming " + std::to_string(t.bytes) +
                           " bytes, beyond its end");
    t.next = std::min(t.data + (t.bytes + 7) / 8 * 8, end);
    return t;
  }
  [[noreturn]] void corrupted(const std::string& where, const std::string& why) {
    throw InputError(path_ + ": " + where + " " + why + " (corrupted file)");
  }

  ByteSource& bytes_;
  bool big_;
  const std::string& path_;
  std::string top_;  // the top-level array, named as far as known (for a stream's faults)
};

// A compressed element at file offset `offset` whose zlib stream is its `bytes` bytes after the
// tag: the inflated miMATRIX element's headers, then every byte its tag claims.
void checkCompressed(std::ifstream& in, bool big, const std::string& path, std::uint64_t offset,
                     std::uint64_t bytes) {
  InflatedBytes stream(in, offset + 8, bytes);
  ArrayHeaderCheck check(stream, big, path);
  const std::string where = "the compressed variable at byte " + std::to_string(offset);
  unsigned char tag[8];
  try {
    stream.read(0, tag, 8);
  } catch (const StreamFault& fault) {
    throw InputError(path + ": " + where + " " + fault.why + " (corrupted file)");
  }
  const std::uint32_t type = readU32(tag, big);
  if (type != kMiMatrix)
    throw InputError(path + ": " + where + " holds data of type " + std::to_string(type) +
                     ", not a matrix (corrupted file)");
  const std::uint64_t claimed = readU32(tag + 4, big);
  check.check(8, 8 + claimed, 0, where);
  try {
    stream.skipTo(8 + claimed);
    stream.finish();
  } catch (const StreamFault& fault) {
    throw InputError(path + ": " + check.named() + " " + fault.why + " (corrupted file)");
  }
}

// What a file that is not a MAT 5 or 7.3 one is, from its first bytes, and how to save it, for
// the files MATLAB and Octave write in their other formats; "" when it is none of those.
std::string otherFormat(const unsigned char* start, std::uint64_t size) {
  const std::string save = ": save with -v7 or -v6 (MATLAB, Octave)";
  const auto startsWith = [&](const char* text, std::size_t n) {
    return size >= n && std::memcmp(start, text, n) == 0;
  };
  if (startsWith("\x89HDF\r\n\x1a\n", 8))
    return "an HDF5 file without the MAT header (Octave's -hdf5 format?)" + save;
  if (startsWith("Octave-1-L", 10) || startsWith("Octave-1-B", 10))
    return "Octave's binary format (-binary)" + save;
  if (startsWith("\x1f\x8b", 2))
    return "a gzip file (Octave's -zip): save with -v7, or with -v6 without -zip";
  if (startsWith("# Created by Octave", 19))
    return "Octave's text format (its default)" + save;
  return "";
}

// 0x and four hex digits, as MAT versions are written.
std::string hex4(unsigned value) {
  char text[8];
  std::snprintf(text, sizeof(text), "0x%04X", value & 0xFFFFu);
  return text;
}

}  // namespace

bool isMatIdentifier(const std::string& name) {
  if (name.empty() || name.size() > kMaxMatNameLength)
    return false;
  if (!std::isalpha(static_cast<unsigned char>(name[0])))
    return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

namespace {

// The header of a MAT file: its format and, for MAT 5, whether its numbers are big-endian.
// Throws InputError naming a file that is neither MAT 5 nor 7.3.
struct MatHeader {
  MatFormat format = MatFormat::Mat5;
  bool big = false;
};

MatHeader readHeader(std::ifstream& in, std::uint64_t size, const std::string& path) {
  unsigned char header[kMat5HeaderBytes] = {};
  in.seekg(0);
  in.read(reinterpret_cast<char*>(header),
          static_cast<std::streamsize>(std::min<std::uint64_t>(size, kMat5HeaderBytes)));
  const std::string other = otherFormat(header, size);
  if (!other.empty())
    throw InputError(path + ": not a MAT 5 or 7.3 file but " + other);
  if (size < kMat5HeaderBytes)
    throw InputError(path + ": not a MAT 5 or 7.3 file (" + std::to_string(size) +
                     " bytes, shorter than their 128-byte header: a MAT 4 file, -v4, or no MAT "
                     "file at all): save with -v7 or -v6 (MATLAB, Octave)");
  const bool little = header[126] == 'I' && header[127] == 'M';
  const bool big = header[126] == 'M' && header[127] == 'I';
  if (!little && !big)
    throw InputError(path +
                     ": not a MAT 5 or 7.3 file (no endian indicator in its header: a MAT 4 "
                     "file, -v4, or no MAT file at all): save with -v7 or -v6 (MATLAB, Octave)");
  const unsigned version = little ? header[124] | header[125] << 8 : header[125] | header[124] << 8;
  if (version == 0x0200)
    return {MatFormat::Mat73, big};
  if (version != 0x0100)
    throw InputError(path + ": unsupported MAT file version " + hex4(version) +
                     " (MAT 5 files have 0x0100, 7.3 ones 0x0200)");
  return {MatFormat::Mat5, big};
}

// Each top-level data element of a MAT 5 file, in order: visit(type, offset of its tag, byte
// count). Throws InputError for an element the file's end cuts (or bytes appended after the
// last) and for one that is not a matrix.
template <typename Visit>
void forEachElement(std::ifstream& in, std::uint64_t size, bool big, const std::string& path,
                    Visit visit) {
  std::uint64_t offset = kMat5HeaderBytes;
  while (offset < size) {
    unsigned char tag[8];
    if (offset + 8 > size)
      throw InputError(path +
                       ": truncated (or bytes appended after its last variable): a data "
                       "element starts at byte " +
                       std::to_string(offset) + " but the file ends at byte " +
                       std::to_string(size));
    in.seekg(static_cast<std::streamoff>(offset));
    in.read(reinterpret_cast<char*>(tag), 8);
    const std::uint32_t type = readU32(tag, big);
    const std::uint64_t bytes = readU32(tag + 4, big);
    if (type != kMiMatrix && type != kMiCompressed)
      throw InputError(path + ": corrupted: data element at byte " + std::to_string(offset) +
                       " has type " + std::to_string(type) + " (expected a matrix)");
    std::uint64_t end = offset + 8 + bytes;
    if (type == kMiMatrix)
      end = (end + 7) / 8 * 8;  // uncompressed elements are 8-byte aligned
    if (offset + 8 + bytes > size)
      throw InputError(path +
                       ": truncated (or bytes appended after its last variable): the "
                       "data element at byte " +
                       std::to_string(offset) + " needs " + std::to_string(bytes) +
                       " bytes but the file ends at byte " + std::to_string(size));
    visit(type, offset, bytes);
    offset = std::min(end, size);
  }
}

std::ifstream openForStructure(const std::string& path, std::uint64_t* size) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in)
    throw InputError(path + ": cannot be opened for reading");
  *size = static_cast<std::uint64_t>(in.tellg());
  return in;
}

}  // namespace

MatFormat checkMatStructure(const std::string& path) {
  std::uint64_t size = 0;
  std::ifstream in = openForStructure(path, &size);
  const MatHeader header = readHeader(in, size, path);
  if (header.format == MatFormat::Mat73)
    return MatFormat::Mat73;
  const bool big = header.big;
  forEachElement(in, size, big, path,
                 [&](std::uint32_t type, std::uint64_t offset, std::uint64_t bytes) {
                   if (type == kMiMatrix) {
                     FileBytes file(in);
                     ArrayHeaderCheck(file, big, path)
                         .check(offset + 8, offset + 8 + bytes, 0,
                                "the variable at byte " + std::to_string(offset));
                   } else {
                     checkCompressed(in, big, path, offset, bytes);
                   }
                 });
  return MatFormat::Mat5;
}

std::size_t countMat5Variables(const std::string& path) {
  std::uint64_t size = 0;
  std::ifstream in = openForStructure(path, &size);
  const MatHeader header = readHeader(in, size, path);
  if (header.format != MatFormat::Mat5)
    throw InputError(path + ": a MAT 7.3 file, not a MAT 5 one");
  std::size_t count = 0;
  forEachElement(in, size, header.big, path,
                 [&](std::uint32_t, std::uint64_t, std::uint64_t) { ++count; });
  return count;
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics

// The structure of a MAT file checked before matio reads it: matio trusts the byte counts,
// dimensions and name lengths it finds and allocates what they claim before reading, so a
// truncated or damaged file would make it read past the end or allocate gigabytes.
#pragma once

#include <cstddef>
#include <string>

#include "tracked_vehicle_dynamics/io/mat_file.h"

namespace tracked_vehicle_dynamics {
namespace io {

/// MATLAB's limit on identifier length (namelengthmax).
constexpr std::size_t kMaxMatNameLength = 63;

/// A valid MATLAB variable name: a letter, then letters, digits or '_', at most 63 characters.
bool isMatIdentifier(const std::string& name);

/// Checks a MAT 5 file's elements against its size, and every array's headers (dimensions, name,
/// a cell's elements and a struct's or object's field names and fields in turn) against the
/// bytes its element holds, in compressed elements too (inflated on the way, one buffer at a
/// time, to the end their headers claim and the stream's check value). Arrays with more than 64
/// dimensions or nested more than 32 deep are refused; MATLAB's class objects (strings, tables)
/// and function handles are passed over. A 7.3 (HDF5) file is left to the HDF5 library's own
/// checks; other formats MATLAB and Octave write are named. Returns the file's format; throws
/// InputError naming the file and the variable (or the byte where its element starts).
MatFormat checkMatStructure(const std::string& path);

/// The variables of a MAT 5 file, counted from its top-level elements' tags alone (nothing
/// inflated): what MatWriter::close() compares with the variables it wrote. Throws InputError as
/// checkMatStructure() does for a file that is not MAT 5, or whose end cuts an element.
std::size_t countMat5Variables(const std::string& path);

}  // namespace io
}  // namespace tracked_vehicle_dynamics

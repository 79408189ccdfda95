// A fast reader of YAML terrain files in the plain layouts that saveTerrainYaml and PyYAML write.
//
// The general reader (terrain_io.h) builds a yaml-cpp node per height, about 0.8 kB each: a
// 7 km road at 1 cm with four lines (2.8 million heights, 74 MB) took 2.2 GB and 23 s, and a
// 2 km road with two lines written by PyYAML's yaml.safe_dump 7.5 s and 0.57 GB. Files in these
// layouts are read here line by line into the arrays themselves instead:
//   # comment lines, blank lines (anywhere, lists included)
//   name: "text" or name: text        (printable ASCII, no quote or backslash inside; unquoted:
//                                      a letter, digit or '_', then those, ". - / ( ) +" and
//                                      single spaces)
//   spacing: 0.01 / start: 0
//   x: / y: a flow list [..], on one line or wrapped over more (each indented), or a block list
//      of "- number" lines at one indentation
//   heights: a flat list as x's (no y), or a block of rows, one per y: "- [..]" (wrapped or
//      not), or "- - a" followed by "  - b" lines (PyYAML's list of lists)
// each key at most once, in any order, values followed only by blanks or " # comment", LF or
// CR LF line ends, numbers in plain decimal ("-1.5e-3"; no '+', no quotes).
//
// Anything else (another YAML form, a value the strict reader refuses, a check of the file that
// fails) returns nullopt and the general reader reads the file: so every file reads to the same
// terrain whichever reader takes it, and every fault is still named by the general reader's
// message (file, key, line).
#pragma once

#include <optional>
#include <string>

#include "tracked_vehicle_dynamics/terrain/terrain.h"

namespace tracked_vehicle_dynamics {
namespace terrain {

/// The terrain of a plain-layout YAML file at `path` that passes every check of
/// loadTerrainYaml, or nullopt (any other file, none at that path, or not a regular file: a
/// named pipe is left whole to the general reader).
std::optional<Terrain> readPlainTerrainYaml(const std::string& path);

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics

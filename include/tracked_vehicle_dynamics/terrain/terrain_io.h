// Terrain files. Every error throws InputError naming the file and the row (CSV) or key (YAML):
//   "<file>: row 7, column 3: height 'nan' is not a finite number"
//   "<file>: heights[1]: expected 3001 heights (one per station, as heights[0]), got 3000 (line 9)"
//
// CSV (comma separated; blank lines and lines starting with '#' are ignored; "row" counts file
// lines from 1):
//   x,-2.5,0,2.5        header: a label, then the lateral position y [m] of each column
//   0.00,0,0,0          station x [m], then one height [m] per lateral line
//   0.01,0,0.001,0
// A two-column file (x,h) is uniform across the width; its header is optional ("x,h"), and a
// numeric second header cell is read as the y of that single line.
//
// YAML:
//   name: bump                # optional
//   spacing: 0.01             # [m] uniform stations start + k spacing ...
//   start: 0.0                # [m] optional, with spacing
//   x: [0.0, 0.01, ...]       # ... or explicit stations [m] (exactly one of spacing / x)
//   y: [-2.5, 0.0, 2.5]       # [m] optional: omitted = uniform across the width
//   heights:                  # [m] one list per y, each one value per station; a flat list
//     - [0.0, 0.0, ...]       #     when y is omitted
//
// Stations and lateral positions must be strictly increasing and all values finite.
#pragma once

#include <string>

#include "tracked_vehicle_dynamics/terrain/terrain.h"
#include "tracked_vehicle_dynamics/terrain/tracks.h"

namespace tracked_vehicle_dynamics {
namespace terrain {

/// Reads a CSV terrain; the Terrain is named after the file stem. Throws InputError.
Terrain loadTerrainCsv(const std::string& path);
/// Reads a YAML terrain; named by its `name` key, else the file stem. Throws InputError.
/// A file in the layouts saveTerrainYaml and PyYAML write is read line by line
/// (terrain_yaml_plain.h: a 74 MB road read and simulated in 2-3 s, in the memory of its
/// arrays), any other by loadTerrainYamlGeneral(), which also names every fault.
Terrain loadTerrainYaml(const std::string& path);
/// Reads any YAML terrain through a yaml-cpp tree: about 0.8 kB per height (a 2.8-million-height
/// road, 2.2 GB). Throws InputError naming the file, key and line of a fault.
Terrain loadTerrainYamlGeneral(const std::string& path);
/// loadTerrainCsv() for ".csv", loadTerrainYaml() for ".yaml"/".yml"; InputError otherwise.
Terrain loadTerrain(const std::string& path);

/// A built-in track (tracks.h: makeTrack(track, options), "half_round:0.2" included) or, when
/// `track` names none, a terrain file (.csv, .yaml, .yml) in the path frame of a centre line at
/// options.lateral_offset (y = y_file - offset; 0 when unset). Throws InputError naming the
/// built-in tracks and the file extensions for anything else, the fault of a malformed
/// half-round spec (anything starting "half_round:" is read as one: a file of such a name needs a
/// directory before it, "./half_round:0.2.csv"), or the file's own error.
Terrain loadTrack(const std::string& track, const TrackOptions& options = {});

/// Writes `terrain` as CSV (every value in its shortest round-trip text, io::roundTripText: a
/// save/load round trip is exact).
/// Written through a temporary file and a rename (io::AtomicTextFile); throws InputError when the
/// file cannot be written, leaving no partial file.
void saveTerrainCsv(const Terrain& terrain, const std::string& path);
/// Writes `terrain` as YAML (shortest round-trip text, as the CSV). Throws InputError when it
/// cannot be written.
void saveTerrainYaml(const Terrain& terrain, const std::string& path);

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics

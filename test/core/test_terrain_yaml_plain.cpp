// The plain-layout YAML terrain reader against the general (yaml-cpp tree) reader: whatever it
// accepts must read to exactly the general reader's terrain, and anything else it must leave to
// the general reader.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cfloat>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/terrain/iso8608.h"
#include "tracked_vehicle_dynamics/terrain/terrain_io.h"
#include "tracked_vehicle_dynamics/terrain/terrain_yaml_plain.h"
#include "tracked_vehicle_dynamics/terrain/tracks.h"

namespace tracked_vehicle_dynamics {
namespace terrain {
namespace {

/// A file of this test's own under the temporary directory, written with `content` as given.
std::string writeFile(const std::string& name, const std::string& content) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("tvd_plain_yaml_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(path, std::ios::binary) << content;
  return path.string();
}

void expectSameTerrain(const Terrain& a, const Terrain& b, const std::string& what) {
  EXPECT_EQ(a.name(), b.name()) << what;
  EXPECT_EQ(a.stations(), b.stations()) << what;
  EXPECT_EQ(a.lateral(), b.lateral()) << what;
  EXPECT_EQ(a.heights(), b.heights()) << what;
}

/// Reads `content` both ways: the plain reader's terrain (or nullopt) and the general reader's
/// (or nullopt when it refuses the file).
struct BothReads {
  std::optional<Terrain> plain;
  std::optional<Terrain> general;
};
BothReads readBoth(const std::string& content, const std::string& name = "road.yaml") {
  const std::string path = writeFile(name, content);
  BothReads reads;
  reads.plain = readPlainTerrainYaml(path);
  try {
    reads.general = loadTerrainYamlGeneral(path);
  } catch (const InputError&) {
  }
  std::filesystem::remove(path);
  return reads;
}

/// Each file is left by the plain reader; the general one reads it, or refuses it.
void expectLeftToTheGeneralReader(const std::vector<std::string>& files, bool general_reads) {
  for (const std::string& content : files) {
    const BothReads reads = readBoth(content);
    EXPECT_FALSE(reads.plain.has_value()) << content;
    EXPECT_EQ(reads.general.has_value(), general_reads) << content;
  }
}

TEST(PlainTerrainYaml, WhatTheToolsWriteReadsAsTheGeneralReaderReadsIt) {
  Iso8608Options sides;
  sides.correlation = LateralCorrelation::IndependentSides;
  const std::vector<Terrain> terrains = {makeTrack("long_hill"), makeTrack("oop_waves"),
                                         makeIso8608('D', 50.0, 4.0, 0.03, 5, sides),
                                         Terrain(Vector::LinSpaced(3, 0.0, 2.0), Vector::Zero(1),
                                                 Matrix::Constant(1, 3, -1e-310), "it's \"odd\""),
                                         Terrain(Vector::LinSpaced(3, 0.0, 2.0), Vector::Zero(1),
                                                 Matrix::Constant(1, 3, 4.9e-324), "tiny")};
  for (const Terrain& terrain : terrains) {
    const std::string path = writeFile("saved.yaml", "");
    saveTerrainYaml(terrain, path);
    const std::optional<Terrain> plain = readPlainTerrainYaml(path);
    const Terrain general = loadTerrainYamlGeneral(path);
    const Terrain loaded = loadTerrainYaml(path);
    std::filesystem::remove(path);
    expectSameTerrain(loaded, general, terrain.name());
    expectSameTerrain(general, terrain, terrain.name());
    // A name with a quote or a backslash is escaped: the general reader's. A subnormal height is
    // the plain reader's where from_chars reads it (GCC 12), else the general one's: either way
    // the same terrain.
    const bool plain_name = terrain.name().find_first_of("\"\\") == std::string::npos;
    const bool subnormal =
        ((terrain.heights().array().abs() < DBL_MIN) && (terrain.heights().array() != 0.0)).any();
    if (!subnormal || !plain_name) {
      ASSERT_EQ(plain.has_value(), plain_name) << terrain.name();
    }
    if (plain)
      expectSameTerrain(*plain, general, terrain.name());
  }
}

// The layout a user writes by hand in the same style: spacing and start, a flat list without
// y, comments after values, CR LF line ends, items at column 0, keys in any order.
TEST(PlainTerrainYaml, HandWrittenPlainFilesRead) {
  const std::vector<std::string> files = {
      "spacing: 0.5   # m\nstart: -1\nheights: [0, 0.1, 0.2, 0]\n",
      "# a bump\r\n\r\nname: \"bump\"\r\nx: [0, 1, 2.5]\r\ny: [-1, 1]\r\nheights:\r\n"
      "- [0, 1e-2, 0]\r\n# the left line\r\n- [0, .5, -0.]\r\n",
      "heights:   # two lines\n    - [1, 2]\n    - [3, 4]\ny: [0, 2.5]\nx: [10, 11]\n",
      "spacing: 1\nheights:\n  - 0\n  - 1\n",  // a block list of numbers
      "spacing: 1\nheights: [0,\n  1]\n",      // a flow list over two lines
      "name: plain\nspacing: 1\nheights: [0, 1]\n",
      "name: Long hill (0.4 m) # c\nspacing: 1\nheights: [0, 1]\n",
      // yaml.safe_dump(d) of PyYAML: block lists, keys sorted, an unquoted name.
      "heights:\n- - 0.0\n  - -2.4059304981671113e-07\n  - 1.0e-05\n- - 0.5\n  - 0.25\n"
      "  - -0.125\nname: road_1\nx:\n- 0.0\n- 0.01\n- 0.02\ny:\n- -2.5\n- 2.5\n",
      // yaml.dump(d, default_flow_style=None): rows as flow lists wrapped at 80 columns.
      "heights:\n- [0.0, -2.4059304981671113e-07, -9.53899338654784e-07, -2.125346804862843e-06,\n"
      "  -5.774207963110057e-06]\n- [1, 2, 3, 4,\n  5]\nname: iso8608_C_seed1\n"
      "x: [0.0, 0.01, 0.02, 0.03,\n  0.04]\ny: [-2.5,\n  2.5]\n",
      // Blank and comment lines inside lists; lists indented under their keys.
      "x:\n  - 0\n\n  # the middle\n  - 1\n  - 2\nheights:\n  - - 0\n    # c\n    - 1\n"
      "    - 2\n  - [3,\n\n     4, 5]\ny: [0, 1]\n",
      "x:\n- 0\n- 1\nheights:\n- [0, 1]\n- - 2\n  - 3\ny: [0, 1]\n",  // rows of two forms
      "spacing: 1\ny: [0]\nheights:\n- [0,\n  # c\n  1]\n",  // a comment line in a flow list
  };
  for (const std::string& content : files) {
    const BothReads reads = readBoth(content);
    ASSERT_TRUE(reads.plain.has_value()) << content;
    ASSERT_TRUE(reads.general.has_value()) << content;
    expectSameTerrain(*reads.plain, *reads.general, content);
  }
}

// Valid YAML in other forms goes to the general reader, which reads it.
TEST(PlainTerrainYaml, OtherYamlFormsAreLeftToTheGeneralReader) {
  const std::vector<std::string> files = {
      "spacing: 1\nheights: [0, # c\n  1]\n",                   // a comment inside a flow list
      "spacing: 1\nheights: [0,\n1]\n",                         // a flow list's line not indented
      "spacing: +1\nheights: [0, 1]\n",                         // YAML's '+'
      "---\nspacing: 1\nheights: [0, 1]\n",                     // a document marker
      "spacing: 1\nheights: [0,\t1]\n",                         // a tab
      "\xEF\xBB\xBFspacing: 1\nheights: [0, 1]\n",              // a byte-order mark
      "name: 'single'\nspacing: 1\nheights: [0, 1]\n",          // single quotes
      "name: -x\nspacing: 1\nheights: [0, 1]\n",                // a name starting with '-'
      "{spacing: 1, heights: [0, 1]}\n",                        // a flow map
      "spacing: 1\nheights: [0, 1] # c\nname: \"d\\u00e9\"\n",  // an escape in the name
  };
  expectLeftToTheGeneralReader(files, /*general_reads=*/true);
}

// Files neither reader takes: the plain one leaves them, and the general one names the fault.
TEST(PlainTerrainYaml, FaultsInTheNewFormsAreTheGeneralReadersToName) {
  const std::vector<std::string> files = {
      "x: [0, 1]\nheights:\n- - 0\n  - - 1\n",               // a list in a list in a list
      "spacing: 1\nheights: [0, 1]\nname: Null\n",           // YAML's null for the name
      "spacing: 1\nheights: [0, 1]\nname: a: b\n",           // a map in a plain scalar
      "spacing: 1\nheights:\n  - 0\n   - 1\n",               // an item deeper than the one before
      "x:\n- 0\n- 1\nheights:\n- [0, 1]\n- 2\ny: [0, 1]\n",  // a row and a number
  };
  expectLeftToTheGeneralReader(files, /*general_reads=*/false);
}

// Random edits of plain files: every file the plain reader accepts, the general one reads to the
// same terrain. The edits break numbers, lists, keys, indentation and line ends, so both
// readers' refusals and the plain reader's hand-overs are exercised.
TEST(PlainTerrainYaml, RandomEditsNeverReadDifferently) {
  const std::vector<std::string> bases = {
      "name: \"r\"\nx: [0, 0.5, 1, 1.5]\ny: [-2.5, 0, 2.5]\nheights:\n  - [0, 0.1, -0.2, 0]\n"
      "  - [0, 1e-3, 2E+1, 0]\n  - [0, 0.25, 0.125, 0]\n",
      "spacing: 0.01\nstart: 3\nheights: [0, -1, 2.5, 1e4, -1e4]  # m\n",
      "# c\r\nspacing: 2e-6\r\ny: [0, 1e-6]\r\nheights:\r\n- [1, 2]\r\n- [3, 4]\r\n",
      // PyYAML's block and wrapped flow lists, an unquoted name.
      "heights:\n- - 0.0\n  - -2.5e-07\n  - 1.0e-05\n- - 0.5\n  - 0.25\n  - -0.125\n"
      "name: road_1\nx:\n- 0.0\n- 0.01\n- 0.02\ny:\n- -2.5\n- 2.5\n",
      "heights:\n- [0.0, -2.4e-07, -9.5e-07,\n  -5.7e-06]\n- [1, 2, 3,\n  4]\n"
      "name: iso C (1)\nx: [0.0, 0.01,\n  0.02, 0.03]\ny: [-2.5,\n  2.5]\n",
      "spacing: 0.5\nheights:\n  - 0\n  - 1.5\n  # c\n  - -2\n",
  };
  const std::vector<std::string> tokens = {"nan", ".inf", "-inf", "1e400", "1e-400", "+1",   "abc",
                                           "",    "1,",   "'1'",  "\"1\"", "-",      "0x10", "1_0",
                                           "1e",  ".",    "1.",   "-.5",   "0.0",    "1e-7", "2e-6",
                                           "1e8", "1e5",  "[1]",  "~",     "&a 1",   "1 2"};
  const std::string characters = " ,[]#-:\t\r\n\"\\e.0-+yx";
  std::mt19937 random(20261207);
  int accepted = 0, handed_over = 0, refused = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    std::string text = bases[static_cast<std::size_t>(trial) % bases.size()];
    const int edits = random() % 4 == 0 ? 2 : 1;
    for (int e = 0; e < edits && !text.empty(); ++e) {
      const std::size_t at = random() % text.size();
      switch (random() % 6) {
        case 0: {  // a number or other token at a number's place
          const std::size_t start = text.find_first_of("0123456789", at);
          if (start == std::string::npos)
            break;
          const std::size_t end = text.find_first_not_of("0123456789.eE+-", start);
          text.replace(start, (end == std::string::npos ? text.size() : end) - start,
                       tokens[random() % tokens.size()]);
          break;
        }
        case 1:  // a character inserted
          text.insert(at, 1, characters[random() % characters.size()]);
          break;
        case 2:  // a character removed
          text.erase(at, 1);
          break;
        case 3: {  // a line repeated
          const std::size_t begin = text.rfind('\n', at);
          const std::size_t from = begin == std::string::npos ? 0 : begin + 1;
          const std::size_t end = text.find('\n', at);
          const std::size_t to = end == std::string::npos ? text.size() : end + 1;
          text.insert(to, text.substr(from, to - from));
          break;
        }
        case 4: {  // a line removed
          const std::size_t begin = text.rfind('\n', at);
          const std::size_t from = begin == std::string::npos ? 0 : begin + 1;
          const std::size_t end = text.find('\n', at);
          text.erase(from, (end == std::string::npos ? text.size() : end + 1) - from);
          break;
        }
        default: {  // two numbers of a list swapped (order, duplicates)
          const std::size_t comma = text.find(", ", at);
          const std::size_t next = comma == std::string::npos ? comma : text.find(", ", comma + 2);
          if (next == std::string::npos)
            break;
          const std::size_t before = text.rfind(' ', comma - 1);
          if (before == std::string::npos || before + 1 >= comma)
            break;
          const std::string left = text.substr(before + 1, comma - before - 1);
          const std::string right = text.substr(comma + 2, next - comma - 2);
          text.replace(comma + 2, right.size(), left);
          text.replace(before + 1, left.size(), right);
          break;
        }
      }
    }
    const BothReads reads = readBoth(text);
    if (reads.plain) {
      ++accepted;
      ASSERT_TRUE(reads.general.has_value()) << "the general reader refuses:\n" << text;
      expectSameTerrain(*reads.plain, *reads.general, text);
    } else {
      ++(reads.general ? handed_over : refused);
    }
  }
  // Every outcome is exercised many times.
  EXPECT_GT(accepted, 300);
  EXPECT_GT(handed_over, 100);
  EXPECT_GT(refused, 300);
  std::printf("plain reader: %d accepted, %d handed over and read, %d refused by both\n", accepted,
              handed_over, refused);
}

TEST(PlainTerrainYaml, NoFileIsNoTerrain) {
  EXPECT_FALSE(readPlainTerrainYaml("/nonexistent/road.yaml").has_value());
  EXPECT_FALSE(readBoth("").plain.has_value());
}

/// Loads the named pipe `path` while a thread writes a terrain the plain reader hands over into
/// it; exits 0 when it reads. A pipe drained by the plain reader left the general one waiting
/// for a second writer for ever: the alarm ends such a child.
[[noreturn]] void loadFromPipe(const std::string& path) {
  ::alarm(20);
  std::thread writer([&path] { std::ofstream(path) << "spacing: +1\nheights: [0, 1]\n"; });
  const Terrain road = loadTerrainYaml(path);
  writer.join();
  std::exit(road.stations().size() == 2 && road.heights()(0, 1) == 1.0 ? 0 : 1);
}

TEST(PlainTerrainYaml, ANamedPipeIsReadOnce) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() /
      ("tvd_plain_yaml_" + std::to_string(::getpid()) + "_pipe.yaml");
  std::filesystem::remove(path);
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  EXPECT_EXIT(loadFromPipe(path.string()), ::testing::ExitedWithCode(0), "");
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace terrain
}  // namespace tracked_vehicle_dynamics

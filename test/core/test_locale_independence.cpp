// Numbers the core writes and reads are the same whatever locale the process has set. A program
// that links the core and calls setlocale(LC_ALL, "") under a comma locale (a GUI, Python through
// ctypes) got "2,138238337" in JSON arrays, a vehicle hash of its own (every cached and saved
// reduced model refused as "reduced from another description") and reduction keys that no
// longer parsed. Each test below fails on that code.
#include <gtest/gtest.h>

#include <clocale>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <locale>
#include <sstream>
#include <string>

#include <unistd.h>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/atomic_file.h"
#include "tracked_vehicle_dynamics/io/csv_reader.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/io/number_text.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

namespace tvd = tracked_vehicle_dynamics;

namespace {

const std::string kVehicle = std::string(TVD_SOURCE_DIR) + "/config/vehicles/paper_vehicle.yaml";
const char* const kCommaLocale = "de_DE.UTF-8";

/// de_DE.UTF-8 compiled by localedef (its source is Debian's `locales` package, which
/// scripts/install_deps.sh installs) into a directory of the test's own, found through LOCPATH:
/// nothing is installed system-wide, and the machine needs no locale generated beforehand.
std::string commaLocaleDirectory() {
  static const std::string directory = [] {
    const std::string dir =
        testing::TempDir() + "tvd_locale_" + std::to_string(static_cast<long>(::getpid()));
    std::filesystem::create_directories(dir);
    // localedef exits 1 on warnings it still writes the locale for: setlocale() below decides.
    const std::string command =
        "localedef -i de_DE -f UTF-8 '" + dir + "/" + kCommaLocale + "' > /dev/null 2>&1";
    const int status = std::system(command.c_str());
    (void)status;
    return dir;
  }();
  return directory;
}

/// Switches the process's C locale (setlocale) and, for the stream test, the global C++ locale
/// to a comma locale; restores "C" and the classic locale afterwards.
class CommaLocale : public ::testing::Test {
 protected:
  void SetUp() override {
    ::setenv("LOCPATH", commaLocaleDirectory().c_str(), 1);
    ASSERT_NE(std::setlocale(LC_ALL, kCommaLocale), nullptr)
        << "cannot make " << kCommaLocale << " with localedef in " << commaLocaleDirectory()
        << " (is Debian's package 'locales' installed? scripts/install_deps.sh installs it)";
    // The locale is in effect: printf itself now writes a comma.
    char text[16];
    std::snprintf(text, sizeof(text), "%.1f", 1.5);
    ASSERT_STREQ(text, "1,5");
  }
  void TearDown() override {
    std::setlocale(LC_ALL, "C");
    std::locale::global(std::locale::classic());
    ::unsetenv("LOCPATH");
  }
};

}  // namespace

TEST_F(CommaLocale, CFormattingAndReadingKeepThePoint) {
  EXPECT_EQ(tvd::io::formatC("%.3g Hz", 2.138238337), "2.14 Hz");
  EXPECT_EQ(tvd::io::formatC("%#.3g", 25.0), "25.0");
  EXPECT_EQ(tvd::io::formatC("%.*f", 2, 0.125), "0.12");
  // Longer than formatC's own buffer: formatted again at its size.
  const std::string long_text = tvd::io::formatC("%s %.1f", std::string(300, 'x').c_str(), 0.5);
  EXPECT_EQ(long_text.size(), 304u);
  EXPECT_EQ(long_text.substr(300), " 0.5");
  char* end = nullptr;
  const char* text = "1.5e-310";  // subnormal: the readers' fallback to strtod
  EXPECT_EQ(tvd::io::strtodC(text, &end), 1.5e-310);
  EXPECT_EQ(end, text + 8);
  double value = 0.0;
  EXPECT_EQ(tvd::io::scanC("0.7", "%lf", &value), 1);
  EXPECT_EQ(value, 0.7);
  EXPECT_EQ(tvd::brief(0.5), "0.5");
  EXPECT_EQ(tvd::beyond(200.0001, 200.0), "200.0001");
}

TEST_F(CommaLocale, JsonNumbersStayJson) {
  std::locale::global(std::locale(kCommaLocale));  // the stream too: "1.234.567" for integers
  std::ostringstream out;
  tvd::io::JsonWriter json(out);
  json.beginArray().value(2.138238337).value(0.5).value(1234567LL).endArray();
  EXPECT_EQ(out.str(), "[2.138238337,0.5,1234567]");
}

TEST_F(CommaLocale, SubnormalsInCsvAreRead) {
  // from_chars reports a subnormal out of range; the reader's strtod fallback must read the '.'.
  const std::optional<double> value = tvd::io::parseNumber("2.5e-310");
  ASSERT_TRUE(value.has_value());
  EXPECT_EQ(*value, 2.5e-310);
}

TEST_F(CommaLocale, VehicleHashIsTheOneOfTheCLocale) {
  std::setlocale(LC_ALL, "C");
  const std::string in_c =
      tvd::vehicle::descriptionHashHex(tvd::vehicle::loadVehicleDescription(kVehicle));
  ASSERT_NE(std::setlocale(LC_ALL, kCommaLocale), nullptr);
  EXPECT_EQ(tvd::vehicle::descriptionHashHex(tvd::vehicle::loadVehicleDescription(kVehicle)), in_c);
}

TEST_F(CommaLocale, ReductionKeysParse) {
  tvd::reduction::VehicleReductionOptions options;
  options.band_hz = 27.5;
  options.mac_threshold = 0.65;
  const std::string key = tvd::reduction::reductionKey(tvd::vehicle::Variant::Tracked, options);
  EXPECT_NE(key.find("band_hz 27.5;"), std::string::npos) << key;
  tvd::vehicle::Variant variant = tvd::vehicle::Variant::Untracked;
  tvd::reduction::VehicleReductionOptions read;
  ASSERT_TRUE(tvd::reduction::parseReductionKey(key, &variant, &read)) << key;
  EXPECT_EQ(variant, tvd::vehicle::Variant::Tracked);
  EXPECT_EQ(read.band_hz, 27.5);
  EXPECT_EQ(read.mac_threshold, 0.65);
}

TEST_F(CommaLocale, TextFilesIgnoreAGlobalStreamLocale) {
  // std::locale::global gives every stream made after it the comma and digit grouping.
  std::locale::global(std::locale(kCommaLocale));
  std::ostringstream probe;
  probe << 1234.5;
  ASSERT_EQ(probe.str(), "1.234,5");
  const std::string path =
      testing::TempDir() + "tvd_locale_" + std::to_string(static_cast<long>(::getpid())) + ".csv";
  {
    tvd::io::AtomicTextFile file(path);
    file.stream() << 1234.5 << "," << 1000000 << "\n";
    file.commit();
  }
  std::ifstream in(path);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(written, "1234.5,1000000\n");
  std::remove(path.c_str());
}

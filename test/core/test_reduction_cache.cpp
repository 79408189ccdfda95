// The reduced-model cache of loadOrReduceVehicle(): one file per description and reduction
// options, so a model reduced with other options is never loaded in place of the one asked for.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include <unistd.h>

#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

namespace tvd = tracked_vehicle_dynamics;
using tvd::reduction::VehicleReductionOptions;

namespace {
const std::string kVehicle = std::string(TVD_SOURCE_DIR) + "/config/vehicles/paper_vehicle.yaml";
}  // namespace

TEST(ReductionCache, FileNameNamesVariantDescriptionAndOptions) {
  const auto variant = tvd::vehicle::Variant::Untracked;
  const std::string base = tvd::reduction::reducedModelCachePath("/c", variant, "abc", {});
  EXPECT_EQ(base, "/c/untracked_abc.mat");
  EXPECT_EQ(tvd::reduction::reducedModelCachePath("/c", tvd::vehicle::Variant::Tracked, "abc", {}),
            "/c/tracked_abc.mat");
  // Every option changes the name, each differently; the same options give the same name.
  std::set<std::string> names = {base};
  for (int which = 0; which < 6; ++which) {
    VehicleReductionOptions o;
    switch (which) {
      case 0:
        o.rule = tvd::reduction::VehicleModeRule::Band;
        break;
      case 1:
        o.global_modes = 41;
        break;
      case 2:
        o.band_hz = 30.000001;
        break;
      case 3:
        o.mac_threshold = 0.8;
        break;
      case 4:
        o.mogesec_masters = 10;
        break;
      default:
        o.mode_count = 30;
        break;
    }
    const std::string name = tvd::reduction::reducedModelCachePath("/c", variant, "abc", o);
    EXPECT_EQ(name, tvd::reduction::reducedModelCachePath("/c", variant, "abc", o));
    EXPECT_EQ(name.rfind("/c/untracked_abc_", 0), 0u) << name;
    EXPECT_TRUE(names.insert(name).second) << "option " << which << " shares " << name;
  }
}

// A model's `reduction` text gives back the variant and options it was reduced with (what
// `tvd frf --reduced FILE` reports), and nothing else parses.
TEST(ReductionCache, ReductionKeyRoundTrips) {
  VehicleReductionOptions band;
  band.rule = tvd::reduction::VehicleModeRule::Band;
  band.band_hz = 40.000000000000007;
  band.mac_threshold = 0.1 + 0.2;
  band.global_modes = 12;
  band.mogesec_masters = 0;
  band.mode_count = 31;
  for (const auto variant : {tvd::vehicle::Variant::Tracked, tvd::vehicle::Variant::Untracked})
    for (const VehicleReductionOptions& o : {VehicleReductionOptions{}, band}) {
      const std::string key = tvd::reduction::reductionKey(variant, o);
      auto parsed_variant = variant == tvd::vehicle::Variant::Tracked
                                ? tvd::vehicle::Variant::Untracked
                                : tvd::vehicle::Variant::Tracked;
      VehicleReductionOptions parsed;
      ASSERT_TRUE(tvd::reduction::parseReductionKey(key, &parsed_variant, &parsed)) << key;
      EXPECT_EQ(parsed_variant, variant);
      EXPECT_EQ(parsed.rule, o.rule);
      EXPECT_EQ(parsed.global_modes, o.global_modes);
      EXPECT_EQ(parsed.band_hz, o.band_hz);  // to the last bit
      EXPECT_EQ(parsed.mac_threshold, o.mac_threshold);
      EXPECT_EQ(parsed.mogesec_masters, o.mogesec_masters);
      EXPECT_EQ(parsed.mode_count, o.mode_count);
      EXPECT_FALSE(tvd::reduction::parseReductionKey(key + ";", &parsed_variant, &parsed));
    }
  const std::string good = tvd::reduction::reductionKey(tvd::vehicle::Variant::Tracked, {});
  // Shortest exact text, and the %.17g text of files written up to 0.3.2 still reads.
  EXPECT_NE(good.find("; band_hz 30; mac_threshold 0.7; "), std::string::npos) << good;
  {
    auto variant = tvd::vehicle::Variant::Untracked;
    VehicleReductionOptions legacy;
    ASSERT_TRUE(tvd::reduction::parseReductionKey(
        "variant tracked; rule mac; global_modes 40; band_hz 30; mac_threshold "
        "0.69999999999999996; mogesec_masters 9; modes 0",
        &variant, &legacy));
    EXPECT_EQ(legacy.mac_threshold, 0.7);
    // A third spelling of the same double is not a key either program wrote: refused.
    EXPECT_FALSE(tvd::reduction::parseReductionKey(
        "variant tracked; rule mac; global_modes 40; band_hz 30.0; mac_threshold 0.7; "
        "mogesec_masters 9; modes 0",
        &variant, &legacy));
  }
  for (const std::string& bad :
       {std::string(), std::string("variant tracked; modes 4"),
        std::string("variant flying") + good.substr(15),
        std::string("variant tracked; rule all") + good.substr(good.find("; global_modes")),
        std::string("variant tracked;  rule mac") + good.substr(good.find("; global_modes"))}) {
    auto variant = tvd::vehicle::Variant::Untracked;
    VehicleReductionOptions options;
    options.band_hz = 1.0;
    EXPECT_FALSE(tvd::reduction::parseReductionKey(bad, &variant, &options)) << bad;
    EXPECT_EQ(variant, tvd::vehicle::Variant::Untracked);  // unchanged
    EXPECT_EQ(options.band_hz, 1.0);
  }
}

// End to end: default options, then fewer MoGeSeC masters (another model, not the cached one,
// even when the default's file is copied to its name), then the same again (now from its own
// cache, equal to what was computed).
TEST(ReductionCache, OtherOptionsAreNotServedFromTheDefaultCache) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("tvd_cache_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const auto variant = tvd::vehicle::Variant::Untracked;
  tvd::reduction::VehicleReductionReport first, second, third;
  const auto defaults =
      tvd::reduction::loadOrReduceVehicle(kVehicle, variant, dir.string(), {}, &first);
  VehicleReductionOptions fewer;
  fewer.mogesec_masters = 4;
  const std::string hash =
      tvd::vehicle::descriptionHashHex(tvd::vehicle::loadVehicleDescription(kVehicle));
  std::filesystem::copy_file(
      first.cache_file, tvd::reduction::reducedModelCachePath(dir.string(), variant, hash, fewer));
  const auto computed =
      tvd::reduction::loadOrReduceVehicle(kVehicle, variant, dir.string(), fewer, &second);
  const auto cached =
      tvd::reduction::loadOrReduceVehicle(kVehicle, variant, dir.string(), fewer, &third);
  EXPECT_FALSE(first.from_cache);
  EXPECT_FALSE(second.from_cache) << second.cache_note;
  EXPECT_NE(second.cache_note.find("cannot be used: " + second.cache_file +
                                   ": reduced as 'variant untracked; rule mac; "
                                   "global_modes 40; band_hz 30; mac_threshold 0.7; "
                                   "mogesec_masters 9; modes 0', expected"),
            std::string::npos)
      << second.cache_note;
  EXPECT_TRUE(third.from_cache) << third.cache_note;
  EXPECT_NE(first.cache_file, second.cache_file);
  EXPECT_EQ(second.cache_file, third.cache_file);
  EXPECT_EQ(defaults.size() - computed.size(), 5);  // 9 MoGeSeC masters by default, now 4
  EXPECT_EQ(cached.size(), computed.size());
  EXPECT_EQ((cached.system.stiffness - computed.system.stiffness).cwiseAbs().maxCoeff(), 0.0);
  std::filesystem::remove_all(dir);
}

TEST(ReductionCache, ModeRuleNamesRoundTrip) {
  for (const auto rule :
       {tvd::reduction::VehicleModeRule::MacCorrelation, tvd::reduction::VehicleModeRule::Band})
    EXPECT_EQ(tvd::reduction::modeRuleFromName(tvd::reduction::modeRuleName(rule)), rule);
  EXPECT_STREQ(tvd::reduction::modeRuleName(tvd::reduction::VehicleModeRule::Band), "band");
  for (const char* bad : {"", "MAC", "all", "band "})
    EXPECT_FALSE(tvd::reduction::modeRuleFromName(bad).has_value()) << bad;
}

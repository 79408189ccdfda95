#include "reduction_options.h"

#include <filesystem>
#include <iostream>
#include <sstream>

#include "commands.h"
#include "output_files.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/home_path.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model_file.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {
using reduction::kMaxGlobalModes;
using reduction::kMaxReductionCount;

// --global-modes in [1, kMaxGlobalModes], with the limit's reason (vehicle_reduction.h).
CLI::Validator globalModeCount() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        int v = 0;
        if (!CLI::detail::lexical_cast(text, v) || v < 1 || v > kMaxGlobalModes)
          return "must be an integer in [1, " + std::to_string(kMaxGlobalModes) + "], got " + text +
                 (v > kMaxGlobalModes ? reduction::kMaxGlobalModesReason : "");
        return std::string();
      },
      "INT");
}
}  // namespace

void ReductionFlags::addTo(CLI::App* command) {
  reduction::VehicleReductionOptions& o = options_;
  flags_ = {
      command
          ->add_option("--rule", rule_,
                       "mode selection: mac (paper) | band (node: ~reduction/rule)")
          ->check(CLI::IsMember({"mac", "band"})),
      command->add_option("--band", o.band_hz, "bandwidth of interest [Hz] (~reduction/band_hz)")
          ->check(positiveNumber()),
      command
          ->add_option("--global-modes", o.global_modes,
                       "modes per variant for the MAC, 1 .. " + std::to_string(kMaxGlobalModes) +
                           " (~reduction/global_modes)")
          ->check(globalModeCount()),
      command
          ->add_option("--masters", o.mogesec_masters,
                       "MoGeSeC master DOFs (paper: 9; ~reduction/mogesec_masters)")
          ->check(CLI::Range(0, kMaxReductionCount)),
      command
          ->add_option(
              "--modes", o.mode_count,
              "fixed-interface modes (0: twice the selected, more until the modes below --band "
              "are within 2 %; ~reduction/mode_count); with --rule band a positive N also "
              "selects the lowest N global modes instead of those below --band")
          ->check(CLI::Range(0, kMaxReductionCount)),
  };
  // (0, 1] as the node's ~reduction/mac_threshold: at 0 every mode would correlate.
  mac_threshold_ =
      command
          ->add_option("--mac-threshold", o.mac_threshold,
                       "MAC threshold, --rule mac only (paper: 0.7; ~reduction/mac_threshold)")
          ->check(finiteNumberWhere([](double v) { return v > 0.0 && v <= 1.0; },
                                    "a number in (0, 1]", "NUMBER"));
  flags_.push_back(mac_threshold_);
}

reduction::VehicleReductionOptions ReductionFlags::options(const std::string& command) const {
  if (mac_threshold_->count() > 0 && rule_ != "mac")
    throw InputError(command + ": --mac-threshold applies to --rule mac only");
  reduction::VehicleReductionOptions o = options_;
  o.rule = reduction::modeRuleFromName(rule_).value();  // CLI11 checked the name
  return o;
}

std::string ReductionFlags::firstGiven() const {
  for (const CLI::Option* flag : flags_)
    if (flag->count() > 0)
      return flag->get_name();
  return std::string();
}

void ReducedModelFlags::addTo(CLI::App* command) {
  command
      ->add_option("--reduced", reduced_file_,
                   "reduced model from `tvd reduce --out` (.mat) instead of the cache; it keeps "
                   "the reduction options it was made with")
      ->check(CLI::ExistingFile);
  cache_dir_option_ =
      command
          ->add_option(
              "--cache-dir", cache_dir_,
              "reduced-model cache (default $XDG_CACHE_HOME/tracked_vehicle_dynamics, else "
              "~/.cache/tracked_vehicle_dynamics; not used with --reduced)")
          // Not checked for writing: an unwritable cache warns and the run goes
          // on. An empty one silently meant the default. "~" is expanded: bash leaves it in
          // --cache-dir=~/x, which made a directory "~" where tvd ran (a transform: check()
          // would drop the expanded text).
          ->transform(CLI::Validator(
              [](std::string& text) {
                if (text.empty())
                  return std::string("must name a directory, got ''");
                try {
                  text = io::expandHome(text, "the directory");
                } catch (const InputError& e) {
                  return std::string(e.what());
                }
                return std::string();
              },
              "DIR"));
  reduction_.addTo(command);
}

void ReducedModelFlags::check(const std::string& command, const std::string& model) const {
  const std::string flag = reduction_.firstGiven();
  if (!reduced_file_.empty() && model == "full")
    throw InputError(command + ": --reduced " + reduced_file_ +
                     " is a reduced model; it cannot be used with --model full");
  if (!reduced_file_.empty() && !flag.empty())
    throw InputError(command + ": " + flag + " is a reduction option; --reduced " + reduced_file_ +
                     " was reduced with its own (run tvd reduce again to change them)");
  if (model == "full" && !flag.empty())
    throw InputError(command + ": " + flag + " applies to --model reduced only");
  // README: an option that would be ignored is refused.
  if (cache_dir_option_->count() > 0 && !reduced_file_.empty())
    throw InputError(command + ": --cache-dir is not used with --reduced " + reduced_file_ +
                     " (the model comes from the file)");
  if (cache_dir_option_->count() > 0 && model == "full")
    throw InputError(command +
                     ": --cache-dir applies to --model reduced only (the full model is "
                     "built from the description on every run)");
  reduction_.options(command);  // --mac-threshold with --rule band
}

const char* sourceName(ReducedModelSource::Kind kind) {
  switch (kind) {
    case ReducedModelSource::Kind::Cache:
      return "cache";
    case ReducedModelSource::Kind::File:
      return "file";
    case ReducedModelSource::Kind::Computed:
      break;
  }
  return "computed";
}

namespace {

ReducedModelSource loadReducedFile(const vehicle::VehicleDescription& description,
                                   vehicle::Variant variant, bool variant_given,
                                   const std::string& command, const std::string& file) {
  ReducedModelSource s;
  s.kind = ReducedModelSource::Kind::File;
  s.file = file;
  const std::string again = "; run tvd reduce again";
  try {
    reduction::VehicleModelFile loaded = reduction::loadVehicleModelFile(file, description);
    s.model = std::move(loaded.model);
    s.variant = loaded.variant;
    s.options = loaded.options;
    s.warnings = s.model.warnings;  // as the run that reduced it warned
  } catch (const reduction::StaleCacheError& e) {
    throw InputError(e.what() + again);
  }
  if (variant_given && s.variant != variant)
    throw InputError(command + ": --reduced " + file + " is the " +
                     vehicle::variantName(s.variant) + " variant, --variant is " +
                     vehicle::variantName(variant));
  return s;
}

// Why the cache directory `dir` cannot be created, when a file stands in its way (it or a
// parent): "--cache-dir X is a file, not a directory", where the filesystem's own message read
// "filesystem error: cannot create directories: Not a directory [X]". Empty otherwise.
std::string cacheDirBlocked(const std::string& dir, bool given) {
  std::error_code error;
  const std::string what = given ? "--cache-dir " + dir : "the cache directory " + dir;
  for (std::filesystem::path p = dir; !p.empty(); p = p.parent_path()) {
    const auto status = std::filesystem::status(p, error);
    if (std::filesystem::exists(status) && !std::filesystem::is_directory(status))
      return p == std::filesystem::path(dir)
                 ? what + " is a file, not a directory"
                 : what + ": " + p.string() + " is a file, not a directory";
    if (std::filesystem::exists(status) || p == p.parent_path())
      break;
  }
  return std::string();
}

// The warnings and notes on stderr (the text and JSON outputs carry them too).
void printWarnings(const ReducedModelSource& s) {
  for (const std::string& w : s.warnings)
    std::cerr << "tvd: warning: " << w << "\n";
  for (const std::string& n : s.notes)
    std::cerr << "tvd: note: " << n << "\n";
}

}  // namespace

ReducedModelSource obtainReducedModel(const vehicle::VehicleDescription& description,
                                      vehicle::Variant variant, bool variant_given,
                                      const std::string& command, const ReducedModelFlags& flags) {
  if (!flags.reducedFile().empty()) {
    ReducedModelSource s =
        loadReducedFile(description, variant, variant_given, command, flags.reducedFile());
    printWarnings(s);
    return s;
  }
  ReducedModelSource s;
  s.variant = variant;
  s.options = flags.reduction().options(command);
  reduction::VehicleReductionReport report;
  const std::string cache_dir = flags.cacheDir().empty() ? defaultCacheDir() : flags.cacheDir();
  s.model = reduction::loadOrReduceVehicle(description, variant, cache_dir, s.options, &report);
  s.kind = report.from_cache ? ReducedModelSource::Kind::Cache : ReducedModelSource::Kind::Computed;
  s.warnings = report.warnings;
  // A cache that cannot be written (a --cache-dir that is a file, a read-only directory) costs
  // the whole reduction on every run: said once, with the reason.
  if (!report.cache_error.empty()) {
    const std::string blocked = cacheDirBlocked(cache_dir, !flags.cacheDir().empty());
    s.warnings.push_back("the reduced-model cache is not used (every run reduces again): " +
                         (blocked.empty() ? report.cache_error : blocked));
  } else
    s.file = report.cache_file;
  if (report.cache_rebuilt)
    s.notes.push_back(report.cache_note);
  printWarnings(s);
  return s;
}

void writeReductionJson(io::JsonWriter& json, const ReducedModelSource& s) {
  const reduction::VehicleReductionOptions& o = s.options;
  json.beginObject().field("source", sourceName(s.kind));
  if (!s.file.empty())
    json.field("file", s.file);
  json.field("variant", vehicle::variantName(s.variant))
      .field("rule", reduction::modeRuleName(o.rule))
      .field("band_hz", o.band_hz)
      .field("global_modes", o.global_modes)
      .field("mac_threshold", o.mac_threshold)
      .field("mogesec_masters", o.mogesec_masters)
      .field("mode_count", o.mode_count)
      .field("selected_global_modes", static_cast<long long>(s.model.selected_modes.size()))
      .field("fixed_interface_modes", static_cast<long long>(s.model.modeCount()))
      .field("master_dofs", static_cast<long long>(s.model.masterCount()))
      .field("reduced_dofs", static_cast<long long>(s.model.size()))
      .field("full_dofs", static_cast<long long>(s.model.full_dof_count))
      .field("created_utc", s.model.created_utc)
      .field("creator", s.model.creator)
      .field("warnings", s.warnings)
      .field("notes", s.notes)
      .endObject();
}

std::string describeReduction(const ReducedModelSource& s) {
  const reduction::VehicleReductionOptions& o = s.options;
  std::ostringstream text;
  text << "rule " << reduction::modeRuleName(o.rule) << ", 0-" << o.band_hz << " Hz, "
       << s.model.selected_modes.size() << " global modes -> " << s.model.modeCount()
       << " fixed-interface modes, " << s.model.masterCount() << " masters; ";
  switch (s.kind) {
    case ReducedModelSource::Kind::File:
      text << "from " << s.file;
      break;
    case ReducedModelSource::Kind::Cache:
      text << "cached";
      break;
    case ReducedModelSource::Kind::Computed:
      text << "computed";
      break;
  }
  return text.str();
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics

// Generic finite-element model files (YAML, SI units); the schema is documented key by key in
// doc/model_file.md, with examples in config/models/.
#pragma once

#include <string>

#include "tracked_vehicle_dynamics/fem/model.h"

namespace tracked_vehicle_dynamics {
namespace io {

/// Loads a model file and validates it (fem::validate(model, path)).
/// Throws InputError "<path>: <key path>: <what> (line N)" for a missing required key, a value
/// of the wrong type, a non-finite number, an unknown key (typo protection) or a key given
/// twice; "<path>: line N, column M: invalid YAML: ..." for syntax errors; "<path>: file not
/// found" and similar when the file cannot be read; and validate()'s "<path>: <item>[i]: ..."
/// for an inconsistent model.
fem::Model loadModelYaml(const std::string& path);

/// Same as loadModelYaml() for YAML text; `where` names the source in messages.
fem::Model parseModelYaml(const std::string& text, const std::string& where);

/// Writes every item of `model` so that loadModelYaml(path) reproduces it exactly (numbers in
/// shortest round-trip form; optional keys at their defaults are mostly left out). The model is not
/// validated, so an invalid one can still be written for inspection. Written through a temporary
/// file and a rename; throws InputError (an Error) when the file cannot be written.
void saveModelYaml(const fem::Model& model, const std::string& path);

/// The YAML text saveModelYaml() writes.
std::string formatModelYaml(const fem::Model& model);

}  // namespace io
}  // namespace tracked_vehicle_dynamics

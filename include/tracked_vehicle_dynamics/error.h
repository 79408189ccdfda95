// Exceptions thrown by the core (STYLE.md #8): every message names the file, key or index at fault.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace tracked_vehicle_dynamics {

// Which to throw: InputError for what a user supplied (a file, a parameter, a message) that is
// wrong, named; SolverError for a well-formed problem the numerics cannot solve as posed; and
// std::logic_error (or a subclass) for a caller's broken precondition, a bug in the calling
// code rather than in its data. Tools and the node catch Error to report the first two in one
// line; a logic_error escaping to them is a defect to fix, not a message to word.

/// Base of all errors raised by the core.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Invalid model, description or parameter (a user error, reported and never repaired silently).
class InputError : public Error {
 public:
  using Error::Error;
};

/// A linear system that cannot be solved as posed (e.g. a singular stiffness matrix).
class SolverError : public Error {
 public:
  using Error::Error;
};

/// A number for an error message: six significant digits ("3.5", "1.2e-05"), not std::to_string's
/// fixed six decimals ("3.500000"); up to ten when that gives the value exactly, so a value typed
/// with up to ten digits reads as typed ("200.0001", not "200").
std::string brief(double value);

/// `value` for a message that rejects it for passing `bound`: brief(value), with digits added (up
/// to 17) until it no longer reads as brief(bound) ("200.00000001" against 200, or a converted
/// 200.0001 km/h that is not exactly that double).
std::string beyond(double value, double bound);

/// The Levenshtein distance between a and b (insertions, deletions, substitutions): how far a
/// misspelt name is from a known one, for the "did you mean" of a message.
std::size_t editDistance(const std::string& a, const std::string& b);

}  // namespace tracked_vehicle_dynamics

// The core tests' check of bad input: the call throws InputError (or SolverError) and its
// message names what is wrong (contains every expected part).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {

/// The call throws Error (InputError, SolverError) whose message contains every part.
template <typename Error, typename Call>
void expectErrorNaming(Call call, const std::vector<std::string>& parts, const char* name) {
  try {
    call();
    ADD_FAILURE() << "no " << name << " thrown (expected one mentioning '" << parts.front() << "')";
  } catch (const Error& e) {
    for (const std::string& part : parts) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
          << "message \"" << e.what() << "\" lacks \"" << part << "\"";
    }
  }
}

template <typename Call>
void expectInputError(Call call, const std::vector<std::string>& parts) {
  expectErrorNaming<InputError>(call, parts, "InputError");
}

template <typename Call>
void expectSolverError(Call call, const std::vector<std::string>& parts) {
  expectErrorNaming<SolverError>(call, parts, "SolverError");
}

/// One expected part (a literal: a std::string overload would make {"a", "b"} ambiguous with
/// std::string's iterator-pair constructor).
template <typename Call>
void expectInputError(Call call, const char* part) {
  expectInputError(call, std::vector<std::string>{part});
}

}  // namespace tracked_vehicle_dynamics

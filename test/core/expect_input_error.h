// The core tests' check of bad input: the call throws InputError and its message names what is
// wrong (contains every expected part).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {

template <typename Call>
void expectInputError(Call call, const std::vector<std::string>& parts) {
  try {
    call();
    ADD_FAILURE() << "no InputError thrown (expected one mentioning '" << parts.front() << "')";
  } catch (const InputError& e) {
    for (const std::string& part : parts) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
          << "message \"" << e.what() << "\" lacks \"" << part << "\"";
    }
  }
}

/// One expected part (a literal: a std::string overload would make {"a", "b"} ambiguous with
/// std::string's iterator-pair constructor).
template <typename Call>
void expectInputError(Call call, const char* part) {
  expectInputError(call, std::vector<std::string>{part});
}

}  // namespace tracked_vehicle_dynamics

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/io/number_text.h"

using tracked_vehicle_dynamics::io::roundTripText;

TEST(RoundTripText, ShortestDecimalOfTypedValues) {
  EXPECT_EQ(roundTripText(0.7), "0.7");  // %.17g: 0.69999999999999996
  EXPECT_EQ(roundTripText(0.05), "0.05");
  EXPECT_EQ(roundTripText(30.0), "30");
  EXPECT_EQ(roundTripText(-1.25), "-1.25");
  EXPECT_EQ(roundTripText(0.1 + 0.2), "0.30000000000000004");  // no shorter text is this double
  EXPECT_EQ(roundTripText(-0.0), "0");
  EXPECT_EQ(roundTripText(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(roundTripText(std::numeric_limits<double>::quiet_NaN()), "nan");
}

TEST(RoundTripText, EveryBitReadsBack) {
  std::mt19937_64 random(7);
  std::uniform_int_distribution<unsigned long long> bits;
  int checked = 0;
  for (int k = 0; k < 20000; ++k) {
    const unsigned long long b = bits(random);
    double x;
    static_assert(sizeof x == sizeof b, "64-bit double");
    std::memcpy(&x, &b, sizeof x);
    if (!std::isfinite(x) || x == 0.0)
      continue;
    ASSERT_EQ(std::strtod(roundTripText(x).c_str(), nullptr), x) << roundTripText(x);
    ++checked;
  }
  EXPECT_GT(checked, 19000);
  const double smallest = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(std::strtod(roundTripText(smallest).c_str(), nullptr), smallest);
  const double largest = std::numeric_limits<double>::max();
  EXPECT_EQ(std::strtod(roundTripText(largest).c_str(), nullptr), largest);
}

// appendGeneral writes what an ostream with setprecision(p) writes (printf's %.{p}g): every bit
// pattern (NaN, infinities, -0, subnormals among them) and the values a table holds, at the
// precisions the result tables use.
TEST(AppendGeneral, IsTheStreamsText) {
  using tracked_vehicle_dynamics::io::appendGeneral;
  std::mt19937_64 random(11);
  std::uniform_int_distribution<unsigned long long> bits;
  std::vector<double> values = {0.0,
                                -0.0,
                                std::numeric_limits<double>::infinity(),
                                -std::numeric_limits<double>::infinity(),
                                std::numeric_limits<double>::quiet_NaN(),
                                -std::numeric_limits<double>::quiet_NaN(),
                                std::numeric_limits<double>::denorm_min(),
                                std::numeric_limits<double>::max(),
                                0.1,
                                9.9999999995,
                                99999.99999,
                                1e-5,
                                123456789.0,
                                -7.12158413e-07};
  for (int k = 0; k < 20000; ++k) {
    const unsigned long long b = bits(random);
    double x;
    std::memcpy(&x, &b, sizeof x);
    values.push_back(x);
    values.push_back(std::ldexp(static_cast<double>(b >> 11) * 0x1.0p-53 - 0.5, k % 40 - 20));
  }
  for (const int precision : {1, 3, 9, 10, 12, 17}) {
    std::string text;
    for (const double x : values) {
      text.clear();
      appendGeneral(text, x, precision);
      std::ostringstream stream;
      stream << std::setprecision(precision) << x;
      ASSERT_EQ(text, stream.str()) << "precision " << precision;
    }
  }
  std::string text = "a,";
  appendGeneral(text, 2.5, 9);
  EXPECT_EQ(text, "a,2.5");  // appended, not overwritten
}

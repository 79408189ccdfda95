#include "tracked_vehicle_dynamics/io/number_text.h"

// POSIX: newlocale, uselocale, strtod_l.
#include <locale.h>

#include <charconv>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>

namespace tracked_vehicle_dynamics {
namespace io {
namespace {

/// The "C" locale as an object, made once (thread-safe static initialisation) and kept for the
/// process's life: POSIX gives every C conversion a per-thread locale (uselocale), so switching
/// the calling thread for one call leaves other threads and the process's locale alone.
locale_t cLocale() {
  static const locale_t c = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
  return c;
}

/// The calling thread in the "C" locale for a scope. newlocale("C") cannot fail short of
/// memory; if it did, uselocale(0) only queries and the process's locale stays in effect.
class CLocaleScope {
 public:
  CLocaleScope() : previous_(uselocale(cLocale())) {}
  ~CLocaleScope() { uselocale(previous_); }
  CLocaleScope(const CLocaleScope&) = delete;
  CLocaleScope& operator=(const CLocaleScope&) = delete;

 private:
  locale_t previous_;
};

}  // namespace

std::string roundTripText(double value) {
  if (value == 0.0)
    return "0";
  if (std::isnan(value))
    return "nan";
  // std::to_chars without a precision is the shortest round-trip form (C++17 [charconv]);
  // 32 characters hold any double's ("-1.7976931348623157e+308" is 24).
  char buffer[32];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, r.ptr);
}

void appendGeneral(std::string& text, double value, int precision) {
  // "-1.2345678901234567e-308" is 24 characters; to_chars never writes past the end it is given.
  char buffer[32];
  const std::to_chars_result r =
      std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, precision);
  text.append(buffer, r.ptr);
}

std::string formatC(const char* pattern, ...) {
  const CLocaleScope c;
  std::va_list args;
  va_start(args, pattern);
  std::va_list again;
  va_copy(again, args);
  char buffer[128];
  const int n = std::vsnprintf(buffer, sizeof(buffer), pattern, args);
  va_end(args);
  std::string text;
  if (n < 0) {
    va_end(again);
    return text;
  }
  if (static_cast<std::size_t>(n) < sizeof(buffer)) {
    text.assign(buffer, static_cast<std::size_t>(n));
  } else {
    // Longer than the buffer (a sentence with a path in it): format again into its own size.
    text.resize(static_cast<std::size_t>(n) + 1);
    std::vsnprintf(text.data(), text.size(), pattern, again);
    text.pop_back();
  }
  va_end(again);
  return text;
}

double strtodC(const char* text, char** end) {
  const locale_t c = cLocale();
  if (c == static_cast<locale_t>(nullptr))
    return std::strtod(text, end);
  return strtod_l(text, end, c);
}

int scanC(const char* text, const char* pattern, ...) {
  const CLocaleScope c;
  std::va_list args;
  va_start(args, pattern);
  const int fields = std::vsscanf(text, pattern, args);
  va_end(args);
  return fields;
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics

#include "tracked_vehicle_dynamics/io/utf8.h"

namespace tracked_vehicle_dynamics {
namespace io {

std::size_t utf8Length(const std::string& s, std::size_t i) {
  if (i >= s.size())
    return 0;
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b = byte(i);
  if (b < 0x80)
    return 1;
  std::size_t n = 0;
  unsigned char low = 0x80, high = 0xBF;  // the second byte's range
  if (b >= 0xC2 && b <= 0xDF) {
    n = 2;
  } else if (b >= 0xE0 && b <= 0xEF) {
    n = 3;
    low = b == 0xE0 ? 0xA0 : 0x80;   // no overlong form
    high = b == 0xED ? 0x9F : 0xBF;  // no surrogate
  } else if (b >= 0xF0 && b <= 0xF4) {
    n = 4;
    low = b == 0xF0 ? 0x90 : 0x80;   // no overlong form
    high = b == 0xF4 ? 0x8F : 0xBF;  // nothing above U+10FFFF
  } else {
    return 0;
  }
  if (i + n > s.size() || byte(i + 1) < low || byte(i + 1) > high)
    return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF)
      return 0;
  return n;
}

namespace {

// The code point of the well-formed sequence of n bytes at s[i] (utf8Length() said n > 0).
char32_t decode(const std::string& s, std::size_t i, std::size_t n) {
  const auto byte = [&](std::size_t k) { return static_cast<char32_t>(s[k]) & 0xFF; };
  if (n == 1)
    return byte(i);
  static const char32_t kLeadMask[5] = {0, 0, 0x1F, 0x0F, 0x07};
  char32_t c = byte(i) & kLeadMask[n];
  for (std::size_t k = 1; k < n; ++k)
    c = (c << 6) | (byte(i + k) & 0x3F);
  return c;
}

}  // namespace

void appendUtf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out.push_back(static_cast<char>(c));
  } else if (c < 0x800) {
    out.push_back(static_cast<char>(0xC0 | (c >> 6)));
    out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
  } else if (c < 0x10000) {
    out.push_back(static_cast<char>(0xE0 | (c >> 12)));
    out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
  } else {
    out.push_back(static_cast<char>(0xF0 | (c >> 18)));
    out.push_back(static_cast<char>(0x80 | ((c >> 12) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
  }
}

std::vector<std::uint16_t> utf8ToUtf16(const std::string& text) {
  std::vector<std::uint16_t> units;
  units.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8Length(text, i);
    const char32_t c = n > 0 ? decode(text, i, n) : kReplacementCharacter;
    i += n > 0 ? n : 1;
    if (c < 0x10000) {
      units.push_back(static_cast<std::uint16_t>(c));
    } else {  // a surrogate pair: c - 0x10000 = 20 bits, high 10 and low 10
      const char32_t v = c - 0x10000;
      units.push_back(static_cast<std::uint16_t>(0xD800 + (v >> 10)));
      units.push_back(static_cast<std::uint16_t>(0xDC00 + (v & 0x3FF)));
    }
  }
  return units;
}

std::string utf16ToUtf8(const std::uint16_t* units, std::size_t count) {
  std::string out;
  out.reserve(count);
  for (std::size_t i = 0; i < count && units[i] != 0; ++i) {
    const char32_t u = units[i];
    if (u >= 0xD800 && u <= 0xDBFF && i + 1 < count && units[i + 1] >= 0xDC00 &&
        units[i + 1] <= 0xDFFF) {
      appendUtf8(out, 0x10000 + ((u - 0xD800) << 10) + (units[i + 1] - 0xDC00));
      ++i;
    } else if (u >= 0xD800 && u <= 0xDFFF) {
      appendUtf8(out, kReplacementCharacter);
    } else {
      appendUtf8(out, u);
    }
  }
  return out;
}

std::string validUtf8(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8Length(text, i);
    if (n > 0)
      out.append(text, i, n);
    else
      appendUtf8(out, kReplacementCharacter);
    i += n > 0 ? n : 1;
  }
  return out;
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics

// UTF-8 text as the output formats need it: JSON must be valid UTF-8 (RFC 8259), and a MAT 5
// char array holds UTF-16 code units, one per element of its dimensions (MATLAB writes char as
// miUINT16; a miUTF8 element whose dimensions count bytes instead of characters is read short,
// or refused, by Octave). Bytes that start no well-formed sequence (a Latin-1 file name, say)
// become U+FFFD, the replacement character, rather than invalid text.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tracked_vehicle_dynamics {
namespace io {

/// U+FFFD, what a byte of no UTF-8 character (or a lone surrogate) reads as.
constexpr char32_t kReplacementCharacter = 0xFFFD;

/// The length of the well-formed UTF-8 sequence at s[i] (RFC 3629: no overlong forms, no
/// surrogates, nothing above U+10FFFF), 0 when there is none (or i is past the end).
std::size_t utf8Length(const std::string& s, std::size_t i);

/// The UTF-16 code units of UTF-8 text (a code point above U+FFFF as a surrogate pair).
std::vector<std::uint16_t> utf8ToUtf16(const std::string& text);

/// The UTF-8 text of UTF-16 code units; a surrogate that is not half of a pair reads as U+FFFD.
/// Stops at a NUL unit (a MAT char array is not NUL-terminated, but some writers pad with NUL).
std::string utf16ToUtf8(const std::uint16_t* units, std::size_t count);

/// Appends the UTF-8 encoding of a code point (<= U+10FFFF, not a surrogate).
void appendUtf8(std::string& out, char32_t code_point);

/// `text` with every byte that starts no well-formed sequence replaced by U+FFFD: what a MAT file
/// or a JSON document holds of it, and so what reads back.
std::string validUtf8(const std::string& text);

}  // namespace io
}  // namespace tracked_vehicle_dynamics

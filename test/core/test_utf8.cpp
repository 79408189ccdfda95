// UTF-8 <-> UTF-16 for the MAT writer and reader, and the validity rule JSON shares (utf8.h).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/io/utf8.h"

namespace io = tracked_vehicle_dynamics::io;

namespace {
using Units = std::vector<std::uint16_t>;
}  // namespace

TEST(Utf8, EncodesEachCodePointAsItsUtf16Units) {
  // 'a' (1 byte), U+00E9 e-acute (2 bytes), U+20AC euro (3 bytes), U+1F600 (4 bytes: the surrogate
  // pair D83D DE00, from (0x1F600 - 0x10000) = 0xF600: high 0x3D, low 0x200).
  const std::string text = "a\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80";
  EXPECT_EQ(io::utf8ToUtf16(text), (Units{0x61, 0xE9, 0x20AC, 0xD83D, 0xDE00}));
  const Units units = io::utf8ToUtf16(text);
  EXPECT_EQ(io::utf16ToUtf8(units.data(), units.size()), text);
  EXPECT_TRUE(io::utf8ToUtf16("").empty());
}

TEST(Utf8, BytesOfNoCharacterBecomeTheReplacementCharacter) {
  // A Latin-1 e-acute (0xE9 then 't'), a lone continuation byte, an overlong '/' (C0 AF), an
  // encoded surrogate (ED A0 80), a sequence cut short at the end: each bad byte is one U+FFFD.
  EXPECT_EQ(io::utf8ToUtf16("\xe9t"), (Units{0xFFFD, 0x74}));
  EXPECT_EQ(io::utf8ToUtf16("\x80"), (Units{0xFFFD}));
  EXPECT_EQ(io::utf8ToUtf16("\xc0\xaf"), (Units{0xFFFD, 0xFFFD}));
  EXPECT_EQ(io::utf8ToUtf16("\xed\xa0\x80"), (Units{0xFFFD, 0xFFFD, 0xFFFD}));
  EXPECT_EQ(io::utf8ToUtf16("x\xe2\x82"), (Units{0x78, 0xFFFD, 0xFFFD}));
  EXPECT_EQ(io::validUtf8("caf\xe9"), "caf\xef\xbf\xbd");
  EXPECT_EQ(io::validUtf8("caf\xc3\xa9"), "caf\xc3\xa9");  // valid text is left as it is
}

TEST(Utf8, LoneSurrogatesReadAsTheReplacementCharacterAndNulEndsTheText) {
  const Units lone_high{0x41, 0xD800, 0x42};
  EXPECT_EQ(io::utf16ToUtf8(lone_high.data(), lone_high.size()),
            "A\xef\xbf\xbd"
            "B");
  const Units lone_low{0xDC00};
  EXPECT_EQ(io::utf16ToUtf8(lone_low.data(), lone_low.size()), "\xef\xbf\xbd");
  const Units high_at_end{0x41, 0xD83D};
  EXPECT_EQ(io::utf16ToUtf8(high_at_end.data(), high_at_end.size()), "A\xef\xbf\xbd");
  const Units padded{0x41, 0x42, 0, 0};
  EXPECT_EQ(io::utf16ToUtf8(padded.data(), padded.size()), "AB");
}

TEST(Utf8, SequenceLengthsFollowRfc3629) {
  EXPECT_EQ(io::utf8Length("a", 0), 1u);
  EXPECT_EQ(io::utf8Length("\xc3\xa9", 0), 2u);
  EXPECT_EQ(io::utf8Length("\xf4\x8f\xbf\xbf", 0), 4u);  // U+10FFFF, the last code point
  EXPECT_EQ(io::utf8Length("\xf4\x90\x80\x80", 0), 0u);  // above it
  EXPECT_EQ(io::utf8Length("\xe0\x80\x80", 0), 0u);      // overlong
  EXPECT_EQ(io::utf8Length("a", 1), 0u);                 // past the end
}

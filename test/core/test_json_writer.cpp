// JSON text of the CLI's --json output (io/json_writer.h): strings escaped as RFC 8259 asks, and
// always valid UTF-8, whatever bytes a file name or a description's name holds.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "tracked_vehicle_dynamics/io/json_writer.h"

using tracked_vehicle_dynamics::io::JsonWriter;

TEST(JsonWriter, EscapesQuotesBackslashesAndControlCharacters) {
  EXPECT_EQ(JsonWriter::escape("a\"b\\c\nd\te"), "a\\\"b\\\\c\\nd\\te");
  EXPECT_EQ(JsonWriter::escape(std::string("\x01\x1f", 2)), "\\u0001\\u001f");
}

TEST(JsonWriter, KeepsUtf8AndReplacesBytesOfNoCharacter) {
  // Two-, three- and four-byte characters pass unchanged: "é", "€", "𝜁".
  const std::string utf8 = "\xc3\xa9 \xe2\x82\xac \xf0\x9d\x9c\x81";
  EXPECT_EQ(JsonWriter::escape(utf8), utf8);
  // Latin-1 bytes, a truncated sequence, an overlong form and a surrogate read as U+FFFD, one
  // per byte that starts no character.
  EXPECT_EQ(JsonWriter::escape("paper_\xff\xfe"), "paper_\\ufffd\\ufffd");
  EXPECT_EQ(JsonWriter::escape("\xe2\x82"), "\\ufffd\\ufffd");
  EXPECT_EQ(JsonWriter::escape("\xc0\xaf"), "\\ufffd\\ufffd");
  EXPECT_EQ(JsonWriter::escape("\xed\xa0\x80"), "\\ufffd\\ufffd\\ufffd");
  EXPECT_EQ(JsonWriter::escape("x\xe9y"), "x\\ufffdy");  // Latin-1 e-acute between ASCII
}

TEST(JsonWriter, NonFiniteNumbersAreNull) {
  std::ostringstream out;
  JsonWriter json(out);
  json.beginObject().field("a", std::nan("")).field("b", 1.5).endObject();
  EXPECT_NE(out.str().find("\"a\":null"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("\"b\":1.5"), std::string::npos) << out.str();
}

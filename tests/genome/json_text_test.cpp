// JSON text that any string can go into (issue 37): a path the user named
// with bytes that are not UTF-8 is written with those bytes as \xNN, where
// nlohmann's dump() throws.
#include "genome/json_text.h"

#include <gtest/gtest.h>

#include "core/text.h"

namespace bx {
namespace {

TEST(Utf8Text, KeepsUtf8AndWritesEveryOtherByteAsAnEscape) {
  EXPECT_EQ(utf8_text("runs/quick-1"), "runs/quick-1");
  EXPECT_EQ(utf8_text("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x90\x9b"), "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x90\x9b");
  EXPECT_EQ(utf8_text("run\xff"), "run\\xff");
  EXPECT_EQ(utf8_text("a\x80z"), "a\\x80z");            // a continuation byte alone
  EXPECT_EQ(utf8_text("\xc3"), "\\xc3");                // cut short
  EXPECT_EQ(utf8_text("\xc0\xaf"), "\\xc0\\xaf");       // an overlong '/'
  EXPECT_EQ(utf8_text("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
  EXPECT_EQ(utf8_text("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // past U+10FFFF
  EXPECT_EQ(utf8_text(std::string("a\0b", 3)), std::string("a\0b", 3));  // valid UTF-8: one_line's concern
}

TEST(JsonText, AStringThatIsNotUtf8IsWrittenWithItsBytesEscapedNotThrown) {
  nlohmann::json j = {{"genome", "runs/best\xff.json"}, {"fitness", 1.5}, {"run\xfe", {"x\xff", 2}}};
  EXPECT_THROW((void)j.dump(), nlohmann::json::type_error);
  const std::string text = json_text(j);
  const nlohmann::json back = nlohmann::json::parse(text);
  EXPECT_EQ(back["genome"], "runs/best\\xff.json");  // still names the file
  EXPECT_EQ(back["fitness"], 1.5);
  EXPECT_EQ(back["run\\xfe"][0], "x\\xff");
  // as dump() writes it otherwise, indented or not, ordered or not
  const nlohmann::json ok = {{"genome", "caf\xc3\xa9.json"}, {"n", {1, 2}}};
  EXPECT_EQ(json_text(ok), ok.dump());
  EXPECT_EQ(json_text(ok, 2), ok.dump(2));
  nlohmann::ordered_json o;
  o["z"] = "\xff";
  o["a"] = 1;
  EXPECT_EQ(json_text(o), "{\"z\":\"\\\\xff\",\"a\":1}");
}

}  // namespace
}  // namespace bx

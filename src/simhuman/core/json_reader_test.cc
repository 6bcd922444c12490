#include "simhuman/core/json_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace simhuman::core {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

std::string Message(const Status& s) { return std::string(s.message()); }

template <typename V>
std::string Message(const StatusOr<V>& s) {
  return s.ok() ? std::string() : std::string(s.status().message());
}

TEST(JsonReaderTest, PointersEscapeAndTreatSlashAsTheRoot) {
  EXPECT_EQ(JsonPointer("", "objects"), "/objects");
  EXPECT_EQ(JsonPointer("/", "objects"), "/objects");
  EXPECT_EQ(JsonPointer("/objects", size_t{3}), "/objects/3");
  EXPECT_EQ(JsonPointer("/a", "b/c~d"), "/a/b~1c~0d");
}

TEST(JsonReaderTest, RangesPrintTheirEndsAndRejectNonFiniteNumbers) {
  EXPECT_EQ(NumberRange::Closed(2, 1024).ToString(), "[2, 1024]");
  EXPECT_EQ(NumberRange::Above(0).ToString(), "(0, inf)");
  EXPECT_EQ(NumberRange::AtLeast(1).ToString(), "[1, inf)");
  EXPECT_EQ(NumberRange::AboveUpTo(0, 1).ToString(), "(0, 1]");
  EXPECT_EQ(NumberRange::Any().ToString(), "(-inf, inf)");
  EXPECT_TRUE(NumberRange::Closed(0, 1).Contains(0));
  EXPECT_TRUE(NumberRange::Closed(0, 1).Contains(1));
  EXPECT_FALSE(NumberRange::Above(0).Contains(0));
  EXPECT_FALSE(NumberRange::Any().Contains(std::nan("")));
  EXPECT_FALSE(NumberRange::Any().Contains(std::numeric_limits<double>::infinity()));
  EXPECT_EQ(FormatNumber(4096), "4096");
  EXPECT_EQ(FormatNumber(0.0003), "0.0003");
  EXPECT_EQ(FormatNumber(-0.0), "0");
  EXPECT_EQ(FormatNumber(1e20), "1e+20");
}

TEST(JsonReaderTest, NumbersNameThePointerTheTypeAndTheRange) {
  EXPECT_EQ(*ReadNumber(json(1.5), "/x"), 1.5);
  EXPECT_EQ(Message(ReadNumber(json("1"), "/x")), "/x: expected a number, got string");
  EXPECT_EQ(Message(ReadNumber(json(std::nan("")), "/x")), "/x: number is not finite");
  EXPECT_EQ(Message(ReadNumber(json(2), "/x", NumberRange::Closed(0, 1))),
            "/x: 2 is outside the valid range [0, 1]");
  auto missing = ReadOptionalNumber(json::object(), "k", "/o");
  ASSERT_TRUE(missing.ok());
  EXPECT_FALSE(missing->has_value());
  EXPECT_EQ(**ReadOptionalNumber(json{{"k", 3}}, "k", "/o"), 3.0);
  EXPECT_THAT(Message(ReadOptionalNumber(json{{"k", true}}, "k", "/o")),
              HasSubstr("/o/k: expected a number, got boolean"));
}

TEST(JsonReaderTest, IntegersAreExactAndMustFitTheirType) {
  EXPECT_EQ(*ReadInt(json(3), "/n"), 3);
  EXPECT_EQ(*ReadInt(json(3.0), "/n"), 3);  // 3.0 and 3e0 are integers
  EXPECT_EQ(*ReadInt64(json::parse("3e7"), "/n"), 30'000'000);
  EXPECT_EQ(Message(ReadInt(json(1.5), "/n")), "/n: expected an integer, got 1.5");
  EXPECT_EQ(Message(ReadInt(json(true), "/n")), "/n: expected an integer, got boolean");
  EXPECT_THAT(Message(ReadInt(json(3e9), "/n")),
              HasSubstr("expected an integer in [-2147483648, 2147483647], got 3000000000"));
  EXPECT_THAT(Message(ReadInt(json(1e300), "/n")), HasSubstr("expected an integer in"));
  EXPECT_EQ(Message(ReadInt(json(0), "/n", NumberRange::Closed(1, 64))),
            "/n: 0 is outside the valid range [1, 64]");
  // uint64: every value up to 2^64 - 1, exactly; negatives are errors
  EXPECT_EQ(*ReadUint64(json::parse("18446744073709551615"), "/s"),
            std::numeric_limits<uint64_t>::max());
  EXPECT_THAT(Message(ReadUint64(json(-1), "/s")), HasSubstr("expected an integer in [0, "));
  EXPECT_THAT(Message(ReadUint64(json(1.8446744073709552e19), "/s")),
              HasSubstr("expected an integer in [0, 18446744073709551615]"));
  // int64: the extremes exactly, one past them an error
  EXPECT_EQ(*ReadInt64(json::parse("9223372036854775807"), "/t"),
            std::numeric_limits<int64_t>::max());
  EXPECT_EQ(*ReadInt64(json::parse("-9223372036854775808"), "/t"),
            std::numeric_limits<int64_t>::min());
  EXPECT_FALSE(ReadInt64(json::parse("9223372036854775808"), "/t").ok());
  EXPECT_FALSE(ReadInt64(json(9.3e18), "/t").ok());
}

TEST(JsonReaderTest, BoolsStringsAndNames) {
  EXPECT_TRUE(*ReadBool(json(true), "/b"));
  EXPECT_EQ(Message(ReadBool(json(1), "/b")), "/b: expected true or false, got number");
  EXPECT_EQ(*ReadString(json("x"), "/s"), "x");
  EXPECT_EQ(Message(ReadString(json(1), "/s")), "/s: expected a string, got number");
  EXPECT_EQ(*ReadName(json("sit"), "/p", {"stand", "sit"}, "posture"), "sit");
  EXPECT_EQ(Message(ReadName(json("fly"), "/p", {"stand", "sit"}, "posture")),
            "/p: unknown posture 'fly'; valid postures are: stand, sit");
}

TEST(JsonReaderTest, ArraysNameTheBadEntry) {
  EXPECT_EQ(ReadNumbers(json{1, 2}, "/pos", 2, 3)->size(), 2u);
  EXPECT_EQ(Message(ReadNumbers(json{1, 2, 3, 4}, "/pos", 2, 3)),
            "/pos: expected an array of 2 or 3 numbers, got an array of 4");
  EXPECT_EQ(Message(ReadNumbers(json{1}, "/pos", 3, 3)),
            "/pos: expected an array of 3 numbers, got an array of 1");
  EXPECT_EQ(Message(ReadNumbers(json("x"), "/pos", 1, 5)),
            "/pos: expected an array of 1 to 5 numbers, got string");
  EXPECT_EQ(Message(ReadNumbers(json{1, "a"}, "/pos", 2, 2)),
            "/pos/1: expected a number, got string");
  auto fixed = ReadFixedNumbers<3>(json{1, 2, 3}, "/t");
  ASSERT_TRUE(fixed.ok());
  EXPECT_EQ((*fixed)[2], 3.0);
  EXPECT_EQ(*ReadInts(json{64, 32}, "/h"), (std::vector<int>{64, 32}));
  EXPECT_EQ(Message(ReadInts(json{64, 0}, "/h", NumberRange::AtLeast(1))),
            "/h/1: 0 is outside the valid range [1, inf)");
  EXPECT_EQ(Message(ReadInts(json{64, 1.5}, "/h")), "/h/1: expected an integer, got 1.5");
  EXPECT_EQ(*ReadStrings(json{"a", "b"}, "/c"), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(Message(ReadStrings(json{"a", 1}, "/c")), "/c/1: expected a string, got number");
  EXPECT_EQ(Message(ReadStrings(json("a"), "/c")), "/c: expected an array of strings, got string");
}

TEST(JsonReaderTest, ObjectsNameUnknownAndMissingKeys) {
  json j = {{"a", 1}, {"zz", 2}};
  EXPECT_EQ(Message(CheckKeys(j, {"a", "b"}, "/cfg")),
            "/cfg: unknown key 'zz'; valid keys are: a, b");
  EXPECT_EQ(Message(CheckKeys(json::array(), {"a"}, "/cfg")),
            "/cfg: expected a JSON object, got array");
  EXPECT_TRUE(RequireKey(j, "a", "/").ok());
  EXPECT_EQ(Message(RequireKey(j, "b", "/")), "/b: missing required key");
  EXPECT_EQ(Message(GetNumber(j, "b", "/cfg")), "/cfg/b: missing required number");
  EXPECT_EQ(*GetNumber(j, "a", "/cfg"), 1.0);
  EXPECT_EQ(Message(GetString(j, "a", "/cfg")), "/cfg/a: expected a string, got number");
}

}  // namespace
}  // namespace simhuman::core

#include "simhuman/language/reply_extract.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace simhuman::language {
namespace {

using ::testing::HasSubstr;

const char kPlan[] = R"({"steps": [{"pairs": []}]})";

TEST(ExtractPlanJsonTest, BareJsonObject) {
  core::StatusOr<nlohmann::json> j = ExtractPlanJson(kPlan);
  ASSERT_TRUE(j.ok()) << j.status();
  EXPECT_TRUE(j->contains("steps"));
}

TEST(ExtractPlanJsonTest, JsonFenceWinsOverChatterAndOtherFences) {
  std::string reply = "Here {is} an [1] aside.\n```python\n{\"steps\": 1}\n```\nand\n```json\n" +
                      std::string(kPlan) + "\n```\nDone.";
  core::StatusOr<nlohmann::json> j = ExtractPlanJson(reply);
  ASSERT_TRUE(j.ok()) << j.status();
  EXPECT_TRUE((*j)["steps"].is_array());
}

TEST(ExtractPlanJsonTest, UntaggedAndUnclosedFences) {
  EXPECT_TRUE(ExtractPlanJson("```\n[[[\"a\"]]]\n```").ok());
  core::StatusOr<nlohmann::json> j = ExtractPlanJson("```json\n[[[\"a\"]]]\n");  // cut reply
  ASSERT_TRUE(j.ok()) << j.status();
  EXPECT_TRUE(j->is_array());
}

TEST(ExtractPlanJsonTest, PlanShapedValuePreferredOverEarlierJson) {
  core::StatusOr<nlohmann::json> j =
      ExtractPlanJson(std::string("Steps [1] and {\"a\": 2}: ") + kPlan + " bye");
  ASSERT_TRUE(j.ok()) << j.status();
  EXPECT_TRUE(j->contains("steps"));
  // without a plan-shaped value the first JSON value is returned (the parser will reject it)
  j = ExtractPlanJson("answer: {\"error\": \"cannot\"} [2]");
  ASSERT_TRUE(j.ok());
  EXPECT_TRUE(j->contains("error"));
}

TEST(ExtractPlanJsonTest, BracketsInsideStringsAreIgnored) {
  core::StatusOr<nlohmann::json> j =
      ExtractPlanJson(R"(x {"steps": [{"label": "a } ] { [ \" b", "pairs": []}]} y)");
  ASSERT_TRUE(j.ok()) << j.status();
  EXPECT_EQ((*j)["steps"][0]["label"], "a } ] { [ \" b");
}

TEST(ExtractPlanJsonTest, MalformedRepliesAreClearErrors) {
  core::StatusOr<nlohmann::json> j = ExtractPlanJson("I cannot help with that.");
  ASSERT_FALSE(j.ok());
  EXPECT_EQ(j.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(std::string(j.status().message()), HasSubstr("llm reply: no JSON plan found"));
  EXPECT_THAT(std::string(j.status().message()), HasSubstr("'I cannot help with that.'"));
  EXPECT_THAT(std::string(ExtractPlanJson("").status().message()), HasSubstr("the reply is empty"));
  EXPECT_FALSE(ExtractPlanJson("{\"steps\": [1, 2}").ok());
  EXPECT_FALSE(ExtractPlanJson("{\"x\": 1e99999}").ok());
}

TEST(ExtractPlanJsonTest, DeepNestingAndHostileBytesAreRefused) {
  EXPECT_FALSE(ExtractPlanJson(std::string(100000, '[') + std::string(100000, ']')).ok());
  std::string bytes = "\xff\xfe{\"steps\": \"\xc3\x28\"}\x01";
  core::StatusOr<nlohmann::json> j = ExtractPlanJson(bytes);  // invalid UTF-8 inside the string
  EXPECT_FALSE(j.ok());
  EXPECT_EQ(Preview("a\x01\xffz"), "a??z");
  EXPECT_EQ(Preview(std::string(100, 'a'), 3), "aaa...");
}

}  // namespace
}  // namespace simhuman::language

#include "simhuman/core/field_table.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace simhuman::core {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

// one field of every supported type
struct Demo {
  double gain = 0.5;
  int count = 4;
  int64_t steps = 1000;
  uint64_t seed = 1;
  bool verbose = false;
  std::string mode = "fast";
  std::string note;
  std::vector<int> widths = {64, 64};
  std::vector<std::string> files;
};

const FieldTable<Demo>& Table() {
  using F = Field<Demo>;
  static const FieldTable<Demo> kTable(
      "demo config", {F("gain", &Demo::gain, "a gain").In(NumberRange::Closed(0, 1)),
                      F("count", &Demo::count, "a count").In(NumberRange::Closed(1, 64)),
                      F("steps", &Demo::steps, "steps").In(NumberRange::AtLeast(1)),
                      F("seed", &Demo::seed, "a seed"), F("verbose", &Demo::verbose, "a flag"),
                      F("mode", &Demo::mode, "a mode").OneOf({"fast", "slow"}),
                      F("note", &Demo::note, "free text"),
                      F("widths", &Demo::widths, "widths").MinItems(1).In(NumberRange::AtLeast(1)),
                      F("files", &Demo::files, "paths").NonEmpty()});
  return kTable;
}

std::string ReadError(const json& j) {
  Demo d;
  Status s = Table().Read(j, "/", &d);
  return std::string(s.message());
}

std::string ValidateError(const Demo& d) { return std::string(Table().Validate(d).message()); }

TEST(FieldTableTest, ReadsEveryTypeAndKeepsMissingKeys) {
  Demo d;
  json j = {{"gain", 0.25},   {"count", 8},     {"steps", 3e7},      {"verbose", true},
            {"mode", "slow"}, {"widths", {32}}, {"files", {"a.bvh"}}};
  j["seed"] = json::parse("18446744073709551615");
  ASSERT_TRUE(Table().Read(j, "/", &d).ok());
  EXPECT_EQ(d.gain, 0.25);
  EXPECT_EQ(d.count, 8);
  EXPECT_EQ(d.steps, 30'000'000);
  EXPECT_EQ(d.seed, 18446744073709551615u);
  EXPECT_TRUE(d.verbose);
  EXPECT_EQ(d.mode, "slow");
  EXPECT_EQ(d.note, "");  // missing: kept
  EXPECT_EQ(d.widths, std::vector<int>{32});
  EXPECT_EQ(d.files, std::vector<std::string>{"a.bvh"});
  EXPECT_TRUE(Table().Validate(d).ok());
}

TEST(FieldTableTest, ReadErrorsNameTheKeyOrPointerAndLeaveTheStructUnchanged) {
  EXPECT_EQ(ReadError(json{{"gian", 1}}),
            "/: unknown key 'gian'; valid keys are: gain, count, steps, seed, verbose, mode, "
            "note, widths, files");
  EXPECT_EQ(ReadError(json{{"count", "8"}}), "/count: expected an integer, got string");
  EXPECT_EQ(ReadError(json{{"count", 8.5}}), "/count: expected an integer, got 8.5");
  EXPECT_EQ(ReadError(json{{"verbose", 1}}), "/verbose: expected true or false, got number");
  EXPECT_EQ(ReadError(json{{"widths", {64, "x"}}}), "/widths/1: expected an integer, got string");
  EXPECT_EQ(ReadError(json{{"files", "a"}}), "/files: expected an array of strings, got string");
  EXPECT_EQ(ReadError(json::array()), "/: expected a JSON object, got array");
  Demo d;
  // the first field is read before the second fails: nothing may stick
  EXPECT_FALSE(Table().Read(json{{"gain", 0.75}, {"count", "x"}}, "/", &d).ok());
  EXPECT_EQ(d.gain, 0.5);
  // a nested table names its own pointer
  EXPECT_EQ(std::string(Table().Read(json{{"count", true}}, "/agents/0", &d).message()),
            "/agents/0/count: expected an integer, got boolean");
}

TEST(FieldTableTest, ValidateNamesTheKeyTheValueAndWhatIsValid) {
  Demo d;
  d.gain = 2;
  EXPECT_EQ(ValidateError(d), "demo config 'gain' = 2 is invalid; valid range is [0, 1]");
  d = Demo();
  d.gain = std::nan("");
  EXPECT_EQ(ValidateError(d), "demo config 'gain' = nan is invalid; valid range is [0, 1]");
  d = Demo();
  d.steps = 0;
  EXPECT_EQ(ValidateError(d), "demo config 'steps' = 0 is invalid; valid range is [1, inf)");
  d = Demo();
  d.mode = "warp";
  EXPECT_EQ(ValidateError(d),
            "demo config 'mode' = \"warp\" is invalid; valid values are: fast, slow");
  d = Demo();
  d.widths = {};
  EXPECT_EQ(ValidateError(d), "demo config 'widths' = [] is invalid; it needs at least 1 entry");
  d.widths = {64, 0};
  EXPECT_EQ(ValidateError(d),
            "demo config 'widths' = [64, 0] is invalid; entry 1 (0) is outside the valid range "
            "[1, inf)");
  d = Demo();
  d.files = {"a", ""};
  EXPECT_EQ(ValidateError(d),
            "demo config 'files' = [\"a\", \"\"] is invalid; entry 1: it must not be empty");
}

TEST(FieldTableTest, ToJsonWritesEveryKeyAndRoundTrips) {
  Demo d;
  d.seed = 18446744073709551615u;
  d.note = "x";
  json j = Table().ToJson(d);
  EXPECT_EQ(j.size(), Table().Keys().size());
  EXPECT_TRUE(j["seed"].is_number_unsigned());
  EXPECT_TRUE(j["count"].is_number_integer());
  EXPECT_TRUE(j["gain"].is_number_float());
  Demo back;
  back.note = "other";
  ASSERT_TRUE(Table().Read(j, "/", &back).ok());
  EXPECT_EQ(Table().ToJson(back), j);
}

}  // namespace
}  // namespace simhuman::core

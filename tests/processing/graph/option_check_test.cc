// CheckOption: every option type against good and bad values, with the message wording the
// pipeline errors are built from.
#include <gtest/gtest.h>

#include "processing/graph/nodes/node_support.h"

namespace mocapfill::graph {
namespace {

using V = OptionValue;

std::string Message(const OptionSpec& spec, const OptionValue& value) {
  const Status s = CheckOption(spec, value);
  EXPECT_FALSE(s.ok()) << FormatOptionValue(value);
  EXPECT_EQ(s.code(), ErrorCode::kInvalidArgument);
  return s.message();
}

TEST(CheckOption, IntegersNeedAnIntegerInRange) {
  const OptionSpec spec = IntOption("candidates", 128, 1, 1000, "doc");
  EXPECT_TRUE(CheckOption(spec, V::Integer(1)).ok());
  EXPECT_TRUE(CheckOption(spec, V::Integer(1000)).ok());
  EXPECT_EQ(Message(spec, V::Integer(0)), "expected an integer in [1, 1000], got 0");
  EXPECT_EQ(Message(spec, V::Integer(1001)), "expected an integer in [1, 1000], got 1001");
  EXPECT_EQ(Message(spec, V::Number(2.5, false)), "expected an integer in [1, 1000], got 2.5");
  EXPECT_EQ(Message(spec, V::String("8")), "expected an integer in [1, 1000], got \"8\"");
}

TEST(CheckOption, NumbersHonourAnExclusiveMinimum) {
  const OptionSpec spec = NumberOption("rate_hz", 30.0, 0.0, true, std::nullopt, "Hz", "doc");
  EXPECT_TRUE(CheckOption(spec, V::Number(0.001, false)).ok());
  EXPECT_TRUE(CheckOption(spec, V::Integer(30)).ok());  // 30 is a number too
  EXPECT_EQ(Message(spec, V::Integer(0)), "expected a number > 0, got 0");
  EXPECT_EQ(Message(spec, V::Bool(true)), "expected a number > 0, got true");
}

TEST(CheckOption, StringsWithChoicesListThem) {
  const OptionSpec spec = StringOption("up", "auto", {"auto", "y", "z"}, "doc");
  EXPECT_TRUE(CheckOption(spec, V::String("z")).ok());
  EXPECT_EQ(Message(spec, V::String("x")), "expected one of auto, y, z, got \"x\"");
  EXPECT_EQ(Message(spec, V::Integer(1)), "expected a string, got 1");
}

TEST(CheckOption, BooleansAreNotNumbers) {
  const OptionSpec spec = BoolOption("texture", true, "doc");
  EXPECT_TRUE(CheckOption(spec, V::Bool(false)).ok());
  EXPECT_EQ(Message(spec, V::Integer(1)), "expected true or false, got 1");
}

TEST(CheckOption, ListAndMapElementsAreCheckedOneByOne) {
  OptionSpec gains = ListOption("gains", OptionType::kNumberList, "doc");
  gains.min = 0.0;
  EXPECT_TRUE(CheckOption(gains, V::Array({V::Integer(1), V::Number(1.5, false)})).ok());
  EXPECT_EQ(Message(gains, V::Array({V::Integer(1), V::Integer(-1)})), "[1]: expected a number >= 0, got -1");
  EXPECT_EQ(Message(gains, V::Integer(1)), "expected an array, got 1");
  const OptionSpec names = ListOption("keep", OptionType::kStringList, "doc");
  EXPECT_EQ(Message(names, V::Array({V::String("Hips"), V::Integer(3)})), "[1]: expected a string, got 3");
  const OptionSpec rename = ListOption("rename", OptionType::kStringMap, "doc");
  EXPECT_TRUE(CheckOption(rename, V::Object({"Hip"}, {V::String("Hips")})).ok());
  EXPECT_EQ(Message(rename, V::Object({"Hip"}, {V::Bool(true)})), "\"Hip\": expected a string, got true");
  EXPECT_EQ(Message(rename, V::Array({})), "expected an object, got []");
}

TEST(CheckOption, ExtraCheckRunsAfterTheTypeCheck) {
  OptionSpec spec = StringOption("method", "a", {}, "doc");
  spec.check = [](const OptionValue& v) { return v.text == "a" ? OkStatus() : InvalidArgument("not a"); };
  EXPECT_TRUE(CheckOption(spec, V::String("a")).ok());
  EXPECT_EQ(Message(spec, V::String("b")), "not a");
  EXPECT_EQ(Message(spec, V::Integer(1)), "expected a string, got 1");  // the check never sees it
}

TEST(CheckOption, PathsMustNotBeEmpty) {
  OptionSpec spec;
  spec.name = "path";
  spec.type = OptionType::kPath;
  EXPECT_TRUE(CheckOption(spec, V::String("walk.bvh")).ok());
  EXPECT_EQ(Message(spec, V::String("")), "expected a path, got an empty string");
}

}  // namespace
}  // namespace mocapfill::graph

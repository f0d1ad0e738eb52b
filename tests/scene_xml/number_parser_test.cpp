// The number grammar of scene attributes: whole-token decimal numbers.

#include "scene_xml/number_parser.h"

#include <gtest/gtest.h>

#include <string_view>
#include <vector>

namespace mhd::scene_xml {
namespace {

TEST(SceneXmlNumbers, ParsesWholeTokens) {
  EXPECT_EQ(parse_double("1.5").status, NumberStatus::Ok);
  EXPECT_DOUBLE_EQ(parse_double("1.5").value, 1.5);
  EXPECT_DOUBLE_EQ(parse_double("-2e-3").value, -2e-3);
  EXPECT_DOUBLE_EQ(parse_double("+4").value, 4.0);
  EXPECT_DOUBLE_EQ(parse_double(".5").value, 0.5);
  EXPECT_DOUBLE_EQ(parse_double(" \t7\n").value, 7.0);
}

TEST(SceneXmlNumbers, RejectsPartialAndForeignSyntax) {
  for (const std::string_view bad : {"", " ", "1.5abc", "abc", "1,5", "0x10", "1e", "--1", "+-1",
                                     "++1", "1 2", "+"}) {
    EXPECT_EQ(parse_double(bad).status, NumberStatus::Invalid) << "'" << bad << "'";
  }
}

TEST(SceneXmlNumbers, NonFiniteAndOutOfRange) {
  EXPECT_EQ(parse_double("nan").status, NumberStatus::NonFinite);
  EXPECT_EQ(parse_double("inf").status, NumberStatus::NonFinite);
  EXPECT_EQ(parse_double("-Infinity").status, NumberStatus::NonFinite);
  EXPECT_EQ(parse_double("1e999").status, NumberStatus::OutOfRange);
}

TEST(SceneXmlNumbers, Integers) {
  EXPECT_EQ(parse_integer("42").value, 42);
  EXPECT_EQ(parse_integer("+8").value, 8);
  EXPECT_EQ(parse_integer("-3").status, NumberStatus::Ok);
  EXPECT_EQ(parse_integer("4.5").status, NumberStatus::Invalid);
  EXPECT_EQ(parse_integer("4abc").status, NumberStatus::Invalid);
  EXPECT_EQ(parse_integer("99999999999999999999").status, NumberStatus::OutOfRange);
}

TEST(SceneXmlNumbers, SplitsOnXmlWhiteSpace) {
  EXPECT_EQ(split_xml_space("  1 2\t\n3  "), (std::vector<std::string_view>{"1", "2", "3"}));
  EXPECT_TRUE(split_xml_space(" \r\n").empty());
  EXPECT_EQ(trim_xml_space("\t x y \n"), "x y");
}

}  // namespace
}  // namespace mhd::scene_xml

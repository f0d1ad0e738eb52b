// Typed reading of a <server>/<planner>/<simulated_user> block: fallbacks, ranges, and
// every problem at its param's line.
#include "scene/param_block_reader.h"

#include <gtest/gtest.h>

namespace mhd {
namespace {

ParamBlock block(std::initializer_list<std::pair<const char*, const char*>> params) {
  ParamBlock b;
  b.where = {"s.xml", 10};
  int line = 11;
  for (const auto& [name, value] : params) {
    b.params.emplace(name, value);
    b.param_where.emplace(name, SourceLocation{"s.xml", line++});
  }
  return b;
}

TEST(ParamBlockReader, ReadsTypedValuesAndFallsBackWhenAbsent) {
  const ParamBlock b = block({{"a_s", " 0.25 "}, {"n", "12"}, {"on", "false"}, {"name", "x y"}});
  ParamBlockReader r(&b, "<server>");
  EXPECT_DOUBLE_EQ(r.positive("a_s", 1.0), 0.25);
  EXPECT_EQ(r.unsigned_integer("n", 3), 12u);
  EXPECT_FALSE(r.boolean("on", true));
  EXPECT_EQ(r.text("name", ""), "x y");
  EXPECT_DOUBLE_EQ(r.number("absent_m", -4.5), -4.5);
  EXPECT_TRUE(r.finish().empty());

  ParamBlockReader none(nullptr, "<server>");
  EXPECT_DOUBLE_EQ(none.fraction("f", 0.5), 0.5);
  EXPECT_TRUE(none.finish().empty());
}

TEST(ParamBlockReader, ReportsEachBadValueAndEachUnknownNameAtItsLine) {
  const ParamBlock b = block({{"neg_s", "-1"}, {"frac", "1.5"}, {"count", "2.5"}, {"flag", "yes"}, {"typo", "1"},
                              {"inf_m", "inf"}});
  ParamBlockReader r(&b, "<server>");
  EXPECT_DOUBLE_EQ(r.positive("neg_s", 2.0), 2.0);  // bad: the fallback is kept
  (void)r.fraction("frac", 0.0);
  (void)r.unsigned_integer("count", 0);
  (void)r.boolean("flag", false);
  (void)r.number("inf_m", 0.0);
  std::vector<std::string> messages;
  for (const Diagnostic& d : r.finish()) messages.push_back(d.to_string());
  EXPECT_EQ(messages, (std::vector<std::string>{
                          "s.xml:11: error: param 'neg_s' in <server> must be a positive number, got '-1'",
                          "s.xml:12: error: param 'frac' in <server> must be a number in [0, 1], got '1.5'",
                          "s.xml:13: error: param 'count' in <server> must be a non-negative integer, got '2.5'",
                          "s.xml:14: error: param 'flag' in <server> must be true or false, got 'yes'",
                          "s.xml:16: error: param 'inf_m' in <server> must be a finite number, got 'inf'",
                          "s.xml:15: error: unknown param 'typo' in <server> (known: count, flag, frac, inf_m, neg_s)"}));
}

}  // namespace
}  // namespace mhd

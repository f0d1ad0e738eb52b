#include "diagnostics/result.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace mhd {
namespace {

Result<int> parse_positive(int v) {
  if (v > 0) return v;
  return Diagnostic{{"scene.xml", 7}, "must be > 0"};
}

TEST(Result, AValueIsOkAndGivesItsValue) {
  const Result<int> r = parse_positive(3);
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(static_cast<bool>(r));
  EXPECT_EQ(r.value(), 3);
  EXPECT_EQ(*r, 3);
  EXPECT_EQ(r.value_or(9), 3);
  EXPECT_EQ(r.error_text(), "");
  EXPECT_TRUE(r.diagnostics().empty());
  EXPECT_THROW((void)r.error(), BadResultAccess);
}

TEST(Result, AnErrorIsNotOkAndCarriesItsDiagnosticsWithFileAndLine) {
  const Result<int> r = parse_positive(-1);
  ASSERT_FALSE(r.ok());
  EXPECT_FALSE(static_cast<bool>(r));
  ASSERT_EQ(r.error().size(), 1u);
  EXPECT_EQ(r.error().front().where.line, 7);
  EXPECT_EQ(r.error_text(), "scene.xml:7: error: must be > 0");
  EXPECT_EQ(r.diagnostics().size(), 1u);
  EXPECT_EQ(r.value_or(9), 9);
}

TEST(Result, ValueOfAnErrorThrowsNamingTheIgnoredError) {
  const Result<int> r = parse_positive(0);
  try {
    (void)r.value();
    FAIL() << "value() of an error returned";
  } catch (const BadResultAccess& e) {
    EXPECT_NE(std::string(e.what()).find("scene.xml:7: error: must be > 0"), std::string::npos) << e.what();
  }
}

TEST(Result, AnEmptyDiagnosticListIsStillAnError) {
  const Result<int> r = Diagnostics{};
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().size(), 1u);
  EXPECT_NE(r.error_text().find("no diagnostic given"), std::string::npos);
}

TEST(Result, SeveralDiagnosticsAreKeptInOrder) {
  const Result<std::string> r = Diagnostics{{{"a.xml", 1}, "first"}, {{"b.xml", 0}, "second"}};
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error_text(), "a.xml:1: error: first\nb.xml: error: second");
}

TEST(Result, AMoveOnlyValueMovesOut) {
  Result<std::unique_ptr<int>> r = std::make_unique<int>(5);
  ASSERT_TRUE(r.ok());
  std::unique_ptr<int> p = std::move(r).value();
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(*p, 5);
}

struct KindError {
  int kind = 0;
  std::string message;
};

TEST(Result, ALayersOwnErrorTypeKeepsItsFields) {
  const Result<double, KindError> bad = KindError{4, "too few samples"};
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().kind, 4);
  EXPECT_EQ(bad.error_text(), "too few samples");
  EXPECT_THROW((void)bad.value(), BadResultAccess);
  const Result<double, KindError> good = 2.5;
  ASSERT_TRUE(good.ok());
  EXPECT_EQ(good.value(), 2.5);
}

TEST(Status, SuccessHasNoErrorAndFailureHasOne) {
  const Status<> fine;
  EXPECT_TRUE(fine.ok());
  EXPECT_THROW((void)fine.error(), BadResultAccess);
  const Status<> failed = Diagnostic{{"rig.xml", 3}, "not a rotation"};
  ASSERT_FALSE(failed.ok());
  EXPECT_EQ(failed.error_text(), "rig.xml:3: error: not a rotation");
}

}  // namespace
}  // namespace mhd

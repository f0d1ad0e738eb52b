#include "sim_common/plugin_params.h"
#include "sim_common/plugin_shell.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace mhd::plugin_support {
namespace {

std::vector<mhd_param> params(std::initializer_list<std::pair<const char*, const char*>> list) {
  std::vector<mhd_param> out;
  for (const auto& [name, value] : list) out.push_back({name, value});
  return out;
}

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const ParamError& e) {
    return e.what();
  }
  return "";
}

TEST(ParamReader, ReadsTypedValuesAndFallsBack) {
  const auto p = params({{"rate_hz", " 90 "}, {"offset_m", "0.1 -2 3e-3"}, {"seed", "12"}, {"slip", "0.25"}});
  ParamReader r(p.data(), p.size());
  EXPECT_EQ(r.positive("rate_hz", 180.0), 90.0);
  EXPECT_EQ(r.positive("absent", 7.0), 7.0);
  EXPECT_EQ(r.vector3("offset_m", Eigen::Vector3d::Zero()), Eigen::Vector3d(0.1, -2.0, 3e-3));
  EXPECT_EQ(r.unsigned_integer("seed", 0, 100), 12u);
  EXPECT_EQ(r.fraction("slip", 0.0), 0.25);
  EXPECT_FALSE(r.optional_number("x_m").has_value());
  r.reject_unknown();

  const auto q = params({{"q", "0 0 2 0"}});
  ParamReader rq(q.data(), q.size());
  EXPECT_EQ(rq.optional_quaternion("q")->coeffs(), Eigen::Vector4d(0.0, 1.0, 0.0, 0.0));  // x y z w
}

TEST(ParamReader, NamesTheParameterAndTheValueInEveryError) {
  const auto message = [](const char* value, auto read) {
    const auto p = params({{"v", value}});
    ParamReader r(p.data(), p.size());
    return error_of([&] { read(r); });
  };
  const auto positive = [](ParamReader& r) { (void)r.positive("v", 1.0); };
  EXPECT_EQ(message("abc", positive), "parameter 'v' must be a positive number, got 'abc'");
  EXPECT_EQ(message("0", positive), "parameter 'v' must be a positive number, got '0'");
  EXPECT_EQ(message("nan", positive), "parameter 'v' must be a positive number, got 'nan'");
  EXPECT_EQ(message("1e999", positive), "parameter 'v' must be a positive number, got '1e999'");
  EXPECT_EQ(message("", positive), "parameter 'v' must be a positive number, got ''");
  EXPECT_EQ(message("-1", [](ParamReader& r) { (void)r.non_negative("v", 1.0); }),
            "parameter 'v' must be a non-negative number, got '-1'");
  EXPECT_EQ(message("1", [](ParamReader& r) { (void)r.fraction("v", 0.0); }),
            "parameter 'v' must be a number in [0, 1), got '1'");
  EXPECT_EQ(message("inf", [](ParamReader& r) { (void)r.number("v", 0.0); }),
            "parameter 'v' must be a number, got 'inf'");
  EXPECT_EQ(message("1.5", [](ParamReader& r) { (void)r.unsigned_integer("v", 0, 9); }),
            "parameter 'v' must be an integer from 0 to 9, got '1.5'");
  EXPECT_EQ(message("10", [](ParamReader& r) { (void)r.unsigned_integer("v", 0, 9); }),
            "parameter 'v' must be an integer from 0 to 9, got '10'");
  EXPECT_EQ(message("1 2", [](ParamReader& r) { (void)r.vector3("v", Eigen::Vector3d::Zero()); }),
            "parameter 'v' must be three numbers 'x y z', got '1 2'");
  EXPECT_EQ(message("1 2 3 4", [](ParamReader& r) { (void)r.vector3("v", Eigen::Vector3d::Zero()); }),
            "parameter 'v' must be three numbers 'x y z', got '1 2 3 4'");
  EXPECT_EQ(message("1 0 0", [](ParamReader& r) { (void)r.optional_quaternion("v"); }),
            "parameter 'v' must be a quaternion 'w x y z' of non-zero norm, got '1 0 0'");
}

TEST(ParamReader, RejectsUnknownDuplicateAndMissingParameters) {
  const auto p = params({{"rate_hz", "90"}, {"colour", "red"}});
  ParamReader r(p.data(), p.size());
  (void)r.positive("rate_hz", 1.0);
  (void)r.positive("latency_s", 1.0);
  EXPECT_EQ(error_of([&] { r.reject_unknown(); }), "unknown parameter 'colour' (known: rate_hz, latency_s)");
  EXPECT_EQ(error_of([&] { (void)r.required_text("file"); }), "missing parameter 'file'");

  const auto twice = params({{"a", "1"}, {"a", "2"}});
  EXPECT_EQ(error_of([&] { ParamReader(twice.data(), twice.size()); }), "parameter 'a' is given twice");
  const auto null_value = params({{"a", nullptr}});
  EXPECT_EQ(error_of([&] { ParamReader(null_value.data(), null_value.size()); }),
            "parameter 0 has a NULL name or value");
}

TEST(ParamReader, ShortensTheKnownListToFitAnErrorMessage) {
  const auto p = params({{"x", "1"}});
  ParamReader r(p.data(), p.size());
  for (int i = 0; i < 40; ++i) (void)r.number(("parameter_" + std::to_string(i)).c_str(), 0.0);
  const std::string message = error_of([&] { r.reject_unknown(); });
  EXPECT_LE(message.size(), static_cast<std::size_t>(MHD_ERROR_MESSAGE_SIZE - 1));
  EXPECT_EQ(message.rfind("unknown parameter 'x' (known: parameter_0, parameter_1, ", 0), 0u);
  EXPECT_EQ(message.substr(message.size() - 6), ", ...)");
}

TEST(PluginShell, ErrorMessagesAreTruncatedAndTerminated) {
  mhd_error err{};
  set_error(&err, std::string(400, 'x'));
  EXPECT_EQ(std::strlen(err.message), sizeof(err.message) - 1);
  set_error(nullptr, "ignored");  // no crash
  EXPECT_EQ(guarded(&err, []() -> mhd_status { throw std::runtime_error("boom"); }), MHD_ERROR);
  EXPECT_STREQ(err.message, "boom");
}

}  // namespace
}  // namespace mhd::plugin_support

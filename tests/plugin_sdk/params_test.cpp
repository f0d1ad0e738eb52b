#include <mhd/plugin_sdk.hpp>
#include <mhd/plugin_sdk_params.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace mhd::sdk {
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

constexpr std::array kDecls{
    sdk::number("rate_hz", "Hz", "180", "rate", sdk::positive()),
    sdk::number("absent", "", nullptr, "never given", sdk::positive()),
    sdk::vector3("offset_m", "m", nullptr, "an offset"),
    sdk::integer("seed", "", "0", "a seed", sdk::between(0, 100)),
    sdk::number("slip", "", "0", "a fraction", sdk::fraction()),
    sdk::number("x_m", "m", nullptr, "a number"),
    sdk::quaternion("q", nullptr, "an orientation"),
    sdk::required_text("file", "a file"),
    sdk::boolean("on", "false", "a switch"),
    sdk::vector3("origin_m", "m", "1 2 3", "an origin"),
};

// One default per parameter, the declared one: no getter takes a second, C++ fallback.
template <class P>
concept TakesAFallback = requires(const P& p) { p.number("rate_hz", 1.0); } ||
                         requires(const P& p) { p.integer("seed", 1u); } ||
                         requires(const P& p) { p.boolean("on", true); } ||
                         requires(const P& p) { p.vector3("origin_m", std::array{0.0, 0.0, 0.0}); };
static_assert(!TakesAFallback<Params>, "a getter with a fallback gives a parameter a second default");

TEST(SdkParams, ReadsTypedValues) {
  const auto p = params({{"rate_hz", " 90 "}, {"offset_m", "0.1 -2 3e-3"}, {"seed", "12"}, {"slip", "0.25"},
                         {"q", "0 0 2 0"}, {"file", "a.csv"}, {"origin_m", "4 5 6"}});
  Params r(kDecls, p.data(), p.size());
  EXPECT_EQ(r.number("rate_hz"), 90.0);
  EXPECT_FALSE(r.optional_number("absent").has_value());
  EXPECT_EQ(*r.optional_vector3("offset_m"), (std::array{0.1, -2.0, 3e-3}));
  EXPECT_EQ(r.vector3("origin_m"), (std::array{4.0, 5.0, 6.0}));
  EXPECT_EQ(r.integer("seed"), 12u);
  EXPECT_EQ(r.number("slip"), 0.25);
  EXPECT_FALSE(r.optional_number("x_m").has_value());
  EXPECT_EQ(*r.optional_quaternion("q"), (std::array{0.0, 0.0, 1.0, 0.0}));  // w x y z, normalised
  EXPECT_EQ(r.text("file"), "a.csv");
  EXPECT_TRUE(r.given("file"));
  EXPECT_FALSE(r.given("absent"));
}

TEST(SdkParams, AbsentValuesComeFromTheDeclaredDefaults) {
  const auto p = params({{"file", "a.csv"}});
  Params r(kDecls, p.data(), p.size());
  EXPECT_EQ(r.number("rate_hz"), 180.0);
  EXPECT_EQ(r.integer("seed"), 0u);
  EXPECT_FALSE(r.boolean("on"));
  EXPECT_EQ(r.vector3("origin_m"), (std::array{1.0, 2.0, 3.0}));
  EXPECT_THROW((void)r.number("x_m"), std::logic_error);  // no default: optional_number is the way
  EXPECT_THROW((void)r.vector3("offset_m"), std::logic_error);
  EXPECT_FALSE(r.optional_vector3("offset_m").has_value());
}

TEST(SdkParams, TheDeclarationsRefuseBadValuesNamingParameterValueAndRule) {
  const auto message = [](const char* name, const char* value) {
    const auto p = params({{name, value}, {"file", "f"}});
    return error_of([&] { Params r(kDecls, p.data(), p.size()); });
  };
  EXPECT_EQ(message("rate_hz", "abc"), "parameter 'rate_hz' must be a number > 0 (Hz), got 'abc'");
  EXPECT_EQ(message("rate_hz", "0"), "parameter 'rate_hz' must be a number > 0 (Hz), got '0'");
  EXPECT_EQ(message("rate_hz", "nan"), "parameter 'rate_hz' must be a number > 0 (Hz), got 'nan'");
  EXPECT_EQ(message("rate_hz", "1e999"), "parameter 'rate_hz' must be a number > 0 (Hz), got '1e999'");
  EXPECT_EQ(message("rate_hz", ""), "parameter 'rate_hz' must be a number > 0 (Hz), got ''");
  EXPECT_EQ(message("slip", "1"), "parameter 'slip' must be a number in [0, 1), got '1'");
  EXPECT_EQ(message("x_m", "inf"), "parameter 'x_m' must be a number (m), got 'inf'");
  EXPECT_EQ(message("seed", "1.5"), "parameter 'seed' must be a non-negative integer in [0, 100], got '1.5'");
  EXPECT_EQ(message("seed", "101"), "parameter 'seed' must be a non-negative integer in [0, 100], got '101'");
  EXPECT_EQ(message("offset_m", "1 2"), "parameter 'offset_m' must be three numbers 'x y z' (m), got '1 2'");
  EXPECT_EQ(message("offset_m", "1 2 3 4"), "parameter 'offset_m' must be three numbers 'x y z' (m), got '1 2 3 4'");
  EXPECT_EQ(message("q", "0 0 0 0"), "parameter 'q' must be four numbers 'w x y z' of non-zero norm, got '0 0 0 0'");
  // The dual: the edge values the rules allow are accepted.
  EXPECT_EQ(message("slip", "0"), "");
  EXPECT_EQ(message("seed", "100"), "");
  EXPECT_EQ(message("rate_hz", "1e-9"), "");
}

TEST(SdkParams, RejectsUnknownDuplicateAndMissingParameters) {
  const auto p = params({{"rate_hz", "90"}, {"colour", "red"}, {"file", "f"}});
  EXPECT_EQ(error_of([&] { Params r(kDecls, p.data(), p.size()); }),
            "unknown parameter 'colour' (known: rate_hz, absent, offset_m, seed, slip, x_m, q, file, on, origin_m)");
  const auto missing = params({{"rate_hz", "90"}});
  EXPECT_EQ(error_of([&] { Params r(kDecls, missing.data(), missing.size()); }),
            "parameter 'file' is required");
  const auto twice = params({{"file", "1"}, {"file", "2"}});
  EXPECT_EQ(error_of([&] { Params r(kDecls, twice.data(), twice.size()); }), "parameter 'file' is given twice");
  const auto null_value = params({{"file", nullptr}});
  EXPECT_EQ(error_of([&] { Params r(kDecls, null_value.data(), null_value.size()); }),
            "parameter 0 has a NULL name or value");
}

TEST(SdkParams, AGetterForAnUndeclaredNameIsAPluginBug) {
  const auto p = params({{"file", "f"}});
  Params r(kDecls, p.data(), p.size());
  EXPECT_THROW((void)r.number("latency_s"), std::logic_error);
}

TEST(SdkParams, ShortensALongErrorToFitAnErrorMessage) {
  std::vector<std::string> names;
  for (int i = 0; i < 40; ++i) names.push_back("parameter_" + std::to_string(i));
  std::vector<mhd_param_decl> decls;
  for (const std::string& name : names) decls.push_back(sdk::number(name.c_str(), "", nullptr, "doc"));
  const auto p = params({{"x", "1"}});
  const std::string message = error_of([&] { Params r(decls, p.data(), p.size()); });
  EXPECT_LE(message.size(), static_cast<std::size_t>(MHD_ERROR_MESSAGE_SIZE - 1));
  EXPECT_EQ(message.rfind("unknown parameter 'x' (known: parameter_0, parameter_1, ", 0), 0u);
  EXPECT_EQ(message.substr(message.size() - 4), "...)");
}

TEST(SdkErrors, ErrorMessagesAreTruncatedAndTerminated) {
  mhd_error err{};
  set_error(&err, std::string(400, 'x'));
  EXPECT_EQ(std::strlen(err.message), sizeof(err.message) - 1);
  set_error(nullptr, "ignored");  // no crash
  EXPECT_EQ(guarded(&err, MHD_ERROR, []() -> mhd_status { throw std::runtime_error("boom"); }), MHD_ERROR);
  EXPECT_STREQ(err.message, "boom");
}

}  // namespace
}  // namespace mhd::sdk

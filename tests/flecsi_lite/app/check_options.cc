// The apps' checks as declared options (app/check_options.hh): parsed whole, finite, in range and
// of the declared count, else a parameter error naming the option and the value; and the frame's
// rule that a run's files are distinct (require_distinct_files), also through a hard link.
#include <catch2/catch.hpp>

#include "flecsi_lite/app.hh"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace flecsi_lite;
using Catch::Contains;

namespace {
const std::vector<app::check_option> checks = {{"check-l1", {"RHO", "P", "V"}, "L1 errors"},
                                               {"check-energy", {"TOL"}, "energy", 0, 1}};

app::check_values parse(const std::vector<std::string>& arguments) {
  runtime::options options;
  app::declare_checks(checks, options);
  std::vector<const char*> argv = {"program"};
  for (const auto& argument : arguments) argv.push_back(argument.c_str());
  options.parse(static_cast<int>(argv.size()), argv.data());
  return app::parse_checks(checks, options);
}

std::string refusal(const std::vector<std::string>& arguments) {
  try {
    parse(arguments);
  } catch (const runtime::parameter_error& e) {
    return e.what();
  }
  return "accepted";
}
}  // namespace

TEST_CASE("a check's bounds are parsed at once, each a whole finite number in range") {
  const auto given = parse({"--check-l1", "0.1, 2e-3,0", "--check-energy=0.5"});
  CHECK(given.has("check-l1"));
  CHECK(given.bounds("check-l1") == std::vector<double>{0.1, 2e-3, 0});
  CHECK(given.bound("check-energy") == 0.5);
  CHECK_FALSE(parse({}).has("check-l1"));
  CHECK(std::isnan(app::parse_bound("1x")));
  CHECK(std::isnan(app::parse_bound("")));
  CHECK(app::parse_bound(" 3 ") == 3);
}

TEST_CASE("a bad check value is a parameter error naming the option, the bound and the value") {
  CHECK_THAT(refusal({"--check-l1", "0.1,x,0.1"}), Contains("--check-l1 '0.1,x,0.1': P = 'x' is not a number"));
  CHECK_THAT(refusal({"--check-l1", "nan,1,1"}), Contains("RHO = 'nan' is not a number"));
  CHECK_THAT(refusal({"--check-l1", "inf,1,1"}), Contains("RHO = 'inf' is not finite"));
  CHECK_THAT(refusal({"--check-l1", "1e999,1,1"}), Contains("RHO = '1e999' is not finite"));
  CHECK_THAT(refusal({"--check-l1", "-1,1,1"}), Contains("RHO = '-1' is out of range"));
  CHECK_THAT(refusal({"--check-l1", "1,1"}), Contains("2 values for 3 bounds"));
  CHECK_THAT(refusal({"--check-l1", "1,1,1,"}), Contains("4 values for 3 bounds"));
  CHECK_THAT(refusal({"--check-energy", "2"}), Contains("TOL = '2' is out of range"));
  CHECK_THAT(refusal({"--check-energy", "2"}), Contains("finite numbers >= 0 and <= 1"));
}

TEST_CASE("a run's files are distinct: any two naming one file are refused naming both keys") {
  const std::string a = "distinct_files_a.txt", b = "distinct_files_b.txt";
  std::remove(b.c_str());
  std::ofstream(a) << "parameters\n";
  CHECK_NOTHROW(app::require_distinct_files({{"the parameter file", a}, {"output_file", b}, {"--trace", ""}}));
  try {
    app::require_distinct_files({{"the parameter file", a}, {"output_file", "o.h5part"}, {"--trace", "./" + a}});
    FAIL("accepted");
  } catch (const runtime::parameter_error& e) {
    CHECK_THAT(std::string(e.what()), Contains("--trace './" + a + "' is also the parameter file '" + a + "'"));
  }
  // A hard link is the same file under another name.
  std::filesystem::create_hard_link(a, b);
  CHECK(app::names_same_file(a, b));
  CHECK_THROWS_AS(app::require_distinct_files({{"the parameter file", a}, {"stop_file", b}}), runtime::parameter_error);
  // A restart may write its checkpoint over the one it continues.
  CHECK_NOTHROW(app::require_distinct_files({{"restart_file", "c.h5part"}, {"checkpoint_file", "c.h5part"}}));
  std::remove(a.c_str());
  std::remove(b.c_str());
}

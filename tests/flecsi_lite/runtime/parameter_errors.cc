// Parameter errors: each mistake in a parameter file or on the command line throws
// parameter_error naming the file and line (or the argument), the key and the bad value;
// mistakes of the program throw std::logic_error.
#include <catch2/catch.hpp>

#include "flecsi_lite/runtime/parameters.hh"
#include "flecsi_lite/util/edit_distance.hh"

using namespace flecsi_lite::runtime;
using Catch::Contains;

namespace {
parameter_schema schema() {
  parameter_schema s;
  s.real("gamma", "adiabatic index").default_value(1.4).range(1, 3);
  s.real("cfl", "Courant number").default_value(0.25).greater_than(0).at_most(1);
  s.integer("particles", "number of particles").at_least(1);
  s.boolean("periodic", "periodic boundaries").default_value(false);
  s.choice("kernel", {"cubic_spline", "wendland_c2"}, "smoothing kernel").default_value("cubic_spline");
  s.real_list("box", "box corners").default_value({0.0, 1.0}).length(2).at_least(-10);
  s.string("output", "output file").default_value("out.h5part");
  return s;
}

// The message of the parameter_error thrown by parsing `text` (with `overrides`).
std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parameters::parse(schema(), text, "run.par", overrides);
  } catch (const parameter_error& e) {
    return e.what();
  }
  FAIL("no parameter_error for:\n" << text);
  return "";
}
}  // namespace

TEST_CASE("an unknown key names the file, the line and the nearest valid key") {
  const auto message = error_of("particles = 10\n# comment\ngama = 1.4\n");
  CHECK_THAT(message, Contains("run.par:3") && Contains("unknown key 'gama'") && Contains("did you mean 'gamma'?"));
  // Nothing close enough: no suggestion.
  CHECK_THAT(error_of("particles = 10\nzzzzzzzzzz = 1\n"), !Contains("did you mean"));
  CHECK_THAT(error_of("particles = 10\n", {"perodic=true"}),
             Contains("command line (--set perodic=true)") && Contains("did you mean 'periodic'?"));
}

TEST_CASE("malformed lines are reported with their text") {
  CHECK_THAT(error_of("particles = 10\ngamma 1.4\n"),
             Contains("run.par:2") && Contains("malformed line 'gamma 1.4'") && Contains("key = value"));
  CHECK_THAT(error_of("= 3\n"), Contains("run.par:1: malformed line '= 3'"));
  CHECK_THAT(error_of("sph eta = 1.2\n"), Contains("malformed line 'sph eta = 1.2'"));
  CHECK_THAT(error_of("particles =   # nothing\n"), Contains("run.par:1: key 'particles' has no value"));
  CHECK_THAT(error_of("particles = 1\n", {"gamma"}), Contains("--set gamma") && Contains("expected key=value"));
  CHECK_THAT(error_of("particles = 1\noutput = \"a.h5part\n"), Contains("run.par:2") && Contains("quote it"));
}

TEST_CASE("a key given twice in a file names both lines; --set may repeat a key") {
  CHECK_THAT(error_of("gamma = 1.4\nparticles = 1\n\ngamma = 1.2\n"),
             Contains("run.par:4: key 'gamma' is given twice (first on line 1)"));
  CHECK_NOTHROW(parameters::parse(schema(), "particles = 1\n", "run.par", {"gamma=1.1", "gamma=1.2"}));
}

TEST_CASE("values of the wrong type name the key, its type and the value") {
  CHECK_THAT(error_of("particles = 1\ngamma = abc\n"),
             Contains("run.par:2: key 'gamma' (real): 'abc' is not a real number"));
  CHECK_THAT(error_of("particles = 1.5\n"), Contains("key 'particles' (integer): '1.5' is not an integer"));
  CHECK_THAT(error_of("particles = 1e3\n"), Contains("'1e3' is not an integer"));
  CHECK_THAT(error_of("particles = 99999999999999999999\n"), Contains("out of the range of a 64-bit integer"));
  CHECK_THAT(error_of("particles = 1\nperiodic = maybe\n"),
             Contains("key 'periodic' (boolean): 'maybe' is not a boolean"));
  CHECK_THAT(error_of("particles = 1\ngamma = 1.4.2\n"), Contains("'1.4.2' is not a real number"));
  CHECK_THAT(error_of("particles = 1\ngamma = inf\n"), Contains("'inf' is not a real number"));
  CHECK_THAT(error_of("particles = 1\ngamma = 1e999\n"), Contains("'1e999' is out of the range of a double"));
  CHECK_THAT(error_of("particles = 1\nbox = 0, x\n"),
             Contains("key 'box' (list of reals)") && Contains("element 2 'x'"));
  CHECK_THAT(error_of("particles = 1\nbox = 0,,1\n"), Contains("element 2 ''"));
  CHECK_THAT(error_of("particles = 1\n", {"gamma=fast"}),
             Contains("command line (--set gamma=fast): key 'gamma' (real): 'fast' is not a real number"));
}

TEST_CASE("values out of range or not among the choices say what is allowed") {
  CHECK_THAT(error_of("particles = 1\ngamma = 3.5\n"),
             Contains("run.par:2: key 'gamma'") && Contains("3.5 is out of range (must be in [1, 3])"));
  CHECK_THAT(error_of("particles = 1\ncfl = 0\n"), Contains("0 is out of range (must be in (0, 1])"));
  CHECK_NOTHROW(parameters::parse(schema(), "particles = 1\ncfl = 1\ngamma = 3\n", "run.par"));
  CHECK_THAT(error_of("particles = 0\n"), Contains("key 'particles'") && Contains("0 is out of range (must be >= 1)"));
  CHECK_THAT(error_of("particles = 1\nkernel = wendland\n"),
             Contains("run.par:2: key 'kernel'") && Contains("'wendland' is not one of: cubic_spline, wendland_c2") &&
               Contains("did you mean 'wendland_c2'?"));
  CHECK_THAT(error_of("particles = 1\nbox = 0, 1, 2\n"), Contains("has 3 elements, not 2"));
  CHECK_THAT(error_of("particles = 1\nbox = -11, 1\n"), Contains("element 1 (-11) is out of range (must be >= -10)"));
}

TEST_CASE("missing required keys are all named, with their description") {
  parameter_schema s = schema();
  s.real("length", "box length");
  try {
    parameters::parse(s, "gamma = 1.4\n", "run.par");
    FAIL("no error");
  } catch (const parameter_error& e) {
    CHECK_THAT(e.what(), Contains("run.par: missing required key 'particles' (number of particles), "
                                  "'length' (box length)"));
  }
  // A required key given only on the command line is fine.
  CHECK(parameters::parse(schema(), "", "", {"particles=5"}).get<int>("particles") == 5);
}

TEST_CASE("a missing or unreadable file is a parameter_error naming it") {
  CHECK_THROWS_WITH(parameters::load(schema(), "no/such/file.par"),
                    Contains("cannot read parameter file 'no/such/file.par'") && Contains("No such file"));
  CHECK_THROWS_WITH(parameters::load(schema(), "."), Contains("'.': it is a directory"));
}

TEST_CASE("an integer too large for the type the program reads it as is a parameter_error") {
  const auto p = parameters::parse(schema(), "particles = 300\n", "run.par");
  CHECK(p.get<std::int16_t>("particles") == 300);
  CHECK_THROWS_AS(p.get<std::int8_t>("particles"), parameter_error);
  CHECK_THROWS_WITH(p.get<std::uint8_t>("particles"), Contains("'particles' = 300 (file run.par:1)"));
}

TEST_CASE("mistakes of the program are logic errors") {
  const auto p = parameters::parse(schema(), "particles = 3\n", "run.par");
  CHECK_THROWS_AS(p.get<double>("gama"), std::logic_error);
  CHECK_THROWS_WITH(p.get<double>("gama"), Contains("no key 'gama'") && Contains("did you mean 'gamma'?"));
  CHECK_THROWS_WITH(p.get<int>("gamma"), Contains("'gamma' is declared real and cannot be read as an integral type"));
  CHECK_THROWS_WITH(p.get<std::string>("particles"), Contains("'particles' is declared integer"));
  CHECK_THROWS_AS(p.get<bool>("gamma"), std::logic_error);

  parameter_schema s;
  s.real("x", "x");
  CHECK_THROWS_AS(s.real("x", "again"), std::logic_error);
  CHECK_THROWS_AS(s.boolean("flag", "a flag").at_least(0), std::logic_error);
  CHECK_THROWS_AS(s.integer("n", "n").default_value("ten"), std::logic_error);
  s.integer("m", "m").default_value(0).at_least(1);
  CHECK_THROWS_WITH(parameters::parse(s, "x = 1\n", "s.par"), Contains("default of 'm' is invalid"));
}

TEST_CASE("LF, CRLF and lone CR all end lines, with the same line numbers") {
  const std::string lines[] = {"particles = 7", "# a comment", "gamma = 1.2", "periodic = yes"};
  for (const std::string end : {"\n", "\r\n", "\r"}) {
    std::string text;
    for (const auto& line : lines) text += line + end;
    const auto p = parameters::parse(schema(), text, "run.par");
    CHECK(p.get<int>("particles") == 7);
    CHECK(p.get<double>("gamma") == 1.2);
    CHECK(p.get<bool>("periodic"));
    CHECK(p.origin("gamma") == "file run.par:3");
    // An error names the same line whatever the line ends.
    CHECK_THAT(error_of(text + "gama = 1" + end), Contains("run.par:5: unknown key 'gama'"));
  }
  // A lone CR before CRLF is an empty line of its own.
  CHECK(parameters::parse(schema(), "particles = 1\r\r\ngamma = 2\r\n", "run.par").origin("gamma") == "file run.par:3");
}

TEST_CASE("a value starting with '=' is an error naming file, line and key") {
  CHECK_THAT(error_of("particles = 1\ngamma == 3\n"),
             Contains("run.par:2: the value of key 'gamma' starts with '='") && Contains("one '='"));
  CHECK_THAT(error_of("particles = 1\n", {"gamma==3"}),
             Contains("command line (--set gamma==3)") && Contains("key 'gamma' starts with '='"));
  // A '=' later in a value is the value's own (strings may hold it).
  CHECK(parameters::parse(schema(), "particles = 1\noutput = a=b\n", "run.par").get<std::string>("output") == "a=b");
}

TEST_CASE("a key longer than 200 characters is an error without a suggestion, quoted short") {
  const std::string long_key(10'000'000, 'g');
  for (const std::string& text : {long_key + " = 1\n", "particles = 1\n" + long_key + "a=1\n"}) {
    const auto message = error_of(text);
    CHECK_THAT(message, Contains("is longer than 200 characters") && !Contains("did you mean"));
    CHECK(message.size() < 300);
  }
  CHECK_THAT(error_of("particles = 1\n", {long_key + "=1"}),
             Contains("command line (--set ggg") && Contains("is longer than 200 characters"));
  // A malformed long line is quoted short too.
  CHECK(error_of(long_key + "\n").size() < 300);
  // 200 characters is still a key, unknown here.
  CHECK_THAT(error_of(std::string(200, 'k') + " = 1\n"), Contains("unknown key"));
}

TEST_CASE("did you mean: the nearest name, found without computing hopeless distances") {
  using flecsi_lite::util::edit_distance;
  using flecsi_lite::util::nearest_name;
  const std::vector<std::string> names = {"particles", "gamma", "periodic", "kernel", "x", "particles_per_side"};
  // The suggestion equals the brute-force nearest within the typo distance, first one on ties.
  for (const std::string typo : {"particels", "gama", "perodic", "kernal", "y", "particles_per_sid", "zzzzzzzz", ""}) {
    std::string expected;
    std::size_t best = std::max<std::size_t>(3, typo.size() / 2) + 1;
    for (const auto& name : names)
      if (const auto d = edit_distance(typo, name); d < best) best = d, expected = name;
    CHECK(nearest_name(typo, names) == expected);
  }
  // Names too long to be a typo of any key get no suggestion.
  CHECK(nearest_name(std::string(300, 'a'), std::vector<std::string>{std::string(299, 'a')}).empty());
}

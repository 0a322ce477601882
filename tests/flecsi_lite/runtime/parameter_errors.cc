// Parameter errors: each mistake in a parameter file or on the command line throws
// parameter_error naming the file and line (or the argument), the key and the bad value;
// mistakes of the program throw std::logic_error.
#include <catch2/catch.hpp>

#include "flecsi_lite/runtime/parameters.hh"

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
} // namespace

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
  CHECK_THAT(error_of("particles = 1\nperiodic = maybe\n"), Contains("key 'periodic' (boolean): 'maybe' is not a boolean"));
  CHECK_THAT(error_of("particles = 1\ngamma = 1.4.2\n"), Contains("'1.4.2' is not a real number"));
  CHECK_THAT(error_of("particles = 1\ngamma = inf\n"), Contains("'inf' is not a real number"));
  CHECK_THAT(error_of("particles = 1\ngamma = 1e999\n"), Contains("'1e999' is out of the range of a double"));
  CHECK_THAT(error_of("particles = 1\nbox = 0, x\n"), Contains("key 'box' (list of reals)") && Contains("element 2 'x'"));
  CHECK_THAT(error_of("particles = 1\nbox = 0,,1\n"), Contains("element 2 ''"));
  CHECK_THAT(error_of("particles = 1\n", {"gamma=fast"}),
             Contains("command line (--set gamma=fast): key 'gamma' (real): 'fast' is not a real number"));
}

TEST_CASE("values out of range or not among the choices say what is allowed") {
  CHECK_THAT(error_of("particles = 1\ngamma = 3.5\n"), Contains("run.par:2: key 'gamma'") &&
                                                         Contains("3.5 is out of range (must be in [1, 3])"));
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

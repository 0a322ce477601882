// Parameter files: values of every type, comments, defaults, command-line overrides, origins,
// the resolved text (which reads back to the same values) and the schema's help.
#include <catch2/catch.hpp>

#include "flecsi_lite/runtime/parameters.hh"

#include <cstdio>
#include <fstream>

using namespace flecsi_lite::runtime;

namespace {
parameter_schema sod_schema() {
  parameter_schema s;
  s.real("gamma", "adiabatic index").default_value(5.0 / 3).range(1, 3);
  s.real("cfl", "Courant number").default_value(0.25).greater_than(0).at_most(1);
  s.integer("particles", "number of particles").at_least(1);
  s.boolean("periodic", "periodic boundaries").default_value(false);
  s.string("output", "output file").default_value("out.h5part");
  s.choice("kernel", {"cubic_spline", "wendland_c2", "wendland_c4"}, "smoothing kernel").default_value("cubic_spline");
  s.real_list("box", "lower and upper corner along x").default_value({0.0, 1.0}).length(2);
  return s;
}
}  // namespace

TEST_CASE("a parameter file sets values of every type; comments and blank lines are ignored") {
  const std::string text =
    "# Sod shock tube\n"
    "\n"
    "gamma = 1.4          # ideal diatomic gas\n"
    "  particles=1000\n"
    "periodic = yes\n"
    "output = \"sod#1.h5part\"   # a quoted string may hold '#'\n"
    "kernel = wendland_c2\n"
    "box = -0.5, 0.5\r\n";
  const auto p = parameters::parse(sod_schema(), text, "sod.par");
  CHECK(p.get<double>("gamma") == 1.4);
  CHECK(p.get<double>("cfl") == 0.25);
  CHECK(p.get<int>("particles") == 1000);
  CHECK(p.get<std::size_t>("particles") == 1000u);
  CHECK(p.get<bool>("periodic"));
  CHECK(p.get<std::string>("output") == "sod#1.h5part");
  CHECK(p.get<std::string>("kernel") == "wendland_c2");
  CHECK(p.get<std::vector<double>>("box") == std::vector<double>{-0.5, 0.5});
  CHECK(p.origin("gamma") == "file sod.par:3");
  CHECK(p.origin("particles") == "file sod.par:4");
  CHECK(p.origin("cfl") == "default");
}

TEST_CASE("booleans, integers, reals and lists accept their usual spellings") {
  auto s = sod_schema();
  const auto value = [&](const std::string& assignment) {
    return parameters::parse(s, "particles = 1", "", {assignment});
  };
  for (const char* yes : {"true", "Yes", "ON", "1"}) CHECK(value(std::string("periodic=") + yes).get<bool>("periodic"));
  for (const char* no : {"false", "no", "Off", "0"})
    CHECK_FALSE(value(std::string("periodic=") + no).get<bool>("periodic"));
  CHECK(value("particles=+42").get<long>("particles") == 42);
  CHECK(value("gamma=2e0").get<double>("gamma") == 2.0);
  CHECK(value("gamma=+1.5").get<double>("gamma") == 1.5);
  CHECK(value("box=[0.25 0.75]").get<std::vector<double>>("box") == std::vector<double>{0.25, 0.75});
  CHECK(value("output=plain text").get<std::string>("output") == "plain text");
}

TEST_CASE("--set overrides are applied after the file, the last one winning") {
  const auto p = parameters::parse(sod_schema(), "gamma = 1.4\nparticles = 10\n", "sod.par",
                                   {"gamma=1.2", "particles = 20", "particles=30"});
  CHECK(p.get<double>("gamma") == 1.2);
  CHECK(p.get<int>("particles") == 30);
  CHECK(p.origin("gamma") == "command line");
}

TEST_CASE("the resolved text lists every key with its origin and reads back to the same values") {
  const auto p =
    parameters::parse(sod_schema(), "gamma = 1.4\nparticles = 10\n", "sod.par", {"cfl=0.1", "output=a b.h5part"});
  const std::string text = p.resolved_text();
  CHECK_THAT(text, Catch::Contains("gamma = 1.4") && Catch::Contains("# file sod.par:1"));
  CHECK_THAT(text, Catch::Contains("cfl = 0.1") && Catch::Contains("# command line"));
  CHECK_THAT(text, Catch::Contains("kernel = \"cubic_spline\"") && Catch::Contains("# default"));
  CHECK_THAT(text, Catch::StartsWith("# resolved parameters (defaults, then sod.par, then the command line)"));

  // Read back as a parameter file, every key keeps its exact value.
  const auto again = parameters::parse(sod_schema(), text, "resolved.par");
  for (const auto& name : sod_schema().names()) {
    CHECK(again.value(name) == p.value(name));
    CHECK(again.origin(name).rfind("file resolved.par:", 0) == 0);
  }
}

TEST_CASE("reals are written with just enough digits to read back exactly") {
  for (double x : {5.0 / 3, 0.1, 1e-300, 123456789.125, -2.5e17}) {
    const std::string text = parameter_declaration::format(x);
    CHECK(std::stod(text) == x);
  }
  CHECK(parameter_declaration::format(0.1) == "0.1");
  CHECK(parameter_declaration::format(std::vector<double>{1, 0.5}) == "1, 0.5");
}

TEST_CASE("the schema's help names every key, its type, default or requirement and constraint") {
  const std::string help = sod_schema().help();
  CHECK_THAT(help, Catch::Contains("gamma (real, default 1.6666666666666667, in [1, 3])"));
  CHECK_THAT(help, Catch::Contains("cfl (real, default 0.25, in (0, 1])"));
  CHECK_THAT(help, Catch::Contains("particles (integer, required, >= 1)"));
  CHECK_THAT(help, Catch::Contains("one of: cubic_spline, wendland_c2, wendland_c4"));
  CHECK_THAT(help, Catch::Contains("box (list of reals, default 0, 1, 2 elements)"));
  CHECK_THAT(help, Catch::Contains("adiabatic index"));
}

TEST_CASE("load reads the file on rank 0 and gives the same values") {
  const std::string path = "unit_parameters_load.par";
  std::ofstream(path) << "particles = 64 # from a file\ngamma = 1.4\n";
  const auto p = parameters::load(sod_schema(), path, {"cfl=0.5"});
  CHECK(p.get<int>("particles") == 64);
  CHECK(p.get<double>("cfl") == 0.5);
  CHECK(p.origin("gamma") == "file " + path + ":2");
  std::remove(path.c_str());
}

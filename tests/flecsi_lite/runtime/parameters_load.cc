// Parameter files at any rank count: rank 0 reads the file and broadcasts its text; every rank
// gets the same values, and the same error for a bad or missing file.
#include <catch2/catch.hpp>

#include "flecsi_lite/runtime/parameters.hh"
#include "tests/support/collective_checks.hh"

#include <fstream>

using flecsi_lite::runtime::parameter_error;
using flecsi_lite::runtime::parameter_schema;
using flecsi_lite::runtime::parameters;
using namespace io_test;

namespace {
parameter_schema schema() {
  parameter_schema s;
  s.real("gamma", "adiabatic index").default_value(1.4).range(1, 3);
  s.integer("particles", "number of particles").at_least(1);
  s.string("output", "output file").default_value("out.h5part");
  return s;
}
}  // namespace

TEST_CASE("every rank resolves the same parameters from the file rank 0 reads") {
  const std::string path = file_name("parameters", ".par"), bad = file_name("parameters_bad", ".par");
  if (rank() == 0) {
    std::ofstream(path) << "# test\nparticles = 128\ngamma = 1.2  # colder\n";
    std::ofstream(bad) << "particles = 128\ngama = 1.2\n";
  }
  barrier();
  const auto p = parameters::load(schema(), path, {"output=run.h5part"});
  CHECK(p.get<int>("particles") == 128);
  CHECK(p.get<double>("gamma") == 1.2);
  CHECK(p.get<std::string>("output") == "run.h5part");
  CHECK(same_on_every_rank(p.resolved_text()));

  std::string message = error_message<parameter_error>([&] { parameters::load(schema(), bad); });
  CHECK(same_on_every_rank(message));
  CHECK_THAT(message, Catch::Contains(bad + ":2: unknown key 'gama'; did you mean 'gamma'?"));

  message = error_message<parameter_error>([&] { parameters::load(schema(), "missing.par"); });
  CHECK(same_on_every_rank(message));
  CHECK_THAT(message, Catch::Contains("cannot read parameter file 'missing.par'"));
}

// Parameters declared once (parameter_block.hh, name_table.hh): the defaults are the struct's own,
// read() fills every member (nested ones too), choice keys take their values, help, did-you-mean
// and resolved names from one name table, file keys read "none" as no file, and block checks run.
#include <catch2/catch.hpp>

#include "flecsi_lite/runtime/name_table.hh"
#include "flecsi_lite/runtime/parameter_block.hh"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

using namespace flecsi_lite::runtime;
using Catch::Contains;

namespace {
enum class shape { sphere, cube, torus };

const name_table<shape>& shape_names() {
  static const name_table<shape> table{"shape",
                                       {{"sphere", shape::sphere}, {"cube", shape::cube}, {"torus", shape::torus}}};
  return table;
}

struct material {
  double density = 2.5;
  struct {
    double gamma = 1.4;
  } gas;
};

// Every kind of key, with defaults that differ from the zero a forgotten default would give.
struct body_settings {
  double radius = 0.75;
  std::int64_t particles = 1000;
  int layers = 3;
  bool rotating = true;
  std::string label = "body";
  std::vector<double> centre{0.5, -0.5};
  shape form = shape::cube;
  material matter;
  std::string output;  // "" : no file
};

parameter_block<body_settings> body_parameters(const body_settings& defaults = {}) {
  parameter_block<body_settings> body(defaults);
  body.real("radius", &body_settings::radius, "radius of the body").greater_than(0);
  body.integer("particles", &body_settings::particles, "number of particles").at_least(1);
  body.integer("layers", &body_settings::layers, "shells of particles").range(1, 10);
  body.boolean("rotating", &body_settings::rotating, "solid-body rotation");
  body.string("label", &body_settings::label, "name in the output");
  body.real_list("centre", &body_settings::centre, "centre of the body").length(2);
  body.choice("shape", &body_settings::form, shape_names(), "shape of the body");
  body.real("density", member(&body_settings::matter, &material::density), "density of the material").greater_than(0);
  body
    .real(
      "gamma", [](body_settings& s) -> double& { return s.matter.gas.gamma; }, "adiabatic index")
    .greater_than(1);
  body.file("output", &body_settings::output, "output file (none: no output)");
  body.check([](const body_settings& s) {
    if (s.form == shape::torus && s.layers < 2) throw parameter_error("a torus needs layers >= 2");
  });
  return body;
}

parameters parse(const parameter_block<body_settings>& block, const std::string& text,
                 const std::vector<std::string>& overrides = {}) {
  parameter_schema schema;
  block.declare(schema);
  return parameters::parse(schema, text, "body.par", overrides);
}
}  // namespace

TEST_CASE("a block's defaults are the struct's default member initializers") {
  const auto block = body_parameters();
  const body_settings d;
  const auto& schema = block.schema();
  CHECK(std::get<double>(*schema.find("radius")->fallback()) == d.radius);
  CHECK(std::get<std::int64_t>(*schema.find("particles")->fallback()) == d.particles);
  CHECK(std::get<std::int64_t>(*schema.find("layers")->fallback()) == d.layers);
  CHECK(std::get<bool>(*schema.find("rotating")->fallback()) == d.rotating);
  CHECK(std::get<std::string>(*schema.find("label")->fallback()) == d.label);
  CHECK(std::get<std::vector<double>>(*schema.find("centre")->fallback()) == d.centre);
  CHECK(std::get<std::string>(*schema.find("shape")->fallback()) == "cube");
  CHECK(std::get<double>(*schema.find("density")->fallback()) == d.matter.density);
  CHECK(std::get<double>(*schema.find("gamma")->fallback()) == d.matter.gas.gamma);
  CHECK(std::get<std::string>(*schema.find("output")->fallback()) == "none");
  // Nothing given: read() gives back exactly the struct's defaults.
  const body_settings read = block.read(parse(block, ""));
  CHECK(read.radius == d.radius);
  CHECK(read.particles == d.particles);
  CHECK(read.form == d.form);
  CHECK(read.matter.gas.gamma == d.matter.gas.gamma);
  CHECK(read.output.empty());
  // Other defaults for one app (as each problem chooses its end time) replace the struct's.
  body_settings other;
  other.radius = 2;
  other.output = "body.h5part";
  const auto custom = body_parameters(other);
  CHECK(std::get<double>(*custom.schema().find("radius")->fallback()) == 2);
  CHECK(custom.read(parse(custom, "")).output == "body.h5part");
}

TEST_CASE("read() fills every member, nested ones included, from the file and --set") {
  const auto block = body_parameters();
  const auto p = parse(block,
                       "radius = 0.25\nparticles = 64\nlayers = 7\nrotating = no\nlabel = \"star\"\n"
                       "centre = 1, 2\nshape = torus\ndensity = 9\n",
                       {"gamma=1.25", "output=star.h5part"});
  const body_settings s = block.read(p);
  CHECK(s.radius == 0.25);
  CHECK(s.particles == 64);
  CHECK(s.layers == 7);
  CHECK_FALSE(s.rotating);
  CHECK(s.label == "star");
  CHECK(s.centre == std::vector<double>{1, 2});
  CHECK(s.form == shape::torus);
  CHECK(s.matter.density == 9);
  CHECK(s.matter.gas.gamma == 1.25);
  CHECK(s.output == "star.h5part");
  // Every key of the block is bound: none is left at its default by this input.
  for (const auto& name : block.schema().names()) CHECK(p.origin(name) != "default");
}

TEST_CASE("a member chain reaches nested members") {
  body_settings s;
  member(&body_settings::matter, &material::density)(s) = 4;
  CHECK(s.matter.density == 4);
}

TEST_CASE("choice keys take their values, help and resolved names from the name table") {
  const auto block = body_parameters();
  CHECK(block.schema().find("shape")->choices() == shape_names().names());
  CHECK_THAT(block.schema().help(), Contains("shape (string, default \"cube\", one of: sphere, cube, torus)"));
  const auto p = parse(block, "shape = sphere\n");
  CHECK(block.read(p).form == shape::sphere);
  CHECK_THAT(p.resolved_text(), Contains("shape = \"sphere\""));
  for (const shape value : shape_names().values()) CHECK(shape_names().value(shape_names().name(value)) == value);
}

TEST_CASE("a misspelled choice is a parameter error naming the choices and the nearest one") {
  const auto block = body_parameters();
  try {
    parse(block, "shape = sphre\n");
    FAIL("no parameter_error");
  } catch (const parameter_error& e) {
    CHECK_THAT(e.what(), Contains("body.par:1: key 'shape'") &&
                           Contains("'sphre' is not one of: sphere, cube, torus") &&
                           Contains("did you mean 'sphere'?"));
  }
  // The table's own lookup says the same, with what the names are of.
  CHECK_THROWS_WITH(shape_names().value("toru"), Contains("unknown shape 'toru'") &&
                                                   Contains("one of: sphere, cube, torus") &&
                                                   Contains("did you mean 'torus'?"));
  CHECK_THROWS_AS(shape_names().value("dodecahedron"), std::invalid_argument);
}

TEST_CASE("bounds, file names and block checks are enforced") {
  const auto block = body_parameters();
  CHECK_THROWS_WITH(parse(block, "layers = 11\n"),
                    Contains("key 'layers'") && Contains("11 is out of range (must be in [1, 10])"));
  CHECK_THROWS_WITH(parse(block, "radius = 0\n"), Contains("0 is out of range (must be > 0)"));
  CHECK(block.read(parse(block, "output = none\n")).output.empty());
  CHECK_THROWS_WITH(block.read(parse(block, "shape = torus\nlayers = 1\n")), Contains("a torus needs layers >= 2"));
  CHECK_NOTHROW(block.read(parse(block, "shape = torus\nlayers = 2\n")));
}

TEST_CASE("mistakes in declaring a block are logic errors") {
  const auto block = body_parameters();
  parameter_schema schema;
  block.declare(schema);
  CHECK_THROWS_AS(block.declare(schema), std::logic_error);  // every key declared twice
  using table = name_table<shape>;
  CHECK_THROWS_AS(table("shape", {{"sphere", shape::sphere}, {"ball", shape::sphere}}), std::logic_error);
  CHECK_THROWS_AS(table("shape", {{"sphere", shape::sphere}, {"sphere", shape::cube}}), std::logic_error);
  const table partial("shape", {{"sphere", shape::sphere}});
  CHECK_THROWS_AS(partial.name(shape::cube), std::logic_error);
}

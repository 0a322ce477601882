// The file keys of the app frame (app/file_settings.hh): their defaults, "none" as no file, and
// the parameter errors of keys that contradict each other.
#include <catch2/catch.hpp>

#include "flecsi_lite/app.hh"

using namespace flecsi_lite;
using Catch::Contains;

namespace {
app::file_settings read(const app::file_settings& defaults, const std::vector<std::string>& overrides) {
  const auto block = app::file_parameters(defaults);
  runtime::parameter_schema schema;
  block.declare(schema);
  return block.read(runtime::parameters::parse(schema, "", "", overrides));
}
}  // namespace

TEST_CASE("the file keys keep an app's defaults and read none as no file") {
  app::file_settings defaults;
  defaults.output_file = "run.h5part";
  const auto files = read(defaults, {});
  CHECK(files.output_file == "run.h5part");
  CHECK(files.checkpoint_file.empty());
  CHECK(files.restart_file.empty());
  CHECK(files.initial_data_step == -1);
  CHECK(read(defaults, {"output_file=none"}).output_file.empty());
  const auto set = read(defaults, {"checkpoint_file=c.h5part", "checkpoint_every=5", "initial_data=i.h5part",
                                   "initial_data_step=2", "output_every=0.5"});
  CHECK(set.checkpoint_file == "c.h5part");
  CHECK(set.checkpoint_every == 5);
  CHECK(set.initial_data == "i.h5part");
  CHECK(set.initial_data_step == 2);
  CHECK(set.output_every == 0.5);
  const std::string help = app::file_parameters(defaults).schema().help();
  for (const char* key : {"output_file", "output_every", "checkpoint_file", "checkpoint_every", "restart_file",
                          "initial_data", "initial_data_step"})
    CHECK_THAT(help, Contains(key));
}

TEST_CASE("contradictory file keys are parameter errors that say what to change") {
  CHECK_THROWS_WITH(read({}, {"restart_file=a.h5part", "initial_data=b.h5part"}),
                    Contains("restart_file and initial_data are both set"));
  CHECK_THROWS_WITH(read({}, {"checkpoint_every=5"}),
                    Contains("checkpoint_every = 5 needs a checkpoint_file (it is none)"));
  CHECK_THROWS_AS(read({}, {"initial_data_step=-2"}), runtime::parameter_error);
}

// main() of the SPH apps (app_main.hh): the framework's app frame with the SPH keys.
#include "specialization/sph/run/app_main.hh"

#include "specialization/sph/files/snapshot_settings.hh"
#include "specialization/sph/model/settings.hh"
#include "specialization/sph/run/statistics.hh"

namespace flecsph::sph {

flecsi_lite::app::definition frame_definition(const app_definition& app) {
  flecsi_lite::app::definition frame;
  frame.program = app.program;
  frame.summary = app.summary;
  frame.declare_parameters = [declare_problem = app.declare_parameters, physics_defaults = app.physics_defaults,
                              run_defaults = app.run_defaults](flecsi_lite::runtime::parameter_schema& schema) {
    if (declare_problem) declare_problem(schema);
    physics_parameters(physics_defaults).declare(schema);
    run_parameters(run_defaults).declare(schema);
    statistics_parameters().declare(schema);
    snapshot_parameters().declare(schema);
  };
  frame.files = app.file_defaults;
  frame.declare_options = app.declare_options;
  frame.checks = app.checks;
  // The statistics file takes part in the frame's rule that a run's files are distinct.
  frame.other_files = [program = app.program](const flecsi_lite::runtime::parameters& p) {
    std::string statistics = statistics_parameters().read(p).file;
    if (statistics == "auto")
      statistics = flecsi_lite::app::beside_output(flecsi_lite::app::file_parameters().read(p).output_file, program,
                                                   ".statistics.txt");
    return std::vector<std::pair<std::string, std::string>>{{"statistics_file", statistics}};
  };
  frame.run = app.run;
  return frame;
}

int app_main(int argc, char** argv, const app_definition& app) {
  return flecsi_lite::app::main(argc, argv, frame_definition(app));
}

}  // namespace flecsph::sph

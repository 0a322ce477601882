// main() of the SPH apps (app.hh).
#include "specialization/sph/app.hh"

#include "flecsi_lite/io.hh"

#include <exception>
#include <iostream>

namespace flecsph::sph {

int app_main(int argc, char** argv, const app_definition& app) {
  using namespace flecsi_lite;
  runtime::options options(app.summary);
  options.positional("parameters", "parameter file (key = value lines); without it, the defaults", false)
    .repeated("set", "KEY=VALUE", "override a parameter (after the file)")
    .flag("parameters-help", "list every parameter key and exit");
  if (app.declare_options) app.declare_options(options);
  runtime::runtime rt(argc, argv, options);
  if (!rt.proceed()) return rt.exit_code();
  runtime::parameter_schema schema;
  app.declare_parameters(schema);
  if (rt.opts().has("parameters-help")) {
    if (runtime::rank() == 0) std::cout << schema.help();
    return 0;
  }
  try {
    const auto p = runtime::parameters::load(schema, rt.opts().get("parameters"), rt.opts().all("set"));
    return app.run(p, rt.opts());
  } catch (const runtime::parameter_error& e) {
    log::error() << e.what();
    return 2;
  } catch (const io::io_error& e) {
    // The ranks agreed on this error (the same on every rank): one report is enough.
    if (runtime::rank() == 0) log::error() << app.program << ": " << e.what();
    return 3;
  } catch (const std::exception& e) {
    log::error() << app.program << ": " << e.what();
    return 3;
  }
}

} // namespace flecsph::sph

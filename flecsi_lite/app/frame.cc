// The app frame's main() (frame.hh): options, parameters, the run, and errors as exit statuses.
#include "flecsi_lite/app/frame.hh"

#include "flecsi_lite/io/io_error.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/runtime/log.hh"

#include <exception>
#include <iostream>

namespace flecsi_lite::app {

runtime::parameter_schema schema_of(const definition& app) {
  runtime::parameter_schema schema;
  if (app.declare_parameters) app.declare_parameters(schema);
  if (app.files) file_parameters(*app.files).declare(schema);
  return schema;
}

namespace {
/// Every option that sets a key, as the --set overrides it stands for, then the --set ones.
std::vector<std::string> overrides_of(const definition& app, const runtime::options& options) {
  std::vector<std::string> overrides;
  for (const auto& shortcut : app.option_keys)
    for (const auto& value : options.all(shortcut.option)) overrides.push_back(shortcut.key + "=" + value);
  for (const auto& assignment : options.all("set")) overrides.push_back(assignment);
  return overrides;
}
} // namespace

int main(int argc, char** argv, const definition& app) {
  // The schema needs no runtime: its keys give the help of the options that set them.
  const runtime::parameter_schema schema = schema_of(app);
  runtime::options options(app.summary);
  options.positional("parameters", "parameter file (key = value lines); without it, the defaults", false)
    .repeated("set", "KEY=VALUE", "override a parameter (after the file)")
    .flag("parameters-help", "list every parameter key and exit");
  for (const auto& shortcut : app.option_keys) {
    const runtime::parameter_declaration* key = schema.find(shortcut.key);
    if (!key) throw std::logic_error(app.program + ": option --" + shortcut.option + " sets no declared key '" +
                                     shortcut.key + "'");
    options.value(shortcut.option, "VALUE", key->description() + " (sets " + shortcut.key + ")",
                  key->required() ? "" : runtime::parameter_declaration::format(*key->fallback()));
  }
  if (app.declare_options) app.declare_options(options);

  runtime::runtime rt(argc, argv, options);
  if (!rt.proceed()) return rt.exit_code();
  if (rt.opts().has("parameters-help")) {
    if (runtime::rank() == 0) std::cout << schema.help();
    return 0;
  }
  try {
    const auto p = runtime::parameters::load(schema, rt.opts().get("parameters"), overrides_of(app, rt.opts()));
    return app.run(run_context(app, p, rt.opts()));
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

} // namespace flecsi_lite::app

// The app frame's main() (frame.hh): options, parameters, the start-up banner, the
// used-parameters file, the run, and errors as exit statuses.
#include "flecsi_lite/app/frame.hh"

#include "flecsi_lite/app/parameter_changes.hh"
#include "flecsi_lite/app/run_limits.hh"

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/io/collective_agreement.hh"
#include "flecsi_lite/io/io_error.hh"
#include "flecsi_lite/io/output_path.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/runtime/log.hh"

#include <exception>
#include <filesystem>
#include <iostream>
#include <sstream>

// Set by the top-level CMakeLists.txt on this file only, so that a new commit recompiles nothing else.
#ifndef FLECSPH_VERSION
#define FLECSPH_VERSION "unknown"
#endif
#ifndef FLECSPH_GIT_DESCRIBE
#define FLECSPH_GIT_DESCRIBE "unknown"
#endif

namespace flecsi_lite::app {

const char* version() { return FLECSPH_VERSION; }
const char* git_describe() { return FLECSPH_GIT_DESCRIBE; }

std::string beside_output(const std::string& output_file, const std::string& program, const std::string& suffix) {
  if (output_file.empty()) return program + suffix;
  return std::filesystem::path(output_file).replace_extension().string() + suffix;
}

void check_distinct_file(const std::string& key, const std::string& path,
                         const std::vector<std::pair<std::string, std::string>>& others) {
  for (const auto& [other_key, other] : others)
    if (names_same_file(path, other))
      throw runtime::parameter_error(key + " '" + path + "' is also " + other_key + ": set " + key +
                                     " to another name (or none)");
}

namespace {
/// The frame's own key, "auto" standing for `<output stem>.used.par`.
struct frame_files {
  std::string used_parameters_file = "auto";
};

runtime::parameter_block<frame_files> frame_file_parameters() {
  runtime::parameter_block<frame_files> block;
  block.file("used_parameters_file", &frame_files::used_parameters_file,
             "every key of this run with its value, a complete rerun file (auto: <output stem>.used.par)");
  return block;
}
}  // namespace

std::string used_parameters_file(const std::string& program, const runtime::parameters& p) {
  const std::string path = frame_file_parameters().read(p).used_parameters_file;
  if (path != "auto") return path;
  const file_settings files = file_parameters().read(p);
  return files.output_file.empty() ? "" : beside_output(files.output_file, program, ".used.par");
}

runtime::parameter_schema schema_of(const definition& app) {
  runtime::parameter_schema schema;
  if (app.declare_parameters) app.declare_parameters(schema);
  if (app.files) {
    file_parameters(*app.files).declare(schema);
    frame_file_parameters().declare(schema);
    run_limit_parameters().declare(schema);
    restart_parameters().declare(schema);
  }
  return schema;
}

namespace {
/// Rank 0: program, version, commit, ranks and threads, before anything runs.
void print_banner(const definition& app) {
  log::info() << app.program << " " << version() << " (git " << git_describe() << "): " << runtime::size()
              << " MPI ranks x " << concurrency() << " threads per rank";
}

/// Where the used parameters go ("" for nowhere); a path that another file key names too is a
/// parameter error, since one of the two files would overwrite the other.
std::string used_parameters_path(const definition& app, const runtime::parameters& p) {
  const file_settings files = file_parameters(*app.files).read(p);
  const std::string path = used_parameters_file(app.program, p);
  check_distinct_file("used_parameters_file", path,
                      {{"output_file", files.output_file},
                       {"checkpoint_file", files.checkpoint_file},
                       {"restart_file", files.restart_file},
                       {"initial_data", files.initial_data}});
  return path;
}

/// The stop file is removed when found: it must not be one of the run's files.
void check_stop_file(const definition& app, const runtime::parameters& p) {
  const file_settings files = file_parameters(*app.files).read(p);
  check_distinct_file("stop_file", resolved_stop_file(run_limit_parameters().read(p), files.output_file, app.program),
                      {{"output_file", files.output_file},
                       {"checkpoint_file", files.checkpoint_file},
                       {"restart_file", files.restart_file},
                       {"initial_data", files.initial_data},
                       {"used_parameters_file", used_parameters_file(app.program, p)}});
}

/// Rank 0 writes the file (io::write_text_file: never over anything but a regular file); every
/// rank throws the same io_error when that fails. Collective.
void write_used_parameters(const definition& app, const std::string& path, const runtime::parameters& p) {
  io::agree(runtime::communicator(), [&] {
    if (runtime::rank() != 0) return;
    std::ostringstream text;
    text << "# " << app.program << " " << version() << " (git " << git_describe()
         << "): every parameter of a run, defaults included; rerun with `" << app.program << " " << path << "`\n"
         << p.resolved_text();
    io::write_text_file(path, text.str(), "used_parameters_file");
  });
  log::info() << app.program << ": parameters of this run in " << path;
}

/// Every option that sets a key, as the --set overrides it stands for, then the --set ones.
std::vector<std::string> overrides_of(const definition& app, const runtime::options& options) {
  std::vector<std::string> overrides;
  for (const auto& shortcut : app.option_keys)
    for (const auto& value : options.all(shortcut.option)) overrides.push_back(shortcut.key + "=" + value);
  for (const auto& assignment : options.all("set")) overrides.push_back(assignment);
  return overrides;
}
}  // namespace

int main(int argc, char** argv, const definition& app) {
  // The schema needs no runtime: its keys give the help of the options that set them.
  const runtime::parameter_schema schema = schema_of(app);
  runtime::options options(app.summary);
  options.positional("parameters", "parameter file (key = value lines); without it, the defaults", false)
    .repeated("set", "KEY=VALUE", "override a parameter (after the file)")
    .flag("parameters-help", "list every parameter key and exit");
  for (const auto& shortcut : app.option_keys) {
    const runtime::parameter_declaration* key = schema.find(shortcut.key);
    if (!key)
      throw std::logic_error(app.program + ": option --" + shortcut.option + " sets no declared key '" + shortcut.key +
                             "'");
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
    print_banner(app);
    if (app.files) check_stop_file(app, p);
    if (app.files && !run_context::control_model_only())
      if (const std::string path = used_parameters_path(app, p); !path.empty()) write_used_parameters(app, path, p);
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

}  // namespace flecsi_lite::app

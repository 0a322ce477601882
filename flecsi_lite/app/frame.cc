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

#include <algorithm>
#include <cctype>
#include <exception>
#include <filesystem>
#include <fstream>
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
      throw runtime::parameter_error(key + " '" + path + "' is also " + other_key + " '" + other + "': set " + key +
                                     " to another name (or none)");
}

void require_distinct_files(const std::vector<named_path>& files) {
  std::vector<std::pair<std::string, std::string>> earlier;
  for (const auto& file : files) {
    std::vector<std::pair<std::string, std::string>> others;
    for (const auto& [key, path] : earlier)
      // A run continued in chunks writes its checkpoint over the one it started from, atomically.
      if (!(file.key == "checkpoint_file" && key == "restart_file") &&
          !(file.key == "restart_file" && key == "checkpoint_file"))
        others.emplace_back(key, path);
    check_distinct_file(file.key, file.path, others);
    earlier.emplace_back(file.key, file.path);
  }
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

/// The text of the used-parameters file of a run of `app` with `p`.
std::string used_parameters_text(const definition& app, const std::string& path, const runtime::parameters& p) {
  std::ostringstream text;
  text << "# " << app.program << " " << version() << " (git " << git_describe()
       << "): every parameter of a run, defaults included; rerun with `" << app.program << " " << path << "`\n"
       << p.resolved_text();
  return text.str();
}

/// The assignments of a parameter text, without comments, blanks and empty lines.
std::vector<std::string> assignments_of(std::istream& text) {
  std::vector<std::string> lines;
  for (std::string line; std::getline(text, line);) {
    line = line.substr(0, line.find('#'));
    line.erase(std::remove_if(line.begin(), line.end(), [](unsigned char c) { return std::isspace(c); }), line.end());
    if (!line.empty()) lines.push_back(line);
  }
  return lines;
}

/// Where the used parameters go ("" for nowhere). The rerun of a used-parameters file
/// (`sod sod.used.par`) names it as both the parameter file and its own used-parameters file:
/// it is left as it is when it holds this run's parameters already, else that is refused.
std::string used_parameters_path(const definition& app, const runtime::parameters& p,
                                 const std::string& parameter_file) {
  const std::string path = used_parameters_file(app.program, p);
  if (path.empty() || !names_same_file(path, parameter_file)) return path;
  std::ifstream in(parameter_file);
  std::istringstream resolved(p.resolved_text());
  if (assignments_of(in) == assignments_of(resolved)) return "";
  throw runtime::parameter_error("used_parameters_file '" + path + "' is also the parameter file '" + parameter_file +
                                 "', and this run's parameters are not the ones it holds: writing them would change "
                                 "the parameter file; set used_parameters_file to another name (or none)");
}

/// Every file the run reads or writes, in the order whose later key require_distinct_files names
/// first: the parameter file, the file keys, the used-parameters file, the app's, the stop file
/// (removed when found) and the --trace file.
std::vector<named_path> run_files(const definition& app, const runtime::parameters& p,
                                  const runtime::options& options) {
  std::vector<named_path> files{{"the parameter file", options.get("parameters")}};
  if (app.files) {
    const file_settings keys = file_parameters(*app.files).read(p);
    files.insert(files.end(), std::initializer_list<named_path>{
                                {"output_file", keys.output_file},
                                {"checkpoint_file", keys.checkpoint_file},
                                {"restart_file", keys.restart_file},
                                {"initial_data", keys.initial_data},
                                {"used_parameters_file", used_parameters_path(app, p, files.front().path)}});
  }
  if (app.other_files)
    for (const auto& [key, path] : app.other_files(p)) files.push_back({key, path});
  if (app.files) {
    const file_settings keys = file_parameters(*app.files).read(p);
    files.push_back({"stop_file", resolved_stop_file(run_limit_parameters().read(p), keys.output_file, app.program)});
  }
  files.push_back({"--trace", options.get("trace")});
  return files;
}

/// The stop file is removed when found, so it may be nothing but a regular file (or absent).
void check_stop_file(const definition& app, const runtime::parameters& p) {
  const file_settings files = file_parameters(*app.files).read(p);
  const std::string path = resolved_stop_file(run_limit_parameters().read(p), files.output_file, app.program);
  if (const std::string kind = path.empty() ? "" : io::non_regular_kind(path); !kind.empty())
    throw runtime::parameter_error("stop_file = '" + path + "' is " + kind +
                                   ", not a regular file: the run removes the stop file it finds; choose another path");
}

/// Rank 0 writes the file aside as `<path>.partial` (io::write_text_file_aside: never over
/// anything but a regular file); every rank throws the same io_error when that fails. Collective.
void write_used_parameters(const definition& app, const std::string& path, const runtime::parameters& p) {
  io::agree(runtime::communicator(), [&] {
    if (runtime::rank() != 0) return;
    io::write_text_file_aside(path, used_parameters_text(app, path, p), "used_parameters_file");
  });
}

/// Once the run succeeded: the used-parameters file replaces an earlier one. Collective.
void commit_used_parameters(const definition& app, const std::string& path) {
  io::agree(runtime::communicator(), [&] {
    if (runtime::rank() == 0) io::commit_text_file(path, "used_parameters_file");
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
  declare_checks(app.checks, options);

  runtime::runtime rt(argc, argv, options);
  if (!rt.proceed()) return rt.exit_code();
  if (rt.opts().has("parameters-help")) {
    if (runtime::rank() == 0) std::cout << schema.help();
    return 0;
  }
  try {
    const check_values checks = parse_checks(app.checks, rt.opts());
    const auto p = runtime::parameters::load(schema, rt.opts().get("parameters"), overrides_of(app, rt.opts()));
    require_distinct_files(run_files(app, p, rt.opts()));
    print_banner(app);
    std::string used_parameters;
    if (app.files) {
      check_stop_file(app, p);
      if (!run_context::control_model_only())
        used_parameters = used_parameters_path(app, p, rt.opts().get("parameters"));
    }
    if (!used_parameters.empty()) write_used_parameters(app, used_parameters, p);
    const int status = app.run(run_context(app, p, rt.opts(), checks));
    if (status == 0 && !used_parameters.empty()) commit_used_parameters(app, used_parameters);
    return status;
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

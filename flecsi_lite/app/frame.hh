// The app frame: main() of every flecsi_lite program that takes parameters. It declares the
// options (a parameter file, --set KEY=VALUE, --parameters-help, options that set keys, the app's
// own), loads the parameters on every rank, runs, and turns errors into exit statuses.
//
//   app::definition heat;
//   heat.program = "heat";
//   heat.declare_parameters = [](runtime::parameter_schema& s) { heat_parameters().declare(s); };
//   heat.run = [](const app::run_context& run) {
//     simulation s{heat_parameters().read(run.parameters())};
//     return run.execute(make_control_model(), s, [](const simulation& s) { return s.passed ? 0 : 1; });
//   };
//   int main(int argc, char** argv) { return app::main(argc, argv, heat); }
//
// At start-up, before anything runs, the app's checks are parsed (check_options.hh) and every
// file the run reads or writes (the parameter file, the file keys, the used-parameters and stop
// files, --trace, the app's own) must be a different file (require_distinct_files); rank 0 prints
// a banner (program, version, git commit, ranks, threads per rank), and apps with files write the
// used-parameters file: every key with its value, defaults included, a complete rerun file (key
// used_parameters_file; "auto": `<output stem>.used.par`), as `<file>.partial`, renamed over
// `<file>` only when the run succeeds (exit status 0), so that a failed run never replaces it.
//
// Exit statuses: 0 the run (or --help, --parameters-help, --control-model); 1 a check of the app
// failed; 2 bad options or parameters; 3 any other error (a bad file, an impossible value), each
// reported on rank 0 with what was wrong.
#pragma once

#include "flecsi_lite/app/check_options.hh"
#include "flecsi_lite/app/file_settings.hh"
#include "flecsi_lite/control/control_model.hh"
#include "flecsi_lite/runtime/options.hh"
#include "flecsi_lite/runtime/parameters.hh"
#include "flecsi_lite/runtime/runtime.hh"

#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace flecsi_lite::app {

/// A command-line option that sets a parameter key: with {"time", "end_time"}, `--time 0.1` is
/// `--set end_time=0.1` (applied before the --set overrides, which win).
struct option_key {
  std::string option;
  std::string key;
};

class run_context;

/// What an app gives the frame.
struct definition {
  std::string program;  ///< the app's name, in messages
  std::string summary;  ///< first line of --help
  /// The app's keys (see runtime::parameter_block).
  std::function<void(runtime::parameter_schema&)> declare_parameters;
  /// With a value, the file keys (file_settings.hh) are declared after the app's, with these defaults.
  std::optional<file_settings> files;
  std::vector<option_key> option_keys;
  /// The app's own options, besides the frame's, the runtime's and the checks.
  std::function<void(runtime::options&)> declare_options;
  /// The app's checks (check_options.hh), parsed before the run: run_context::checks().
  std::vector<check_option> checks;
  /// The files the app reads or writes besides the frame's, as (key, path; empty: none), from
  /// the loaded parameters: they take part in require_distinct_files.
  std::function<std::vector<std::pair<std::string, std::string>>(const runtime::parameters&)> other_files;
  /// The run, once the parameters are loaded; returns the exit status.
  std::function<int(const run_context&)> run;
};

/// What a run sees: the resolved parameters and the options.
class run_context {
 public:
  run_context(const definition& app, const runtime::parameters& parameters, const runtime::options& options,
              const check_values& checks = {})
      : app_(app), parameters_(parameters), options_(options), checks_(checks) {}

  const std::string& program() const { return app_.program; }
  const runtime::parameters& parameters() const { return parameters_; }
  const runtime::options& options() const { return options_; }
  /// The app's checks given on the command line, parsed at start-up.
  const check_values& checks() const { return checks_; }

  /// True under --control-model: the model is written, nothing runs and nothing is checked.
  static bool control_model_only() { return !runtime::current_settings().control_model_file.empty(); }

  /// Runs `model` on `state` and returns `check(state)`, the exit status of the app's checks;
  /// under --control-model, writes the model (on rank 0) and returns 0 without running or checking.
  /// A state with a member commit_outputs() writes its outputs under temporary names: it is called
  /// only once the run and the checks have passed, so that a failed run never replaces an earlier
  /// output.
  template<class State, class Check>
  int execute(const control::control_model<State>& model, State& state, Check&& check) const {
    const int status = model.execute(state);
    if (status || control_model_only()) return status;
    const int verdict = check(static_cast<const State&>(state));
    if (verdict == 0) commit_outputs(state);
    return verdict;
  }
  template<class State>
  int execute(const control::control_model<State>& model, State& state) const {
    const int status = model.execute(state);
    if (status == 0) commit_outputs(state);
    return status;
  }

 private:
  template<class State, class = void>
  struct has_commit_outputs : std::false_type {};
  template<class State>
  struct has_commit_outputs<State, std::void_t<decltype(std::declval<State&>().commit_outputs())>> : std::true_type {};
  template<class State>
  static void commit_outputs(State& state) {
    if constexpr (has_commit_outputs<State>::value) state.commit_outputs();
  }

  const definition& app_;
  const runtime::parameters& parameters_;
  const runtime::options& options_;
  check_values checks_;
};

/// The version of this build (PROJECT_VERSION) and its commit, as `git describe --always --dirty`
/// gave it at configure time ("unknown" outside a git checkout).
const char* version();
const char* git_describe();

/// A file that goes with the output: `<output stem><suffix>` (sod.h5part, ".used.par":
/// sod.used.par), or `<program><suffix>` when there is no output (`output_file` empty).
std::string beside_output(const std::string& output_file, const std::string& program, const std::string& suffix);

/// The used-parameters file of a run of `program` with `p` (keys of an app with files):
/// used_parameters_file with "auto" resolved; empty: none.
std::string used_parameters_file(const std::string& program, const runtime::parameters& p);

/// Throws parameter_error when `path`, the value of `key`, names the same file as one of `others`
/// (key and value; an empty value is none; file_settings.hh names_same_file): one of two files
/// with one name would be lost.
void check_distinct_file(const std::string& key, const std::string& path,
                         const std::vector<std::pair<std::string, std::string>>& others);

/// One file of a run under the key (or option) that names it: "output_file", "--trace", ...
struct named_path {
  std::string key;
  std::string path;  ///< empty: none
};

/// Every file a run reads or writes, in the order of `files`: throws parameter_error naming both
/// keys (check_distinct_file's message, the later key first) when two of them are one file
/// (names_same_file: also through links, or one the other's `.partial`). checkpoint_file may be
/// restart_file (a checkpoint replaces the one it continues only once complete).
void require_distinct_files(const std::vector<named_path>& files);

/// The schema of `app`: its keys, then the file keys and used_parameters_file when it has files.
runtime::parameter_schema schema_of(const definition& app);

/// Starts the runtime, parses the options, loads the parameters and runs `app` (see the exit
/// statuses above). Collective.
int main(int argc, char** argv, const definition& app);

}  // namespace flecsi_lite::app

// The runtime of a flecsi_lite program (runtime.hh): MPI and Kokkos start-up and shut-down, the
// standard options, and the checks of what they name (a --trace file that cannot be written).
#include "flecsi_lite/runtime/runtime.hh"

#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/runtime/job_memory.hh"
#include "flecsi_lite/runtime/log.hh"
#include "flecsi_lite/runtime/thread_share.hh"
#include "flecsi_lite/runtime/timers.hh"

#include <Kokkos_Core.hpp>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <vector>

namespace flecsi_lite::runtime {
namespace {
settings global_settings;
MPI_Comm framework_comm = MPI_COMM_NULL;
std::vector<std::function<void()>> finalizers;

/// Why rank 0 could not write `path` ("" when it can): the trace is written only at the end, so
/// the check opens the file now (without truncating an existing one, and removing one it created).
std::string unwritable_reason(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return "it is a directory";
  const auto status = std::filesystem::symlink_status(path, error);
  // Opening a fifo would wait for a reader for ever; a link or a device is never replaced.
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    return "it exists and is not a regular file (a link, fifo, device or socket): it is never replaced";
  const bool existed = std::filesystem::exists(status);
  std::ofstream out(path, std::ios::app);
  if (!out) return std::strerror(errno);
  out.close();
  if (!existed) std::filesystem::remove(path, error);
  return "";
}

/// The same verdict on every rank: rank 0 checks, the others receive its reason.
std::string trace_problem(const std::string& path) {
  std::string reason;
  if (rank() == 0) reason = unwritable_reason(path);
  int length = static_cast<int>(reason.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, communicator());
  reason.resize(static_cast<std::size_t>(length));
  MPI_Bcast(reason.data(), length, MPI_CHAR, 0, communicator());
  return reason;
}
}  // namespace

const settings& current_settings() { return global_settings; }

void at_finalize(std::function<void()> action) { finalizers.push_back(std::move(action)); }

runtime::runtime(int& argc, char**& argv, options program_options) : options_(std::move(program_options)) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_dup(MPI_COMM_WORLD, &framework_comm);
  detail::set_communicator(framework_comm);
  // Thread binding stays off unless the user asks (Kokkos warns when the variable is unset).
  setenv("OMP_PROC_BIND", "false", 0);
  // Kokkos prints its ~40 lines of options for --help too: it sees --help only as --help-kokkos
  // (passed as --kokkos-help), ours stays for our options. It removes the --kokkos-* arguments
  // it recognizes and keeps the order of the others.
  static char kokkos_help[] = "--kokkos-help", hidden_help[] = "--flecsi-lite-help";
  bool kokkos_help_asked = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") == 0)
      argv[i] = hidden_help;
    else if (std::strcmp(argv[i], "--help-kokkos") == 0 || std::strcmp(argv[i], "--kokkos-help") == 0) {
      argv[i] = kokkos_help;
      kokkos_help_asked = true;
    }
  }
  // Each rank's share of its node's cores unless the user chose; both spellings of the option.
  const std::string thread_error = detail::prepare_kokkos_threads(argc, argv);
  Kokkos::initialize(argc, argv);
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], hidden_help) == 0) argv[i] = const_cast<char*>("--help");  // argv was copied

  std::string program = argc > 0 ? argv[0] : "program";
  global_settings.program = program.substr(program.find_last_of('/') + 1);
  options_.flag("help", "print this help and exit")
    .flag("help-kokkos", "print the options of Kokkos (--kokkos-num-threads=N, ...) and exit")
    .flag("control-model", "write the control model as a Graphviz file <program>-control-model.dot and exit")
    .flag("log-all-ranks", "every rank logs, each line prefixed by its rank (default: rank 0 only)")
    .value("trace", "FILE", "record every task launch, ghost copy and reduction of the executor to FILE")
    .flag("no-timers", "do not print the timer summary at exit");
  if (!thread_error.empty()) {
    if (rank() == 0) std::cerr << global_settings.program << ": " << thread_error << "\n";
    exit_code_ = 2;
    return;
  }
  if (kokkos_help_asked) {  // Kokkos printed its options
    exit_code_ = 0;
    return;
  }
  try {
    options_.parse(argc, argv);
  } catch (const options_error& e) {
    if (rank() == 0) std::cerr << global_settings.program << ": " << e.what() << "\n";
    exit_code_ = 2;
    return;
  }
  if (options_.has("help")) {
    if (rank() == 0) std::cout << options_.help(global_settings.program);
    exit_code_ = 0;
    return;
  }
  log::set_all_ranks(options_.has("log-all-ranks"));
  detail::warn_if_oversubscribed(communicator());
  global_settings.job_memory = detect_job_memory(communicator());
  if (options_.has("control-model"))
    global_settings.control_model_file = global_settings.program + "-control-model.dot";
  global_settings.trace_file = options_.get("trace");
  if (!global_settings.trace_file.empty()) {
    if (const auto reason = trace_problem(global_settings.trace_file); !reason.empty()) {
      if (rank() == 0)
        std::cerr << global_settings.program << ": cannot write the --trace file '" << global_settings.trace_file
                  << "': " << reason << "\n";
      exit_code_ = 2;
      return;
    }
  }
  global_settings.timers = !options_.has("no-timers");
}

runtime::~runtime() {
  for (auto it = finalizers.rbegin(); it != finalizers.rend(); ++it) (*it)();
  finalizers.clear();
  if (proceed() && global_settings.timers) timers::report(std::cout);
  Kokkos::finalize();
  detail::set_communicator(MPI_COMM_NULL);
  MPI_Comm_free(&framework_comm);
  MPI_Finalize();
}

}  // namespace flecsi_lite::runtime

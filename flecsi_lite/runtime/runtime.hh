// The runtime of a flecsi_lite program: initializes MPI then Kokkos, parses the command line,
// and at the end prints the timer summary and finalizes Kokkos then MPI.
//
//   int main(int argc, char** argv) {
//     flecsi_lite::runtime::runtime rt(argc, argv, my_options);
//     if (!rt.proceed()) return rt.exit_code();   // --help, or a bad option
//     ...
//   }
#pragma once

#include "flecsi_lite/runtime/options.hh"

#include <functional>
#include <limits>
#include <string>

namespace flecsi_lite::runtime {

/// Settings every flecsi_lite program understands (see runtime::standard_options).
struct settings {
  std::string program;             // argv[0] without directories
  std::string control_model_file;  // non-empty: write the control model as Graphviz and stop
  std::string trace_file;          // non-empty: the executor records a trace there
  bool timers = true;              // print the timer summary at exit
  // Bytes all ranks may allocate together (detect_job_memory, job_memory.hh); +inf until the
  // runtime has started.
  double job_memory = std::numeric_limits<double>::infinity();
};
const settings& current_settings();

/// Registers work to do when the runtime ends, before Kokkos and MPI finalize (last first).
void at_finalize(std::function<void()> action);

class runtime {
 public:
  runtime(int& argc, char**& argv, options program_options = options{});
  runtime(const runtime&) = delete;
  runtime& operator=(const runtime&) = delete;
  ~runtime();

  /// False after --help, a bad option or a --trace file that cannot be written (exit status 2):
  /// main should return exit_code().
  bool proceed() const { return exit_code_ < 0; }
  int exit_code() const { return exit_code_ < 0 ? 0 : exit_code_; }
  const options& opts() const { return options_; }

 private:
  options options_;
  int exit_code_ = -1;
};

}  // namespace flecsi_lite::runtime

// The files a run reads and writes, as parameter keys every app of the frame shares (frame.hh):
// output, checkpoints, restart and initial data, with the checks of keys that contradict.
#pragma once

#include "flecsi_lite/runtime/parameter_block.hh"

#include <string>

namespace flecsi_lite::app {

/// An empty file name is "none" (in a parameter file: `output_file = none`).
struct file_settings {
  std::string output_file;      ///< H5Part output
  double output_every = 0;      ///< simulation time between outputs; 0: first and last step only
  std::string checkpoint_file;  ///< replaced at each checkpoint, and written when a run stops early
  long checkpoint_every = 0;    ///< steps between checkpoints; 0: none
  std::string restart_file;     ///< continue the run of this checkpoint
  std::string initial_data;     ///< H5Part file or SWIFT-format initial conditions of the initial particles
  long initial_data_step = -1;  ///< its Step#k; -1: the last
};

/// The keys output_file, output_every, checkpoint_file, checkpoint_every, restart_file,
/// initial_data and initial_data_step with `defaults`; read() rejects (parameter_error, naming the
/// keys) restart_file with initial_data; checkpoint_every without a checkpoint_file; an output or
/// checkpoint path (written also when a run stops early) that exists and is not a regular file,
/// or whose folder is missing or not
/// writable; output_file equal to checkpoint_file, restart_file or initial_data, and
/// checkpoint_file equal to initial_data (compared as resolved paths). checkpoint_file may equal
/// restart_file: a new checkpoint replaces the one it continues from atomically.
runtime::parameter_block<file_settings> file_parameters(const file_settings& defaults = {});

/// Whether two non-empty paths name one file, or one names the other's temporary `<path>.partial`
/// (compared as resolved paths: "./a.h5part" and "a.h5part" are one file; two existing names
/// of one file, hard links included, are one file): writing one would replace or corrupt the
/// other. Every collision check of the frame's file keys uses it.
bool names_same_file(const std::string& a, const std::string& b);

}  // namespace flecsi_lite::app

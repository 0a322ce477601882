// h5part_to_ascii: exports one step of an H5Part file to the ASCII columns splash reads
// (`splash -f ascii`; Debian's splash 3.6 cannot read H5Part itself).
//
//   h5part_to_ascii run.h5part > last.dat              # last step, default columns
//   h5part_to_ascii --step 12 --columns x,rho,P run.h5part --output step12.dat
//   h5part_to_ascii --list run.h5part                  # steps, times and datasets
#include "flecsi_lite/app.hh"
#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <mpi.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace {
using namespace flecsi_lite;

// Splash's usual first columns, then the rest of an SPH dump.
const std::vector<std::string> default_columns{"x", "y", "z", "vx", "vy", "vz", "m", "rho", "P", "u", "h", "id"};

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

std::int64_t parse_step(const std::string& text, const io::h5part_reader& reader) {
  if (text.empty() || text == "last") return reader.last_step();
  std::size_t used = 0;
  long long step = -1;
  try {
    step = std::stoll(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || step < 0)
    throw runtime::options_error("--step takes a step index k of Step#k or 'last', not '" + text + "'");
  return step;
}

void list_contents(const io::h5part_reader& reader, std::int64_t step, std::ostream& out) {
  out << reader.path() << ": " << reader.steps().size() << " steps\n";
  for (const auto k : reader.steps()) {
    const auto info = reader.step_information(k);
    out << "  Step#" << k << "  time " << info.time << "  iteration " << info.step << "  particles "
        << reader.particle_count(k) << '\n';
  }
  out << "datasets of Step#" << step << ':';
  for (const auto& name : reader.datasets(step))
    out << ' ' << name << " (" << io::element_type_name(reader.dataset_type(step, name)) << ')';
  out << '\n';
}

int run(int argc, char** argv) {
  runtime::options options("Exports one step of an H5Part file as ASCII columns for splash -f ascii.");
  options.flag("help", "print this help and exit")
    .value("step", "K", "the step to export: index k of Step#k, or 'last'", "last")
    .value("columns", "A,B,...",
           "comma-separated datasets to export (default: those of x y z vx vy "
           "vz m rho P u h id present, else all)")
    .value("output", "FILE", "write to FILE instead of standard output")
    .flag("list", "list the steps, their times and the datasets of the step, and exit")
    .positional("file", "the H5Part file");
  try {
    options.parse(argc, argv);
  } catch (const runtime::options_error& e) {
    std::cerr << "h5part_to_ascii: " << e.what() << '\n';
    return 2;
  }
  if (options.has("help")) {
    std::cout << options.help("h5part_to_ascii");
    return 0;
  }
  // The export never replaces its own input (also through a link or its temporary name).
  if (options.has("output") && app::names_same_file(options.get("output"), options.get("file"))) {
    std::cerr << "h5part_to_ascii: --output '" << options.get("output") << "' is the input file '"
              << options.get("file") << "': it would be replaced by its text; give another --output\n";
    return 2;
  }
  try {
    io::h5part_reader reader(options.get("file"), MPI_COMM_SELF);
    const std::int64_t step = parse_step(options.get("step"), reader);
    if (options.has("list")) {
      list_contents(reader, step, std::cout);
      return 0;
    }
    // Before anything is read or written: the export replaces only a regular file (never a device,
    // folder, link or fifo), through a temporary file that must not be one either.
    if (options.has("output")) {
      io::require_replaceable(options.get("output"), "--output");
      io::require_replaceable(options.get("output") + ".partial", "temporary file");
      io::require_writable_folder(options.get("output"), "--output");
    }
    const auto columns = options.has("columns") ? split_list(options.get("columns"))
                                                : io::available_columns(reader, step, default_columns);
    if (!options.has("output")) {
      io::write_ascii_columns(reader, step, columns, std::cout);
      return 0;
    }
    // Written to a temporary name first, so that a failure leaves no half-written file.
    const std::string output = options.get("output"), partial = output + ".partial";
    try {
      std::ofstream out(partial);
      if (!out) throw std::runtime_error("cannot write '" + partial + "'");
      io::write_ascii_columns(reader, step, columns, out);
      if (!out.flush()) throw std::runtime_error("cannot write '" + partial + "'");
    } catch (...) {
      std::remove(partial.c_str());
      throw;
    }
    if (std::rename(partial.c_str(), output.c_str()) != 0)
      throw std::runtime_error("cannot rename '" + partial + "' to '" + output + "'");
    return 0;
  } catch (const runtime::options_error& e) {
    std::cerr << "h5part_to_ascii: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "h5part_to_ascii: " << e.what() << '\n';
    return 1;
  }
}
}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, status = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) status = run(argc, argv);  // a serial tool: other ranks, if any, wait
  MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
  MPI_Finalize();
  return status;
}

// Output safety of the H5Part writer: the final name appears only at close (the partial file
// before), every finished step is on disk while the run goes on, and a run that stops without
// closing (writer destroyed, or an exception mid-step) never harms a complete file of that name.
#include <catch2/catch.hpp>

#include "flecsi_lite/io/h5part_reader.hh"
#include "flecsi_lite/io/h5part_writer.hh"
#include "tests/support/collective_checks.hh"

#include <filesystem>

using namespace flecsi_lite::io;
using namespace io_test;
namespace fs = std::filesystem;

namespace {
// Rank r writes r + 2 particles of value `value`.
void write_step(h5part_writer& out, int k, double value) {
  out.begin_step({1.0 * k, k, 1.0});
  out.write("x", std::vector<double>(rank() + 2, value));
  out.end_step();
}

std::uint64_t expected_count() { return static_cast<std::uint64_t>(size()) * (size() + 3) / 2; }

// Every value of dataset x of step k equals `value`.
bool all_equal(const h5part_reader& in, int k, double value) {
  const auto x = in.read<double>(k, "x");
  int mine = std::all_of(x.begin(), x.end(), [&](double v) { return v == value; }), all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, comm());
  return all == 1 && in.particle_count(k) == expected_count();
}
}  // namespace

TEST_CASE("the final name appears only at close; the partial file holds every finished step") {
  const std::string path = file_name("atomic"), snapshot = file_name("atomic_snapshot");
  remove_files({path, snapshot});
  h5part_writer out(path);
  CHECK(out.partial_path() == path + ".partial");
  CHECK(fs::exists(path + ".partial"));
  CHECK_FALSE(fs::exists(path));
  write_step(out, 0, 1.0);
  write_step(out, 1, 2.0);
  // What a crash right now would leave behind: a copy of the partial file as it is on disk.
  if (rank() == 0) fs::copy_file(path + ".partial", snapshot);
  barrier();
  out.begin_step({2, 2, 1});  // an unfinished step is not in the snapshot
  out.write("x", std::vector<double>(rank() + 2, 3.0));
  CHECK_FALSE(fs::exists(path));
  out.end_step();
  out.close();
  CHECK(fs::exists(path));
  CHECK_FALSE(fs::exists(path + ".partial"));

  h5part_reader crashed(snapshot);
  CHECK(crashed.steps() == std::vector<std::int64_t>{0, 1});
  CHECK(crashed.root_attribute_as<int>("NumSteps") == 2);
  CHECK(all_equal(crashed, 0, 1.0));
  CHECK(all_equal(crashed, 1, 2.0));
  h5part_reader complete(path);
  CHECK(complete.steps().size() == 3);
  CHECK(all_equal(complete, 2, 3.0));
}

TEST_CASE("a writer destroyed without close leaves a complete file of that name untouched") {
  const std::string path = file_name("survivor");
  remove_files({path});
  {
    h5part_writer out(path);
    write_step(out, 0, 1.0);
    write_step(out, 1, 2.0);
    out.close();
  }
  {
    h5part_writer out(path);  // a new run to the same name...
    write_step(out, 0, -1.0);
    out.begin_step({1, 1, 1});
    out.write("x", std::vector<double>(rank() + 2, -2.0));
    // ...destroyed mid-step, as when the run is stopped.
  }
  CHECK(fs::exists(path + ".partial"));
  {
    h5part_reader in(path);
    CHECK(in.steps() == std::vector<std::int64_t>{0, 1});
    CHECK(all_equal(in, 0, 1.0));
    CHECK(all_equal(in, 1, 2.0));
  }
  // The partial file holds the finished step only; the unfinished one was dropped.
  h5part_reader partial(path + ".partial");
  CHECK(partial.steps() == std::vector<std::int64_t>{0});
  CHECK(partial.root_attribute_as<int>("NumSteps") == 1);
  CHECK(all_equal(partial, 0, -1.0));
}

TEST_CASE("an exception in the middle of a step leaves the complete file untouched") {
  const std::string path = file_name("exception");
  remove_files({path});
  {
    h5part_writer out(path);
    write_step(out, 0, 5.0);
    out.close();
  }
  const auto run = [&] {
    h5part_writer out(path);
    write_step(out, 0, 6.0);
    write_step(out, 1, 7.0);
    out.begin_step({2, 2, 1});
    out.write("x", std::vector<double>(rank() + 2, 8.0));
    throw std::runtime_error("simulated crash in step 2");
  };
  CHECK_THROWS_WITH(run(), "simulated crash in step 2");
  h5part_reader in(path);
  CHECK(in.steps() == std::vector<std::int64_t>{0});
  CHECK(all_equal(in, 0, 5.0));
  h5part_reader partial(path + ".partial");
  CHECK(partial.steps() == std::vector<std::int64_t>{0, 1});
  CHECK(all_equal(partial, 1, 7.0));
}

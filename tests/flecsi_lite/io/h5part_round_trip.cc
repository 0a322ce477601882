// H5Part round trips at any rank count: uneven local counts (odd ranks hold no particles), every
// value and attribute read back, by the default block partition and by explicit slices; steps
// beyond ten in numeric order; an empty step; appending; checkpoints.
#include <catch2/catch.hpp>

#include "flecsi_lite/io/checkpoint.hh"
#include "flecsi_lite/io/detail/h5part_layout.hh"
#include "flecsi_lite/io/h5part_reader.hh"
#include "flecsi_lite/io/h5part_writer.hh"
#include "flecsi_lite/io/run_state_checksums.hh"
#include "tests/support/collective_checks.hh"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numeric>
#include <vector>

using namespace flecsi_lite::io;
using namespace io_test;

namespace {
// Particles of rank r in step k: uneven, and none on odd ranks.
std::uint64_t local_count(int r, int k) { return r % 2 == 1 ? 0 : 5 + 3 * r + k; }
// Where rank r's particles start, computed independently of the library's exclusive scan.
std::uint64_t offset_of(int r, int k) {
  std::uint64_t offset = 0;
  for (int q = 0; q < r; ++q) offset += local_count(q, k);
  return offset;
}
std::uint64_t global_count(int k) { return offset_of(size(), k); }

// The values of particle g (global index) in step k, one per element type.
double x_of(std::uint64_t g, int k) { return 0.5 * g + 100.0 * k + 1.0 / 3; }
std::uint64_t id_of(std::uint64_t g, int k) { return (std::uint64_t{1} << 40) + 7 * g + k; }
std::int64_t signed_of(std::uint64_t g, int k) {
  return -static_cast<std::int64_t>(g) * (k + 1) - (std::int64_t{1} << 35);
}
float m_of(std::uint64_t g, int k) { return 0.25f * static_cast<float>(g + k); }

// Above the 64 KiB an attribute may take in HDF5's oldest file format.
std::string long_text() { return std::string(100000, 'p') + "end"; }

step_info info_of(int k) { return {0.125 * k + 1.0 / 7, 10 * k + 3, 0.125}; }

void write_series(const std::string& path, int steps) {
  h5part_writer out(path);
  out.describe_run({"mpi_io_test", "gamma = 1.4\nparticles = 10\n", 3});
  out.set_attribute("seed", std::int64_t{12345});
  out.set_attribute("long_text", long_text());
  for (int k = 0; k < steps; ++k) {
    out.begin_step(info_of(k));
    const std::uint64_t n = local_count(rank(), k), first = offset_of(rank(), k);
    std::vector<double> x(n);
    std::vector<std::uint64_t> id(n);
    std::vector<std::int64_t> signed_values(n);
    std::vector<std::int32_t> writer(n, rank());
    std::vector<float> m(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      x[i] = x_of(first + i, k), id[i] = id_of(first + i, k);
      signed_values[i] = signed_of(first + i, k), m[i] = m_of(first + i, k);
    }
    out.write("x", x.data(), n);
    out.write("id", id);
    out.write("signed", signed_values);
    out.write("rank", writer);
    out.write("m", m);
    out.set_step_attribute("energy", 1.5 * k);
    out.end_step();
    CHECK(out.steps_written() == k + 1);
  }
  out.close();
}

// Checks the values of rank-local part `part` of step k, read in every type.
void check_part(const h5part_reader& in, int k, slice part) {
  const auto x = in.read<double>(k, "x", part);
  const auto id = in.read<std::uint64_t>(k, "id", part);
  const auto signed_values = in.read<std::int64_t>(k, "signed", part);
  const auto m = in.read<float>(k, "m", part);
  const auto writer = in.read<std::int32_t>(k, "rank", part);
  REQUIRE(x.size() == part.count);
  for (std::uint64_t i = 0; i < part.count; ++i) {
    const std::uint64_t g = part.offset + i;
    CHECK(x[i] == x_of(g, k));
    CHECK(id[i] == id_of(g, k));
    CHECK(signed_values[i] == signed_of(g, k));
    CHECK(m[i] == m_of(g, k));
    CHECK((offset_of(writer[i], k) <= g && g < offset_of(writer[i], k) + local_count(writer[i], k)));
  }
}
}  // namespace

TEST_CASE("a multi-step file of uneven counts reads back exactly, by blocks and by slices") {
  const std::string path = file_name("round_trip");
  remove_files({path});
  write_series(path, 3);

  h5part_reader in(path);
  CHECK(in.steps() == std::vector<std::int64_t>{0, 1, 2});
  CHECK(in.root_attribute_as<std::string>("program") == "mpi_io_test");
  CHECK(in.root_attribute_as<std::string>("parameters") == "gamma = 1.4\nparticles = 10\n");
  CHECK(in.root_attribute_as<int>("dimension") == 3);
  CHECK(in.root_attribute_as<std::int64_t>("NumSteps") == 3);
  CHECK(in.root_attribute_as<long>("seed") == 12345);
  CHECK(in.root_attribute_as<std::string>("long_text") == long_text());
  CHECK(in.root_attribute_names() ==
        std::vector<std::string>{"NumSteps", "dimension", "long_text", "parameters", "program", "seed"});

  for (int k = 0; k < 3; ++k) {
    CHECK(in.step_attribute_as<double>(k, "TimeValue") == info_of(k).time);
    CHECK(in.step_attribute_as<double>(k, "time") == info_of(k).time);
    CHECK(in.step_attribute_as<std::int64_t>(k, "step") == info_of(k).step);
    CHECK(in.step_attribute_as<double>(k, "dt") == info_of(k).dt);
    CHECK(in.step_attribute_as<double>(k, "energy") == 1.5 * k);
    const step_info info = in.step_information(k);
    CHECK((info.time == info_of(k).time && info.step == info_of(k).step && info.dt == info_of(k).dt));

    CHECK(in.datasets(k) == std::vector<std::string>{"id", "m", "rank", "signed", "x"});
    CHECK(in.dataset_type(k, "x") == element_type::float64);
    CHECK(in.dataset_type(k, "id") == element_type::uint64);
    CHECK(in.dataset_type(k, "signed") == element_type::int64);
    CHECK(in.dataset_type(k, "rank") == element_type::int32);
    CHECK(in.dataset_type(k, "m") == element_type::float32);
    CHECK(in.particle_count(k) == global_count(k));

    // Default: a balanced block per rank, covering every particle once.
    const slice block = in.block(k);
    CHECK(block == block_slice(global_count(k), rank(), size()));
    check_part(in, k, block);
    CHECK(in.read<double>(k, "x").size() == block.count);

    // Explicit: rank r reads what rank p-1-r wrote (empty for odd writers).
    const int mirror = size() - 1 - rank();
    const slice written{offset_of(mirror, k), local_count(mirror, k)};
    check_part(in, k, written);
    const auto writer = in.read<std::int32_t>(k, "rank", written);
    CHECK(std::all_of(writer.begin(), writer.end(), [&](std::int32_t w) { return w == mirror; }));
  }
}

TEST_CASE("steps are numbered Step#0, Step#1, ... and listed in numeric order beyond ten") {
  const std::string path = file_name("many_steps");
  remove_files({path});
  {
    h5part_writer out(path);
    for (int k = 0; k < 12; ++k) {
      out.begin_step({1.0 * k, k, 1.0});
      out.write("x", std::vector<double>(rank() + 1, 1.0 * k));
      out.end_step();
    }
    out.close();
  }
  h5part_reader in(path);
  std::vector<std::int64_t> expected(12);
  std::iota(expected.begin(), expected.end(), 0);
  CHECK(in.steps() == expected);
  CHECK(in.last_step() == 11);
  CHECK(in.root_attribute_as<int>("NumSteps") == 12);
  for (int k = 0; k < 12; ++k) {
    CHECK(in.step_information(k).time == 1.0 * k);
    const auto x = in.read<double>(k, "x");
    CHECK(std::all_of(x.begin(), x.end(), [&](double v) { return v == 1.0 * k; }));
  }
}

TEST_CASE("a step in which no rank has particles is written and read") {
  const std::string path = file_name("empty_step");
  remove_files({path});
  {
    h5part_writer out(path);
    out.begin_step({0.5, 1, 0.1});
    out.write("x", std::vector<double>{});
    out.write("id", static_cast<const std::int64_t*>(nullptr), 0);
    out.end_step();
    out.close();
  }
  h5part_reader in(path);
  CHECK(in.particle_count(0) == 0);
  CHECK(in.datasets(0) == std::vector<std::string>{"id", "x"});
  CHECK(in.read<double>(0, "x").empty());
  CHECK(in.read<std::int64_t>(0, "id", slice{0, 0}).empty());
}

TEST_CASE("append continues a complete file, which stays complete until close") {
  const std::string path = file_name("append");
  remove_files({path});
  write_series(path, 2);
  {
    h5part_writer out(path, comm(), h5part_writer::mode::append);
    CHECK(out.steps_written() == 2);
    out.begin_step(info_of(2));
    out.write("x", std::vector<double>(local_count(rank(), 2), 7.0));
    out.end_step();
    if (rank() == 0) {
      h5part_reader untouched(path, MPI_COMM_SELF);
      CHECK(untouched.steps().size() == 2);
    }
    barrier();
    out.close();
  }
  h5part_reader in(path);
  CHECK(in.steps() == std::vector<std::int64_t>{0, 1, 2});
  CHECK(in.root_attribute_as<int>("NumSteps") == 3);
  check_part(in, 1, in.block(1));
  const auto x = in.read<double>(2, "x");
  CHECK(std::all_of(x.begin(), x.end(), [](double v) { return v == 7.0; }));
  CHECK(in.particle_count(2) == global_count(2));
}

TEST_CASE("a restart drops the steps after its iteration, or continues an interrupted partial file") {
  const std::string path = file_name("continue");
  remove_files({path, path + ".partial"});
  write_series(path, 4);  // iterations 3, 13, 23, 33
  {
    h5part_writer out(path, comm(), h5part_writer::mode::append);
    CHECK(out.last_iteration() == 33);
    CHECK(out.drop_steps_from(14) == 2);  // a restart at iteration 13 keeps Step#0 and Step#1
    CHECK(out.steps_written() == 2);
    CHECK(out.last_iteration() == 13);
    out.begin_step({9.0, 14, 0.5});
    out.write("x", std::vector<double>(local_count(rank(), 2), 5.0));
    out.end_step();
    out.finish();  // not committed: the run was "killed"; the complete file keeps its 4 steps
  }
  {
    h5part_reader untouched(path);
    CHECK(untouched.steps().size() == 4);
  }
  if (rank() == 0) std::filesystem::remove(path);
  barrier();
  {
    // Without the complete file, the partial one the interrupted run left is continued.
    h5part_writer out(path, comm(), h5part_writer::mode::append);
    CHECK(out.steps_written() == 3);
    CHECK(out.last_iteration() == 14);
    CHECK(out.drop_steps_from(100) == 0);
    out.close();
  }
  h5part_reader in(path);
  CHECK(in.steps() == std::vector<std::int64_t>{0, 1, 2});
  CHECK(in.root_attribute_as<int>("NumSteps") == 3);
  CHECK(in.step_information(2).step == 14);
  check_part(in, 1, in.block(1));
}

TEST_CASE("a checkpoint holds one full-precision step and the run state") {
  const std::string path = file_name("checkpoint", ".chk");
  remove_files({path});
  const run_state state{
    {"next_output_time", 0.75}, {"outputs_written", std::int64_t{4}}, {"kernel", std::string("wendland_c2")}};
  const step_info info{2.0 / 3, 41, 1e-3 / 3};
  const auto write_arrays = [&](h5part_writer& out) {
    const std::uint64_t n = local_count(rank(), 0), first = offset_of(rank(), 0);
    std::vector<double> x(n);
    std::vector<std::uint64_t> id(n);
    for (std::uint64_t i = 0; i < n; ++i) x[i] = x_of(first + i, 0) / 3, id[i] = id_of(first + i, 0);
    out.write("x", x);
    out.write("id", id);
  };
  write_checkpoint(path, info, state, write_arrays);

  {
    h5part_reader in(path);
    const checkpoint_contents contents = read_checkpoint(in);
    CHECK(contents.state == state);
    CHECK((contents.info.time == info.time && contents.info.step == info.step && contents.info.dt == info.dt));
    const slice block = in.block(0);
    const auto x = in.read<double>(0, "x");
    for (std::uint64_t i = 0; i < block.count; ++i) CHECK(x[i] == x_of(block.offset + i, 0) / 3);
    CHECK_NOTHROW(verify_run_state(in, contents));  // the checksums match what was written
  }

  // A checkpoint that fails while being written leaves the previous one as it was.
  const auto failing = [&](h5part_writer& out) {
    out.write("x", std::vector<double>(3, -1.0));
    throw std::runtime_error("simulated failure while writing the checkpoint");
  };
  CHECK_THROWS_WITH(write_checkpoint(path, {9, 9, 9}, {}, failing), "simulated failure while writing the checkpoint");
  h5part_reader in(path);
  CHECK(read_checkpoint(in).state == state);
  CHECK(in.step_information(0).step == 41);

  // A plain output file is not a checkpoint.
  const std::string plain = file_name("not_checkpoint");
  remove_files({plain});
  write_series(plain, 1);
  h5part_reader other(plain);
  CHECK_THAT(error_message<file_error>([&] { read_checkpoint(other); }), Catch::Contains("is not a checkpoint"));
}

namespace {
// A file written like a checkpoint by hand: the marker, `state`, a clock and, unless empty, `checksums`.
void write_like_checkpoint(const std::string& path, const run_state& state, const step_info& info,
                           const std::string& checksums) {
  h5part_writer out(path);
  out.set_attribute(checkpoint_marker, std::int64_t{1});
  for (const auto& [name, value] : state) out.set_attribute(checkpoint_state_prefix + name, value);
  if (!checksums.empty()) out.set_attribute(checksums_attribute, checksums);
  out.begin_step(info);
  out.write("x", std::vector<double>(local_count(rank(), 0), 1.0));
  out.end_step();
  out.close();
}
}  // namespace

TEST_CASE("a restart's run state must match the checksums written with it") {
  const std::string path = file_name("checksums", ".chk");
  remove_files({path});
  const run_state state{{"next_output", 0.5}, {"output_due", std::int64_t{1}}, {"program", std::string("sod")}};
  const step_info info{0.25, 7, 1e-3};
  const checked_values written{{"time", 0.25},
                               {"step", std::int64_t{7}},
                               {"dt", 1e-3},
                               {"state:next_output", 0.5},
                               {"state:output_due", std::int64_t{1}},
                               {"state:program", std::string("sod")}};
  const auto verify = [&] {
    h5part_reader in(path);
    verify_run_state(in, read_checkpoint(in));
  };
  // Checksums of other values (dt one ulp up, output_due 2): both named, the others not.
  checked_values other = written;
  other["dt"] = std::nextafter(1e-3, 1.0);
  other["state:output_due"] = std::int64_t{2};
  write_like_checkpoint(path, state, info, checksums_text(other));
  const auto changed = error_message<layout_error>(verify);
  CHECK_THAT(changed, Catch::Contains("Step#0 attribute 'dt', root attribute 'state:output_due' differ from the "
                                      "value the writing run stored"));
  CHECK_THAT(changed, !Catch::Contains("'time'") && !Catch::Contains("state:program"));
  // The same values: accepted.
  write_like_checkpoint(path, state, info, checksums_text(written));
  CHECK_NOTHROW(verify());
  // Without checksums (a checkpoint of an earlier version): refused, saying to make it again.
  write_like_checkpoint(path, state, info, "");
  CHECK_THAT(error_message<layout_error>(verify),
             Catch::Contains("has no root attribute 'checksums'") && Catch::Contains("make the checkpoint again"));
}

TEST_CASE("identical runs write byte-identical files") {
  const std::string first = file_name("identical_a"), second = file_name("identical_b");
  remove_files({first, second});
  write_series(first, 2);
  write_series(second, 2);
  if (rank() == 0) {
    const auto bytes = [](const std::string& path) {
      std::ifstream in(path, std::ios::binary);
      return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    };
    const std::string a = bytes(first), b = bytes(second);
    CHECK(a.size() > 100000);
    CHECK(a == b);
  }
  barrier();
}

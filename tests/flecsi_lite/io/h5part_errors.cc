// Errors of the H5Part reader and writer: each throws the same io_error subclass with the same
// message on every rank (no rank left waiting), naming the file, the step and the dataset;
// HDF5 prints nothing.
#include <catch2/catch.hpp>

#include "flecsi_lite/io/h5part_reader.hh"
#include "flecsi_lite/io/h5part_writer.hh"
#include "tests/support/collective_checks.hh"

#include <hdf5.h>

#include <filesystem>
#include <fstream>

using namespace flecsi_lite::io;
using namespace io_test;
using Catch::Contains;
namespace fs = std::filesystem;

namespace {
void write_small_file(const std::string& path) {
  h5part_writer out(path);
  for (int k = 0; k < 2; ++k) {
    out.begin_step({1.0 * k, k, 1.0});
    out.write("x", std::vector<double>(rank() + 1, 1.0));
    out.write("rho", std::vector<double>(rank() + 1, 2.0));
    out.write("id", std::vector<std::int64_t>(rank() + 1, 3));
    out.end_step();
  }
  out.close();
}

// Rank 0 writes, with serial HDF5, a file that breaks the layout: in Step#0 datasets of lengths
// 4 and 3; in Step#1 a 2-D dataset.
void write_broken_layout(const std::string& path) {
  if (rank() == 0) {
    const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    const double values[4] = {1, 2, 3, 4};
    const auto add = [&](const char* group_name, const char* name, int rank_of_space, const hsize_t* dims) {
      hid_t group = H5Lexists(file, group_name, H5P_DEFAULT) > 0
                      ? H5Gopen2(file, group_name, H5P_DEFAULT)
                      : H5Gcreate2(file, group_name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      const hid_t space = H5Screate_simple(rank_of_space, dims, nullptr);
      const hid_t set = H5Dcreate2(group, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values);
      H5Dclose(set), H5Sclose(space), H5Gclose(group);
    };
    const hsize_t four[1] = {4}, three[1] = {3}, square[2] = {2, 2};
    add("Step#0", "x", 1, four);
    add("Step#0", "y", 1, three);
    add("Step#1", "x", 2, square);
    H5Fclose(file);
  }
  barrier();
}
}  // namespace

TEST_CASE("a missing file, a file that is not HDF5 and a truncated file give clean errors on every rank") {
  const std::string good = file_name("errors_good"), text = file_name("errors_text", ".txt"),
                    truncated = file_name("errors_truncated"), stub = file_name("errors_stub");
  remove_files({good, text, truncated, stub});
  write_small_file(good);
  if (rank() == 0) {
    std::ofstream(text) << "x y z\n1 2 3\n";
    fs::copy_file(good, truncated);
    fs::resize_file(truncated, fs::file_size(good) / 2);
    fs::copy_file(good, stub);
    fs::resize_file(stub, 6);  // not even the HDF5 signature is left
  }
  barrier();

  const auto open = [](const std::string& path) { return [path] { h5part_reader in(path); }; };
  std::string message = error_message<file_error>(open("no_such_file.h5part"));
  CHECK(same_on_every_rank(message));
  CHECK_THAT(message, Contains("cannot open 'no_such_file.h5part': no such file"));

  message = error_message<file_error>(open(text));
  CHECK(same_on_every_rank(message));
  CHECK_THAT(message, Contains("'" + text + "' is not an HDF5 file"));

  message = error_message<file_error>(open(truncated));
  CHECK(same_on_every_rank(message));
  CHECK_THAT(message, Contains("'" + truncated + "' is truncated or corrupted") && Contains("HDF5: truncated file"));

  message = error_message<file_error>(open(stub));
  CHECK(same_on_every_rank(message));
  CHECK_THAT(message, Contains("'" + stub + "' is not an HDF5 file"));

  // The good file is still fine, and a directory is not a file.
  CHECK_NOTHROW(open(good)());
  CHECK_THAT(error_message<file_error>(open(".")), Contains("'.'") && Contains("is a directory"));
}

TEST_CASE("a missing step, dataset or attribute is named, with what the file has") {
  const std::string path = file_name("errors_missing");
  remove_files({path});
  write_small_file(path);
  h5part_reader in(path);

  std::string message = error_message<missing_step_error>([&] { in.read<double>(7, "x"); });
  CHECK(same_on_every_rank(message));
  CHECK(message == "'" + path + "' has no step 7 (it has steps 0 to 1)");
  CHECK_THAT(error_message<missing_step_error>([&] { in.datasets(-1); }), Contains("has no step -1"));

  message = error_message<missing_dataset_error>([&] { in.read<double>(1, "rh"); });
  CHECK(same_on_every_rank(message));
  CHECK(message == "step 1 of '" + path + "' has no dataset 'rh'; did you mean 'rho'? (datasets: id rho x)");
  CHECK_THAT(error_message<missing_dataset_error>([&] { in.dataset_type(0, "velocity"); }),
             Contains("no dataset 'velocity' (datasets: id rho x)"));

  message = error_message<missing_attribute_error>([&] { in.step_attribute(0, "TimeValu"); });
  CHECK_THAT(message, Contains("step 0 of '" + path + "' has no attribute 'TimeValu'; did you mean 'TimeValue'?"));
  CHECK_THAT(error_message<missing_attribute_error>([&] { in.root_attribute("program"); }),
             Contains("has no root attribute 'program'"));
}

TEST_CASE("reading with the wrong element type names both types") {
  const std::string path = file_name("errors_type");
  remove_files({path});
  write_small_file(path);
  h5part_reader in(path);
  std::string message = error_message<element_type_error>([&] { in.read<double>(0, "id"); });
  CHECK(same_on_every_rank(message));
  CHECK(message == "dataset 'id' of step 0 of '" + path + "' holds int64 values, not double");
  CHECK_THAT(error_message<element_type_error>([&] { in.read<std::int32_t>(0, "x"); }),
             Contains("dataset 'x' of step 0") && Contains("holds double values, not int32"));
  CHECK_THAT(error_message<element_type_error>([&] { in.step_attribute_as<std::string>(0, "dt"); }),
             Contains("attribute 'dt' of step 0") && Contains("is real 1, not a string"));
}

TEST_CASE("a slice out of range on one rank makes every rank throw") {
  const std::string path = file_name("errors_slice");
  remove_files({path});
  write_small_file(path);
  h5part_reader in(path);
  const std::uint64_t n = in.particle_count(0);
  const int last = size() - 1;
  const slice part = rank() == last ? slice{n - 1, 2} : slice{0, 1};
  const std::string message = error_message<slice_error>([&] { in.read<double>(0, "x", part); });
  CHECK(same_on_every_rank(message));
  CHECK_THAT(message, Contains("dataset 'x' of step 0") &&
                        Contains("has " + std::to_string(n) + " particles; rank " + std::to_string(last) +
                                 " asked for [" + std::to_string(n - 1) + ", " + std::to_string(n + 1) + ")"));
  // The reader is still usable afterwards.
  CHECK(in.read<double>(0, "x").size() == in.block(0).count);
}

TEST_CASE("datasets of different lengths in one step, and 2-D datasets, break the layout") {
  const std::string path = file_name("errors_layout");
  remove_files({path});
  write_broken_layout(path);
  h5part_reader in(path);
  std::string message = error_message<layout_error>([&] { in.read<double>(0, "x"); });
  CHECK(same_on_every_rank(message));
  CHECK(message == "step 0 of '" + path + "' has datasets of different lengths: 'x' has 4 particles, 'y' has 3");
  CHECK_THAT(error_message<layout_error>([&] { in.particle_count(0); }), Contains("different lengths"));
  CHECK_THAT(error_message<layout_error>([&] { in.read<double>(1, "x"); }),
             Contains("dataset 'x' of step 1 of '" + path + "' has 2 dimensions; H5Part datasets are 1-D"));
}

namespace {
// Rank 0 writes a step whose datasets declare 2^40 particles (the dataspace a flipped bit or a
// forged file gives) but hold none: storage is allocated only when written, so the file is tiny.
void write_huge_declared_extent(const std::string& path) {
  if (rank() == 0) {
    const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    const hid_t group = H5Gcreate2(file, "Step#0", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const hsize_t huge[1] = {hsize_t(1) << 40};
    const hid_t space = H5Screate_simple(1, huge, nullptr);
    for (const char* name : {"x", "m"})
      H5Dclose(H5Dcreate2(group, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    H5Sclose(space), H5Gclose(group), H5Fclose(file);
  }
  barrier();
}
}  // namespace

TEST_CASE("a declared extent the file cannot hold is an error before anything is allocated") {
  const std::string path = file_name("errors_huge_extent");
  remove_files({path});
  write_huge_declared_extent(path);
  h5part_reader in(path);
  const std::string message = error_message<file_error>([&] { in.particle_count(0); });
  CHECK(same_on_every_rank(message));
  CHECK_THAT(message, Contains("dataset 'm' of step 0 of '" + path + "' declares 1099511627776 particles of 8 bytes"));
  CHECK_THAT(message, Contains("the file is corrupted"));
  CHECK_THAT(error_message<file_error>([&] { in.read<double>(0, "x"); }), Contains("declares 1099511627776"));
}

TEST_CASE("misuse of the writer is an error on every rank and leaves the writer usable") {
  const std::string path = file_name("errors_writer");
  remove_files({path});
  h5part_writer out(path);
  const std::vector<double> values(rank() + 1, 1.0);
  std::string message = error_message<usage_error>([&] { out.write("x", values); });
  CHECK(same_on_every_rank(message));
  CHECK_THAT(message, Contains("write dataset 'x' of step 0 in '" + path + "': no open step"));
  CHECK_THAT(error_message<usage_error>([&] { out.end_step(); }), Contains("end_step: no open step"));

  out.begin_step({0, 0, 0});
  CHECK_THAT(error_message<usage_error>([&] {
               out.begin_step({1, 1, 1});
             }),
             Contains("step 0 of '" + path + "' is still open"));
  out.write("x", values);
  CHECK_THAT(error_message<usage_error>([&] { out.write("x", values); }),
             Contains("dataset 'x' of step 0") && Contains("already written"));
  CHECK_THAT(error_message<usage_error>([&] { out.write("a/b", values); }),
             Contains("'a/b' is not a valid dataset name"));
  CHECK_THAT(error_message<layout_error>([&] { out.write("y", std::vector<double>(rank() + 2, 1.0)); }),
             Contains("dataset 'y' of step 0 in '" + path + "' has") && Contains("but the step's other datasets have"));
  if (size() > 1) {
    message = error_message<layout_error>([&] { out.write(rank() == 0 ? "u" : "v", values); });
    CHECK(same_on_every_rank(message));
    CHECK_THAT(message, Contains("ranks write different datasets"));
    message = error_message<layout_error>([&] {
      if (rank() == 0)
        out.write("u", std::vector<std::int32_t>(rank() + 1));
      else
        out.write("u", std::vector<std::int64_t>(rank() + 1));
    });
    CHECK(same_on_every_rank(message));
    CHECK_THAT(message, Contains("ranks write different datasets (names or element types differ)"));
    CHECK_NOTHROW(out.write("u", std::vector<std::int32_t>(rank() + 1)));
    CHECK_NOTHROW(out.write("w", values));
    CHECK_THAT(error_message<layout_error>([&] { out.set_attribute("seed", std::int64_t{rank()}); }),
               Contains("ranks set different root attributes"));
  }
  out.write("z", values);
  out.end_step();
  out.close();
  CHECK_THAT(error_message<usage_error>([&] { out.begin_step({1, 1, 1}); }), Contains("is closed"));

  h5part_reader in(path);
  CHECK(in.steps() == std::vector<std::int64_t>{0});
  std::vector<std::string> expected{"x", "z"};
  if (size() > 1) expected = {"u", "w", "x", "z"};
  CHECK(in.datasets(0) == expected);
}

TEST_CASE("a writer that cannot create its file fails on every rank") {
  const std::string message = error_message<file_error>([] { h5part_writer out("no/such/directory/out.h5part"); });
  CHECK(same_on_every_rank(message));
  CHECK_THAT(message, Contains("cannot create 'no/such/directory/out.h5part.partial' for writing"));
}

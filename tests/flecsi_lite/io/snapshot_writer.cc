// The GADGET/SWIFT-layout snapshot writer on several ranks: the layout read back with serial HDF5
// (groups, N and N x 3 datasets in rank order, 1-D numeric and string attributes), the final name
// only after close, an earlier file kept when a writer is abandoned, the same error on every rank
// when ranks disagree, and the XDMF index of a series of such files.
#include <catch2/catch.hpp>

#include "flecsi_lite/io/io_error.hh"
#include "flecsi_lite/io/snapshot_writer.hh"
#include "flecsi_lite/io/xdmf_index.hh"
#include "tests/support/collective_checks.hh"

#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace flecsi_lite::io;
using namespace io_test;
namespace fs = std::filesystem;

namespace {
std::uint64_t total_rows() { return std::uint64_t(size()) * (size() + 1) / 2; }

// Rank r writes r + 1 rows (x, 10 x, 100 x) with x = global row index, and the row index as ids.
void write_particles(snapshot_writer& out, double time) {
  std::uint64_t first = 0;
  for (int r = 0; r < rank(); ++r) first += r + 1;
  std::vector<double> xyz;
  std::vector<std::uint64_t> ids;
  for (int i = 0; i <= rank(); ++i) {
    const double x = double(first + i);
    xyz.insert(xyz.end(), {x, 10 * x, 100 * x});
    ids.push_back(first + i);
  }
  out.set_attributes("Header", {{"Time", std::vector<double>{time}},
                                {"NumPart_Total", std::vector<std::uint32_t>{std::uint32_t(total_rows()), 0}},
                                {"Code", std::string("test")}});
  out.write("PartType0", "Coordinates", xyz, 3, {{"U_L exponent", std::vector<float>{1.f}}});
  out.write("PartType0", "ParticleIDs", ids);
}

// Serial reads on rank 0.
std::vector<hsize_t> shape_of(hid_t file, const char* dataset) {
  const hid_t d = H5Dopen2(file, dataset, H5P_DEFAULT), s = H5Dget_space(d);
  std::vector<hsize_t> extent(H5Sget_simple_extent_ndims(s));
  H5Sget_simple_extent_dims(s, extent.data(), nullptr);
  H5Sclose(s), H5Dclose(d);
  return extent;
}
template<class T>
std::vector<T> read_all(hid_t file, const char* dataset, hid_t type, std::size_t count) {
  std::vector<T> values(count);
  const hid_t d = H5Dopen2(file, dataset, H5P_DEFAULT);
  H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Dclose(d);
  return values;
}
hsize_t attribute_length(hid_t file, const char* object, const char* name) {
  const hid_t a = H5Aopen_by_name(file, object, name, H5P_DEFAULT, H5P_DEFAULT), s = H5Aget_space(a);
  const hsize_t n = H5Sget_simple_extent_npoints(s);
  H5Sclose(s), H5Aclose(a);
  return n;
}
}  // namespace

TEST_CASE("a snapshot holds its groups, N x 3 datasets in rank order and SWIFT-style attributes") {
  const std::string path = file_name("snapshot_layout", ".hdf5");
  remove_files({path});
  {
    snapshot_writer out(path);
    CHECK(fs::exists(path + ".partial"));
    write_particles(out, 0.25);
    CHECK_FALSE(fs::exists(path));
    out.close();
  }
  CHECK(fs::exists(path));
  CHECK_FALSE(fs::exists(path + ".partial"));
  if (rank() == 0) {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(file >= 0);
    CHECK(shape_of(file, "PartType0/Coordinates") == std::vector<hsize_t>{total_rows(), 3});
    CHECK(shape_of(file, "PartType0/ParticleIDs") == std::vector<hsize_t>{total_rows()});
    const auto xyz = read_all<double>(file, "PartType0/Coordinates", H5T_NATIVE_DOUBLE, 3 * total_rows());
    const auto ids = read_all<std::uint64_t>(file, "PartType0/ParticleIDs", H5T_NATIVE_UINT64, total_rows());
    for (std::uint64_t i = 0; i < total_rows(); ++i) {
      CHECK(ids[i] == i);
      CHECK(xyz[3 * i] == double(i));
      CHECK(xyz[3 * i + 2] == 100.0 * double(i));
    }
    // Numbers as 1-D arrays (even one value), as SWIFT and GADGET write them.
    CHECK(attribute_length(file, "Header", "Time") == 1);
    CHECK(attribute_length(file, "Header", "NumPart_Total") == 2);
    CHECK(attribute_length(file, "PartType0/Coordinates", "U_L exponent") == 1);
    double time = 0;
    const hid_t a = H5Aopen_by_name(file, "Header", "Time", H5P_DEFAULT, H5P_DEFAULT);
    H5Aread(a, H5T_NATIVE_DOUBLE, &time);
    H5Aclose(a);
    CHECK(time == 0.25);
    H5Fclose(file);
  }
  barrier();
}

TEST_CASE("an abandoned snapshot leaves the earlier file of its name as it was") {
  const std::string path = file_name("snapshot_abandoned", ".hdf5");
  remove_files({path});
  {
    snapshot_writer out(path);
    write_particles(out, 1.0);
    out.close();
  }
  const auto earlier = fs::file_size(path);
  {
    snapshot_writer out(path);
    out.set_attributes("Header", {{"Time", std::vector<double>{2.0}}});
  }  // destroyed without close()
  CHECK(fs::file_size(path) == earlier);
  CHECK_FALSE(fs::exists(path + ".partial"));
  CHECK(describe_snapshot(path).time == 1.0);
  barrier();
}

TEST_CASE("ranks that disagree, bad names and a folder in the way fail alike on every rank") {
  const std::string path = file_name("snapshot_errors", ".hdf5");
  remove_files({path});
  snapshot_writer out(path);
  const std::string mismatch = error_message<layout_error>([&] {
    out.set_attributes("Header", {{"Time", std::vector<double>{double(rank() == size() - 1)}}});
  });
  if (size() > 1) CHECK_THAT(mismatch, Catch::Contains("ranks set different attributes"));
  CHECK(same_on_every_rank(mismatch));
  const std::string twice = error_message<usage_error>([&] {
    out.write("PartType0", "Masses", std::vector<double>(2, 1.0));
    out.write("PartType0", "Masses", std::vector<double>(2, 1.0));
  });
  CHECK_THAT(twice, Catch::Contains("already written"));
  CHECK(same_on_every_rank(twice));
  CHECK_THAT(error_message<usage_error>([&] { out.write("Part/Type0", "x", std::vector<double>(1)); }),
             Catch::Contains("not a valid name"));
  out.close();

  const std::string folder = file_name("snapshot_folder", ".hdf5");
  if (rank() == 0) fs::create_directories(folder);
  barrier();
  const std::string refused = error_message<file_error>([&] { snapshot_writer blocked(folder); });
  CHECK_THAT(refused, Catch::Contains("directory"));
  CHECK(same_on_every_rank(refused));
  CHECK(fs::is_directory(folder));
}

TEST_CASE("the XDMF index lists every snapshot with its time, points and arrays") {
  std::vector<std::string> paths;
  for (int k = 0; k < 2; ++k) {
    paths.push_back(file_name("series_000" + std::to_string(k), ".hdf5"));
    remove_files({paths.back()});
    snapshot_writer out(paths.back());
    write_particles(out, 0.5 * k);
    out.close();
  }
  const std::string index = file_name("series", ".xdmf");
  write_xdmf_index(comm(), index, paths);
  const auto description = describe_snapshot(paths[1]);
  CHECK(description.time == 0.5);
  REQUIRE(description.grids.size() == 1);
  CHECK(description.grids[0].group == "PartType0");
  CHECK(description.grids[0].points == total_rows());
  REQUIRE(description.grids[0].arrays.size() == 2);
  CHECK(description.grids[0].arrays[1].name == "ParticleIDs");
  CHECK(description.grids[0].arrays[1].number_type == "UInt");
  std::ifstream in(index);
  std::stringstream text;
  text << in.rdbuf();
  CHECK_THAT(text.str(), Catch::Contains("<Time Type=\"Single\" Value=\"0.5\"/>"));
  CHECK_THAT(text.str(), Catch::Contains(paths[0] + ":/PartType0/Coordinates"));
  CHECK_THAT(text.str(), Catch::Contains("Dimensions=\"" + std::to_string(total_rows()) + " 3\""));
  CHECK_FALSE(fs::exists(index + ".partial"));
  // A missing snapshot is an error on every rank, and the index stays as it was.
  const std::string missing = error_message<file_error>([&] {
    write_xdmf_index(comm(), index, {paths[0], file_name("series_absent", ".hdf5")});
  });
  CHECK_THAT(missing, Catch::Contains("no snapshot file"));
  CHECK(same_on_every_rank(missing));
  std::ifstream again(index);
  std::stringstream unchanged;
  unchanged << again.rdbuf();
  CHECK(unchanged.str() == text.str());
}

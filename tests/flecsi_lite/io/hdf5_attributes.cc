// Scalar HDF5 attributes: every kind written and read back (also replaced with another kind),
// variable-length strings from other writers, names listed; HDF5's error printing silenced and
// its reason reported.
#include <catch2/catch.hpp>

#include "flecsi_lite/io/detail/hdf5_attributes.hh"
#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/detail/hdf5_handle.hh"

#include <cstdio>

using namespace flecsi_lite::io;

namespace {
struct scratch_file {
  std::string path = "unit_io_hdf5_attributes.h5";
  hdf5_handle file = file_handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  ~scratch_file() {
    file.close();
    std::remove(path.c_str());
  }
};
}  // namespace

TEST_CASE("attributes of every kind read back exactly and can be replaced") {
  scratch_file scratch;
  const hid_t root = scratch.file.get();
  write_attribute(root, "count", std::int64_t{-(std::int64_t{1} << 60)});
  write_attribute(root, "time", 1.0 / 3);
  write_attribute(root, "empty", std::string());
  write_attribute(root, "program", std::string("sod"));
  CHECK(read_attribute(root, "count", "count") == attribute_value{-(std::int64_t{1} << 60)});
  CHECK(read_attribute(root, "time", "time") == attribute_value{1.0 / 3});
  CHECK(read_attribute(root, "empty", "empty") == attribute_value{std::string()});
  CHECK(read_attribute(root, "program", "program") == attribute_value{std::string("sod")});
  write_attribute(root, "program", 2.5);  // another kind under the same name
  CHECK(read_attribute(root, "program", "program") == attribute_value{2.5});
  CHECK(attribute_names(root) == std::vector<std::string>{"count", "empty", "program", "time"});
  CHECK(has_attribute(root, "time"));
  CHECK_FALSE(has_attribute(root, "TimeValue"));
}

TEST_CASE("variable-length string and int32 attributes written by other tools are read") {
  scratch_file scratch;
  const hid_t root = scratch.file.get();
  auto space = dataspace_handle(H5Screate(H5S_SCALAR));
  auto type = datatype_handle(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.get(), H5T_VARIABLE);
  const char* text = "written by h5py";
  auto text_attribute = attribute_handle(H5Acreate2(root, "origin", type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT));
  H5Awrite(text_attribute.get(), type.get(), &text);
  const int dimension = 2;
  auto int_attribute =
    attribute_handle(H5Acreate2(root, "dimension", H5T_STD_I32BE, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  H5Awrite(int_attribute.get(), H5T_NATIVE_INT, &dimension);
  text_attribute.close(), int_attribute.close();
  CHECK(read_attribute(root, "origin", "origin") == attribute_value{std::string("written by h5py")});
  CHECK(read_attribute(root, "dimension", "dimension") == attribute_value{std::int64_t{2}});

  const hsize_t three = 3;
  auto array_space = dataspace_handle(H5Screate_simple(1, &three, nullptr));
  const double values[3] = {1, 2, 3};
  auto array = attribute_handle(H5Acreate2(root, "box", H5T_IEEE_F64LE, array_space.get(), H5P_DEFAULT, H5P_DEFAULT));
  H5Awrite(array.get(), H5T_NATIVE_DOUBLE, values);
  array.close();
  CHECK_THROWS_WITH(read_attribute(root, "box", "attribute 'box'"),
                    "attribute 'box' holds 3 values; only single values are read");
}

TEST_CASE("a quiet scope silences HDF5 and restores its handler; the reason is kept") {
  H5E_auto2_t before = nullptr;
  void* before_data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &before, &before_data);
  {
    hdf5_quiet_scope quiet;
    H5E_auto2_t during = nullptr;
    void* during_data = nullptr;
    H5Eget_auto2(H5E_DEFAULT, &during, &during_data);
    CHECK(during == nullptr);
    CHECK(H5Fopen("unit_io_no_such_file.h5", H5F_ACC_RDONLY, H5P_DEFAULT) < 0);
    CHECK_FALSE(hdf5_error_detail().empty());
    CHECK_THAT(hdf5_reason(), Catch::StartsWith(" (HDF5: ") && Catch::EndsWith(")"));
    H5Eclear2(H5E_DEFAULT);
    CHECK(hdf5_reason().empty());
  }
  H5E_auto2_t after = nullptr;
  void* after_data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &after, &after_data);
  CHECK(after == before);
  CHECK(after_data == before_data);
}

// Element types: C++ types map to the H5Part element types, HDF5 datatypes (any byte order) are
// classified back, and attribute values convert only to the types they can hold.
#include <catch2/catch.hpp>

#include "flecsi_lite/io/attribute_value.hh"
#include "flecsi_lite/io/element_type.hh"

using namespace flecsi_lite::io;

TEST_CASE("C++ types map to element types by kind, size and sign") {
  static_assert(element_type_of<double>() == element_type::float64);
  static_assert(element_type_of<const float>() == element_type::float32);
  static_assert(element_type_of<long>() == element_type::int64);
  static_assert(element_type_of<long long>() == element_type::int64);
  static_assert(element_type_of<std::uint64_t>() == element_type::uint64);
  static_assert(element_type_of<std::size_t>() == element_type::uint64);
  static_assert(element_type_of<int>() == element_type::int32);
  CHECK(std::string(element_type_name(element_type::int32)) == "int32");
}

TEST_CASE("HDF5 datatypes are classified whatever their byte order") {
  for (auto type :
       {element_type::float64, element_type::float32, element_type::int64, element_type::uint64, element_type::int32}) {
    CHECK(classify(file_type(type)) == type);
    CHECK(classify(memory_type(type)) == type);
  }
  CHECK(classify(H5T_IEEE_F64BE) == element_type::float64);
  CHECK(classify(H5T_STD_I32BE) == element_type::int32);
  CHECK(classify(H5T_STD_I16LE) == element_type::unsupported);
  CHECK(classify(H5T_STD_U32LE) == element_type::unsupported);
  CHECK(describe_datatype(H5T_STD_I16LE) == "int16");
  CHECK(describe_datatype(H5T_STD_U32LE) == "uint32");
  CHECK(describe_datatype(H5T_C_S1) == "string");
}

TEST_CASE("attribute values convert only to types that hold them exactly") {
  const attribute_value integer = std::int64_t{300}, real = 0.5, text = std::string("sod");
  CHECK(attribute_as<int>(integer, "a") == 300);
  CHECK(attribute_as<double>(integer, "a") == 300.0);
  CHECK(attribute_as<double>(real, "b") == 0.5);
  CHECK(attribute_as<std::string>(text, "c") == "sod");
  CHECK_THROWS_WITH(attribute_as<int>(real, "attribute 'dt'"), "attribute 'dt' is real 0.5, not an integer");
  CHECK_THROWS_WITH(attribute_as<double>(text, "attribute 'p'"), "attribute 'p' is string sod, not a real");
  CHECK_THROWS_WITH(attribute_as<std::string>(integer, "attribute 'n'"), "attribute 'n' is integer 300, not a string");
  CHECK_THROWS_AS(attribute_as<std::int8_t>(integer, "n"), element_type_error);
  CHECK_THROWS_AS(attribute_as<unsigned>(attribute_value{std::int64_t{-1}}, "n"), element_type_error);
  CHECK(to_string(attribute_value{0.1}) == "0.10000000000000001");
}

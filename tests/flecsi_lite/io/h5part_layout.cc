// The on-disk layout as HDF5's own tools see it: exactly /Step#k groups holding 1-D datasets of
// the global length, with the TimeValue/time/step/dt attributes and the root attributes.
#include <catch2/catch.hpp>

#include "flecsi_lite/io/h5part_writer.hh"
#include "tests/support/collective_checks.hh"

#include <array>
#include <cstdio>
#include <sstream>

using namespace flecsi_lite::io;
using namespace io_test;

namespace {
// Output of a shell command, with runs of blanks squeezed to one space and line indentation
// reduced to at most one space.
std::string run_command(const std::string& command) {
  std::string output;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    std::array<char, 4096> buffer;
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) output.append(buffer.data(), n);
    pclose(pipe);
  }
  std::string squeezed;
  for (char c : output)
    if (!(c == ' ' && !squeezed.empty() && squeezed.back() == ' ')) squeezed += c;
  return squeezed;
}

void write_layout_file(const std::string& path) {
  h5part_writer out(path);
  out.describe_run({"layout_test", "gamma = 1.4\n", 2});
  for (int k = 0; k < 2; ++k) {
    out.begin_step({0.5 * k, 100 + k, 0.5});
    const std::size_t n = rank() + 1;
    out.write("x", std::vector<double>(n, 1.0));
    out.write("y", std::vector<double>(n, 2.0));
    out.write("id", std::vector<std::uint64_t>(n, 3));
    out.end_step();
  }
  out.close();
}
}  // namespace

#if defined(FLECSPH_H5LS) && defined(FLECSPH_H5DUMP)
TEST_CASE("h5ls and h5dump see exactly the H5Part layout /Step#k/<quantity> with its attributes") {
  const std::string path = file_name("layout");
  remove_files({path});
  write_layout_file(path);
  if (rank() == 0) {
    const std::string n = std::to_string(size() * (size() + 1) / 2);
    const std::string expected =
      "/ Group\n"
      "/Step#0 Group\n"
      "/Step#0/id Dataset {" +
      n +
      "}\n"
      "/Step#0/x Dataset {" +
      n +
      "}\n"
      "/Step#0/y Dataset {" +
      n +
      "}\n"
      "/Step#1 Group\n"
      "/Step#1/id Dataset {" +
      n +
      "}\n"
      "/Step#1/x Dataset {" +
      n +
      "}\n"
      "/Step#1/y Dataset {" +
      n + "}\n";
    CHECK(run_command(std::string(FLECSPH_H5LS) + " -r " + path) == expected);

    const std::string header = run_command(std::string(FLECSPH_H5DUMP) + " -H " + path);
    for (const std::string& part :
         {std::string("GROUP \"/\" {\n ATTRIBUTE \"NumSteps\" {\n DATATYPE H5T_STD_I64LE\n DATASPACE SCALAR\n }\n"
                      " ATTRIBUTE \"dimension\" {\n DATATYPE H5T_STD_I64LE"),
          std::string(
            "GROUP \"Step#1\" {\n ATTRIBUTE \"TimeValue\" {\n DATATYPE H5T_IEEE_F64LE\n DATASPACE SCALAR\n }\n"
            " ATTRIBUTE \"dt\" {\n DATATYPE H5T_IEEE_F64LE\n DATASPACE SCALAR\n }\n"
            " ATTRIBUTE \"step\" {\n DATATYPE H5T_STD_I64LE\n DATASPACE SCALAR\n }\n"
            " ATTRIBUTE \"time\" {\n DATATYPE H5T_IEEE_F64LE\n DATASPACE SCALAR\n }\n"
            " DATASET \"id\" {\n DATATYPE H5T_STD_U64LE\n DATASPACE SIMPLE { ( " +
            n + " ) / ( " + n +
            " ) }\n }\n"
            " DATASET \"x\" {\n DATATYPE H5T_IEEE_F64LE\n DATASPACE SIMPLE { ( " +
            n + " ) / ( " + n + " ) }\n }\n")})
      CHECK_THAT(header, Catch::Contains(part));

    const auto attribute = [&](const std::string& name) {
      return run_command(std::string(FLECSPH_H5DUMP) + " -a '" + name + "' " + path);
    };
    CHECK_THAT(attribute("/Step#1/TimeValue"), Catch::Contains("(0): 0.5\n"));
    CHECK_THAT(attribute("/Step#1/time"), Catch::Contains("(0): 0.5\n"));
    CHECK_THAT(attribute("/Step#1/step"), Catch::Contains("(0): 101\n"));
    CHECK_THAT(attribute("/Step#0/dt"), Catch::Contains("(0): 0.5\n"));
    CHECK_THAT(attribute("/NumSteps"), Catch::Contains("(0): 2\n"));
    CHECK_THAT(attribute("/program"), Catch::Contains("(0): \"layout_test\"\n"));
    CHECK_THAT(attribute("/dimension"), Catch::Contains("(0): 2\n"));
  }
  barrier();
}
#endif

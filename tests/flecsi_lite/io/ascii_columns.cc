// ASCII column export for splash: the default SPH columns in splash's order when present, a time
// header splash recognizes, labels at least four spaces apart, and every value read back exactly.
#include <catch2/catch.hpp>

#include "flecsi_lite/io/ascii_columns.hh"
#include "flecsi_lite/io/h5part_writer.hh"
#include "tests/support/collective_checks.hh"

#include <cstdlib>
#include <sstream>

using namespace flecsi_lite::io;
using namespace io_test;

namespace {
const std::vector<std::string> sph_columns{"x", "y", "z", "vx", "vy", "vz", "m", "rho", "P", "u", "h", "id"};

std::uint64_t local_count(int r) { return r == 1 ? 0 : 4 + r; }
double value_of(std::size_t column, std::uint64_t g) { return (column + 1) * 1.1 + g / 3.0; }

// Writes the SPH columns (and one more) in an order unlike splash's, for every rank's particles.
void write_sph_file(const std::string& path) {
  h5part_writer out(path);
  out.begin_step({0.3125, 40, 0.01});
  std::uint64_t first = 0;
  for (int q = 0; q < rank(); ++q) first += local_count(q);
  const std::uint64_t n = local_count(rank());
  for (std::size_t c = sph_columns.size(); c-- > 0;) {
    if (sph_columns[c] == "id") {
      std::vector<std::int64_t> id(n);
      for (std::uint64_t i = 0; i < n; ++i) id[i] = 1000000007LL * static_cast<std::int64_t>(first + i);
      out.write("id", id);
    } else {
      std::vector<double> values(n);
      for (std::uint64_t i = 0; i < n; ++i) values[i] = value_of(c, first + i);
      out.write(sph_columns[c], values);
    }
  }
  out.write("extra", std::vector<float>(n, 0.5f));
  out.end_step();
  out.close();
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> result;
  for (std::string word; in >> word;) result.push_back(word);
  return result;
}
}  // namespace

TEST_CASE("a step exports to splash's ASCII columns with exact values") {
  const std::string path = file_name("sph_columns");
  remove_files({path});
  write_sph_file(path);
  h5part_reader in(path);

  const auto columns = available_columns(in, 0, sph_columns);
  CHECK(columns == sph_columns);
  CHECK(available_columns(in, 0, {"nothing", "known"}) ==
        std::vector<std::string>{"P", "extra", "h", "id", "m", "rho", "u", "vx", "vy", "vz", "x", "y", "z"});

  std::ostringstream text;
  write_ascii_columns(in, 0, columns, text);
  std::istringstream lines(text.str());
  std::string time_line, label_line;
  std::getline(lines, time_line);
  std::getline(lines, label_line);

  // Splash reads the time as the first number after '#' on a header line that holds a '.'.
  REQUIRE(time_line.size() > 2);
  CHECK(time_line.substr(0, 2) == "# ");
  CHECK(std::strtod(time_line.c_str() + 1, nullptr) == 0.3125);
  CHECK(time_line.find('.') != std::string::npos);
  CHECK_THAT(time_line, Catch::Contains("Step#0 (iteration 40)"));

  // Labels: '#', then the names, at least four spaces apart (splash splits on runs of spaces).
  CHECK(label_line[0] == '#');
  CHECK(words(label_line.substr(1)) == columns);
  CHECK(label_line.find("   y") != std::string::npos);
  CHECK(label_line.find("    P") != std::string::npos);

  std::uint64_t rows = 0;
  for (std::string row; std::getline(lines, row); ++rows) {
    const auto fields = words(row);
    REQUIRE(fields.size() == columns.size());
    for (std::size_t c = 0; c + 1 < columns.size(); ++c)
      CHECK(std::strtod(fields[c].c_str(), nullptr) == value_of(c, rows));
    CHECK(std::strtoll(fields.back().c_str(), nullptr, 10) == 1000000007LL * static_cast<long long>(rows));
  }
  CHECK(rows == in.particle_count(0));

  CHECK_THAT(error_message<missing_dataset_error>([&] {
               write_ascii_columns(in, 0, {"x", "rhoo"}, text);
             }),
             Catch::Contains("no dataset 'rhoo'; did you mean 'rho'?"));
  CHECK_THAT(error_message<missing_step_error>([&] { write_ascii_columns(in, 3, {"x"}, text); }),
             Catch::Contains("has no step 3"));
}

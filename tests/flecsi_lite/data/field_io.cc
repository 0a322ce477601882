// Fields carry their persistence (data/persistence.hh, data/field_io.hh): writing walks the
// registered fields by role, with dataset names, padding and element types as declared; reading
// converts any numeric type, fills absent optional fields with zero or the index, and reports
// missing datasets and values that break a rule on every rank alike. On 1 and 2 ranks.
#include <catch2/catch.hpp>

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

using namespace flecsi_lite;

namespace {
// A topology whose owned size the test sets.
struct bag : data::topology_base {
  explicit bag(std::size_t n) { set_sizes(n, 0); }
};
enum class phase : std::int32_t { solid = 0, liquid = 1 };

const field<double>::definition<bag> temperature{
  "temperature", persist::output().restart().initial_required(persist::at_least(0, "temperatures"))};
const field<phase>::definition<bag> state{
  "phase", persist::output().initial_optional(persist::one_of({0, 1}, "0 for solid or 1 for liquid"))};
const field<std::array<double, 2>>::definition<bag> velocity{
  "velocity", persist::as("vx", "vy", "vz").padded().output().restart().initial_optional()};
const field<std::uint64_t>::definition<bag> label{"label", persist::output().initial_optional_index()};
const field<double>::definition<bag> memory{"memory", persist::restart()};
const field<double>::definition<bag> scratch{"scratch"};

/// Entity i of rank r has global index first + i; its values derive from it.
void fill(std::uint64_t first, field<double>::accessor<wo> t, field<phase>::accessor<wo> p,
          field<std::array<double, 2>>::accessor<wo> v, field<std::uint64_t>::accessor<wo> l,
          field<double>::accessor<wo> m, field<double>::accessor<wo> s) {
  for (std::size_t i = 0; i < t.owned_size(); ++i) {
    const double g = double(first + i);
    t(i) = 1.0 / (3.0 + g);
    p(i) = (first + i) % 2 ? phase::liquid : phase::solid;
    v(i) = {g, -g};
    l(i) = 100 + first + i;
    m(i) = g / 7.0;
    s(i) = 42;
  }
}

std::string file(const std::string& stem) { return stem + "_" + std::to_string(runtime::size()) + ".h5part"; }

/// This rank's block: rank r owns 2 + r entities after those of the lower ranks.
io::slice my_block() {
  std::uint64_t first = 0;
  for (int r = 0; r < runtime::rank(); ++r) first += 2 + r;
  return {first, std::uint64_t(2 + runtime::rank())};
}
}  // namespace

TEST_CASE("fields are written by role with their names, padding and element types", "[data][persistence]") {
  const auto block = my_block();
  bag b(block.count);
  execute<fill>(block.offset, temperature(b), state(b), velocity(b), label(b), memory(b), scratch(b));
  {
    io::h5part_writer out(file("field_io_roles"));
    out.begin_step({0.0, 0, 0.0});
    data::write_fields(b, out, data::role::output);
    out.end_step();
    out.begin_step({1.0, 1, 0.0});
    data::write_fields(b, out, data::role::output | data::role::restart);
    out.end_step();
    out.close();
  }
  const io::h5part_reader in(file("field_io_roles"));
  CHECK(in.datasets(0) == std::vector<std::string>{"label", "phase", "temperature", "vx", "vy", "vz"});
  CHECK(in.datasets(1) == std::vector<std::string>{"label", "memory", "phase", "temperature", "vx", "vy", "vz"});
  CHECK(in.dataset_type(0, "phase") == io::element_type::int32);
  CHECK(in.dataset_type(0, "label") == io::element_type::uint64);
  CHECK(in.dataset_type(0, "vz") == io::element_type::float64);
  const std::uint64_t n = in.particle_count(0);
  const auto t = in.read<double>(0, "temperature", {0, n});
  const auto p = in.read<std::int32_t>(0, "phase", {0, n});
  const auto vy = in.read<double>(0, "vy", {0, n});
  const auto vz = in.read<double>(0, "vz", {0, n});
  const auto l = in.read<std::uint64_t>(0, "label", {0, n});
  for (std::uint64_t g = 0; g < n; ++g) {
    CHECK(t[g] == 1.0 / (3.0 + double(g)));
    CHECK(p[g] == std::int32_t(g % 2));
    CHECK(vy[g] == -double(g));
    CHECK(vz[g] == 0.0);
    CHECK(l[g] == 100 + g);
  }

  // A restart reads back every restart field bitwise, into a new topology of the reader's block.
  bag restored(in.block(1).count);
  data::read_fields(restored, in, 1, data::role::restart);
  const auto first = in.block(1).offset;
  const auto rt = host_view(temperature(restored));
  const auto rv = host_view(velocity(restored));
  const auto rm = host_view(memory(restored));
  const auto rl = host_view(label(restored));
  for (std::size_t i = 0; i < restored.owned_size(); ++i) {
    CHECK(rt(i) == 1.0 / (3.0 + double(first + i)));
    CHECK(rv(i)[1] == -double(first + i));
    CHECK(rm(i) == double(first + i) / 7.0);
    CHECK(rl(i) == 0);  // output only: not restart state
  }
}

TEST_CASE("initial data: any numeric type, defaults for absent optional fields, checks", "[data][persistence]") {
  const int rank = runtime::rank(), size = runtime::size();
  const std::uint64_t total = 5;
  const auto block = io::block_slice(total, rank, size);
  std::vector<float> t(block.count);
  std::vector<std::int32_t> vx(block.count);
  std::vector<double> bad(block.count);
  for (std::size_t i = 0; i < block.count; ++i) {
    t[i] = 0.5f * float(block.offset + i);
    vx[i] = std::int32_t(block.offset + i);
    bad[i] = block.offset + i == 4 ? -1.0 : 1.0;
  }
  {
    io::h5part_writer out(file("field_io_initial"));
    out.begin_step({0.0, 0, 0.0});  // float32 temperatures, int32 vx, no vy, phase or label
    out.write("temperature", t);
    out.write("vx", vx);
    out.end_step();
    out.begin_step({0.0, 1, 0.0});  // no temperature
    out.write("vx", vx);
    out.end_step();
    out.begin_step({0.0, 2, 0.0});  // a negative temperature at index 4
    out.write("temperature", bad);
    out.end_step();
    out.close();
  }
  const io::h5part_reader in(file("field_io_initial"));
  bag b(in.block(0).count);
  data::read_fields(b, in, 0, data::role::initial);
  const auto first = in.block(0).offset;
  const auto rt = host_view(temperature(b));
  const auto rv = host_view(velocity(b));
  const auto rp = host_view(state(b));
  const auto rl = host_view(label(b));
  for (std::size_t i = 0; i < b.owned_size(); ++i) {
    CHECK(rt(i) == 0.5 * double(first + i));
    CHECK(rv(i)[0] == double(first + i));
    CHECK(rv(i)[1] == 0.0);
    CHECK(rp(i) == phase::solid);
    CHECK(rl(i) == first + i);  // absent: the index in the step
  }

  bag missing(in.block(1).count);
  CHECK_THROWS_AS(data::read_fields(missing, in, 1, data::role::initial), io::missing_dataset_error);
  bag negative(in.block(2).count);
  CHECK_THROWS_WITH(
    data::read_fields(negative, in, 2, data::role::initial),
    "'" + file("field_io_initial") + "' Step#2: particle 4 has temperature = -1 (temperatures must be >= 0)");
}

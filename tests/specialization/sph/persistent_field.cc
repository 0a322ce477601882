// A field that a specialization adds in one line, its definition with persistence (output and
// restart), reaches every output step and survives a checkpoint and restart bitwise: no list of
// datasets anywhere names it (flecsi_lite/data/persistence.hh, field_io.hh). The field evolves
// in a task the test places in the SPH step, so a restart that lost it would end elsewhere.
// On 1 and 2 ranks.
#include "sph_setup.hh"

#include "specialization/sph/files/particle_output.hh"
#include "specialization/sph/run/restart.hh"

#include "flecsi_lite/data.hh"
#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace {
using namespace sph_test;
constexpr int D = 2;

// The test specialization: the SPH fields and a passive tracer, added by this one line.
struct tracer_fields : sph::fields<D> {
  static inline const definition<double> tracer{"tracer", sph::persist::output().restart()};
};

/// The initial tracer of particle `id`: a value whose bits a lossy copy would change.
double label_of(std::uint64_t id) { return 1.0 / (3.0 + double(id)); }

/// The tracer decays at rate 1: tracer *= exp(-dt) in every step, so tracer = label exp(-t).
void decay(double dt, sph::rw<double> tracer) {
  const double factor = std::exp(-dt);
  for (std::size_t i = 0; i < tracer.owned_size(); ++i) tracer(i) *= factor;
}

void label(flecsi_lite::field<std::uint64_t>::accessor<flecsi_lite::ro> id,
           flecsi_lite::field<double>::accessor<flecsi_lite::wo> tracer) {
  for (std::size_t i = 0; i < id.owned_size(); ++i) tracer(i) = label_of(id(i));
}

struct tracer_run : sph::simulation<D> {
  std::string checkpoint;  ///< written after step checkpoint_step (when set)
  long checkpoint_step = -1;
};

constexpr long steps = 8, checkpoint_step = 4;
const lattice shape{10, true, 1.0, 1.0, 0.2, 0.3, 0.3};

void set_unit_box(tracer_run& s) {
  tree::box<D> unit;
  unit.lo.fill(0.0);
  unit.hi.fill(1.0);
  s.tree_settings.fixed_box = unit;
  s.tree_settings.periodic.fill(true);
}

/// Runs `s` to step `steps` from what `initial_data` makes, writing the checkpoint on the way
/// when asked, and then one output step to `output`.
template<class InitialData>
void run(tracer_run& s, InitialData initial_data, const std::string& output) {
  s.physics.eos.ideal.gamma = 1.4;
  s.run.end_time = 1.0;
  s.run.max_steps = steps;
  s.run.progress_every = 0;
  s.run.diagnostics_every = 0;
  auto m = sph::make_control_model<tracer_run>();
  m.action("initial_data", "tracer_particles", initial_data);
  m.action("advance", "tracer_decay",
           [](tracer_run& state) { flecsi_lite::execute<decay>(state.dt, tracer_fields::tracer(*state.particles)); })
    .after("kick");
  m.action("output", "tracer_checkpoint", [](tracer_run& state) {
    if (state.step == state.checkpoint_step) sph::write_restart_checkpoint(state, state.checkpoint, {});
  });
  m.run(s);
  flecsi_lite::io::h5part_writer out(output);
  sph::write_particles(out, s);
  out.close();
}

/// Every particle's value of dataset `name` in the last step of `path`, by id.
template<class T>
std::map<std::uint64_t, T> by_id(const std::string& path, const std::string& name) {
  const flecsi_lite::io::h5part_reader in(path);
  const auto step = in.last_step();
  const flecsi_lite::io::slice all{0, in.particle_count(step)};
  const auto ids = in.read<std::uint64_t>(step, "id", all);
  const auto values = in.read<T>(step, name, all);
  std::map<std::uint64_t, T> result;
  for (std::size_t i = 0; i < ids.size(); ++i) result[ids[i]] = values[i];
  return result;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }
}  // namespace

TEST_CASE("a field added in one line reaches the output and survives a restart bitwise", "[sph][persistence]") {
  const std::string ranks = std::to_string(flecsi_lite::runtime::size());
  const std::string checkpoint = "persistent_field_checkpoint_" + ranks + ".h5part";
  const std::string full = "persistent_field_full_" + ranks + ".h5part";
  const std::string restarted = "persistent_field_restarted_" + ranks + ".h5part";

  tracer_run writing;
  writing.checkpoint = checkpoint;
  writing.checkpoint_step = checkpoint_step;
  run(
    writing,
    [](tracer_run& s) {
      load_lattice(s, shape);
      flecsi_lite::execute<label>(tracer_fields::id()(*s.particles), tracer_fields::tracer(*s.particles));
    },
    full);
  REQUIRE(writing.step == steps);

  tracer_run continuing;
  run(
    continuing,
    [&](tracer_run& s) {
      set_unit_box(s);
      sph::read_restart_checkpoint(s, checkpoint);
      REQUIRE(s.step == checkpoint_step);
    },
    restarted);
  REQUIRE(continuing.step == steps);

  // The output and the checkpoint hold the tracer, as doubles, and every particle kept its own
  // (the particles were distributed again and again on the way): label exp(-t), to the rounding
  // of one product per step.
  const flecsi_lite::io::h5part_reader output(full), saved(checkpoint);
  CHECK(output.dataset_type(output.last_step(), "tracer") == flecsi_lite::io::element_type::float64);
  CHECK(saved.has_dataset(0, "tracer"));
  const auto expect_decayed = [](const std::map<std::uint64_t, double>& tracers, double time) {
    REQUIRE(tracers.size() == std::size_t(shape.per_side * shape.per_side));
    REQUIRE(time > 0);
    for (const auto& [id, value] : tracers) CHECK(value == Approx(label_of(id) * std::exp(-time)).epsilon(1e-14));
  };
  expect_decayed(by_id<double>(full, "tracer"), output.step_information(output.last_step()).time);
  expect_decayed(by_id<double>(checkpoint, "tracer"), saved.step_information(0).time);

  // The restarted run ends where the writing run ends, bit for bit: the tracer and every other
  // dataset of the final step.
  const flecsi_lite::io::h5part_reader again(restarted);
  REQUIRE(again.datasets(again.last_step()) == output.datasets(output.last_step()));
  for (const auto& name : output.datasets(output.last_step())) {
    if (output.dataset_type(output.last_step(), name) != flecsi_lite::io::element_type::float64) continue;
    const auto a = by_id<double>(full, name), b = by_id<double>(restarted, name);
    REQUIRE(a.size() == b.size());
    std::size_t differing = 0;
    for (const auto& [id, value] : a) differing += !same_bits(value, b.at(id));
    INFO("dataset " << name);
    CHECK(differing == 0);
  }
  CHECK(again.step_information(again.last_step()).time == output.step_information(output.last_step()).time);
}

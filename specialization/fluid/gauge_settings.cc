// The gauges' keys (gauge_settings.hh).
#include "specialization/fluid/gauge_settings.hh"

namespace flecsph::fluid {

namespace rt = flecsi_lite::runtime;

namespace {
rt::parameter_block<gauge_settings> declare() {
  rt::parameter_block<gauge_settings> p;
  p.real_list("gauges", &gauge_settings::coordinates,
              "gauge faces x1, y1, x2, y2 (units of length; a point: x, y, x, y), one group of 4 per gauge");
  p.integer("gauge_samples", &gauge_settings::samples, "points sampled along a gauge's face").range(1, 1000);
  p.file("gauge_file", &gauge_settings::file,
         "CSV of the surge front and the gauges' pressure and velocity (auto: <output stem>.gauges.csv; none: off)");
  p.integer("gauge_every", &gauge_settings::every, "steps between rows of gauge_file").at_least(1);
  p.real("front_height", &gauge_settings::front_height,
         "surge front: fluid at most this far above the floor (units of length)")
    .greater_than(0)
    .at_most(1e10);
  p.real("gauge_smoothing", &gauge_settings::smoothing,
         "gauges: the interpolation's smoothing length in units of each particle's h (1: the SPH field)")
    .at_least(1)
    .at_most(10);
  p.check([](const gauge_settings& s) {
    if (s.coordinates.size() % 4 != 0)
      throw rt::parameter_error("gauges: " + std::to_string(s.coordinates.size()) +
                                " numbers, not groups of 4 (x1, y1, x2, y2 per gauge)");
    if (!s.coordinates.empty() && s.file.empty())
      throw rt::parameter_error("gauges: " + std::to_string(s.coordinates.size() / 4) +
                                " gauges given but gauge_file = none: set gauge_file (auto: <output stem>.gauges.csv)");
  });
  return p;
}
}  // namespace

std::vector<gauge_face> gauge_settings::faces() const {
  std::vector<gauge_face> out;
  for (std::size_t i = 0; i + 3 < coordinates.size(); i += 4)
    out.push_back({{coordinates[i], coordinates[i + 1]}, {coordinates[i + 2], coordinates[i + 3]}});
  return out;
}

const rt::parameter_block<gauge_settings>& gauge_parameters() {
  static const auto block = declare();
  return block;
}

}  // namespace flecsph::fluid

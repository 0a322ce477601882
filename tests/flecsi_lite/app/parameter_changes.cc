// Restarts and parameters: two resolved parameter texts compared key by key, the free keys left
// aside, and the error that names every other differing key with both values.
#include <catch2/catch.hpp>

#include "flecsi_lite/app/parameter_changes.hh"
#include "flecsi_lite/runtime/parameters.hh"

#include <string>

using namespace flecsi_lite;

namespace {
const std::string written =
  "# resolved parameters (run.par)\n"
  "gamma = 1.4            # run.par:2\n"
  "kernel = \"cubic # spline\"  # default\n"
  "end_time = 0.2         # run.par:3\n"
  "output_file = \"a.h5part\" # run.par:4\n";

std::string message_of(const std::string& now, const std::string& allowed) {
  try {
    app::require_same_parameters("c.h5part", written, now, app::frame_free_keys(), allowed);
  } catch (const runtime::parameter_error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("parameter texts are read as key and value, quoted strings whole") {
  const auto values = app::parameter_values(written);
  CHECK(values.size() == 4);
  CHECK(values.at("gamma") == "1.4");
  CHECK(values.at("kernel") == "\"cubic # spline\"");
  CHECK(values.at("output_file") == "\"a.h5part\"");
}

TEST_CASE("a restart may change the free keys, and others only when allowed") {
  const std::string same_physics =
    "gamma = 1.4 # other origin\nkernel = \"cubic # spline\"\n"
    "end_time = 0.2\noutput_file = \"b.h5part\"\n";
  CHECK(message_of(same_physics, "none").empty());  // output_file is free, origins do not count
  const std::string changed =
    "gamma = 1.6666666666666667\nkernel = \"wendland\"\nend_time = 0.2\n"
    "output_file = \"b.h5part\"\n";
  const std::string message = message_of(changed, "none");
  CHECK(message.find("'c.h5part'") != std::string::npos);
  CHECK(message.find("gamma: checkpoint 1.4, this run 1.6666666666666667") != std::string::npos);
  CHECK(message.find("kernel: checkpoint \"cubic # spline\", this run \"wendland\"") != std::string::npos);
  CHECK(message.find("output_file") == std::string::npos);
  const std::string only_kernel = message_of(changed, "gamma");
  CHECK(only_kernel.find("kernel") != std::string::npos);
  CHECK(only_kernel.find("gamma:") == std::string::npos);
  CHECK(message_of(changed, "gamma, kernel").empty());
  CHECK(message_of(changed, "all").empty());
  CHECK(message_of(same_physics, "gamam").find("allow_parameter_changes names 'gamam'") != std::string::npos);
  // end_time is not the frame's: without the app's free keys it counts.
  CHECK(message_of(same_physics + "end_time = 0.4\n", "none").find("end_time: checkpoint 0.2, this run 0.4") !=
        std::string::npos);
}

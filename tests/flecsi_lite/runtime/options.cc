// Options parsing: values, flags, repeats, positionals, and misspelled options.
#include <catch2/catch.hpp>

#include "flecsi_lite/runtime/options.hh"

using flecsi_lite::runtime::options;
using flecsi_lite::runtime::options_error;

namespace {
options make() {
  options o("test");
  o.flag("verbose", "talk").value("steps", "N", "steps", "10").repeated("set", "K=V", "override");
  o.positional("parameters", "parameter file");
  return o;
}
}  // namespace

TEST_CASE("options parse values, flags, repeats and positionals") {
  auto o = make();
  const char* argv[] = {"prog", "--steps=5", "--set", "a=1", "file.par", "--set=b=2", "--verbose"};
  o.parse(7, argv);
  CHECK(o.get("steps") == "5");
  CHECK(o.has("verbose"));
  CHECK(o.all("set") == std::vector<std::string>{"a=1", "b=2"});
  CHECK(o.get("parameters") == "file.par");
}

TEST_CASE("options use defaults and report missing positionals") {
  auto o = make();
  const char* argv[] = {"prog"};
  CHECK_THROWS_WITH(o.parse(1, argv), Catch::Contains("missing argument <parameters>"));
  CHECK(o.get("steps") == "10");
}

TEST_CASE("a misspelled option names the nearest valid one") {
  auto o = make();
  const char* argv[] = {"prog", "--stpes", "3", "f"};
  CHECK_THROWS_WITH(o.parse(4, argv), Catch::Contains("did you mean '--steps'"));
  const char* argv2[] = {"prog", "--steps"};
  CHECK_THROWS_WITH(make().parse(2, argv2), Catch::Contains("needs a value"));
}

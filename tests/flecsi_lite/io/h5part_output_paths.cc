// Paths the writers never destroy: an existing output or checkpoint path that is a folder, a
// symbolic link, a fifo or a device is refused before anything is written (no partial file, the
// link's target untouched), and finish() completes a file that replaces the earlier one only at
// commit().
#include <catch2/catch.hpp>

#include "flecsi_lite/io/checkpoint.hh"
#include "flecsi_lite/io/h5part_reader.hh"
#include "flecsi_lite/io/h5part_writer.hh"
#include "flecsi_lite/io/output_path.hh"
#include "tests/support/collective_checks.hh"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace flecsi_lite::io;
using namespace io_test;
namespace fs = std::filesystem;

namespace {
std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Rank 0 writes `text` to `path`; every rank returns after that.
void write_text(const std::string& path, const std::string& text) {
  if (rank() == 0) std::ofstream(path, std::ios::binary) << text;
  barrier();
}

void write_one_step(h5part_writer& out, double value) {
  out.begin_step({0, 0, 1});
  out.write("x", std::vector<double>(rank() + 1, value));
  out.end_step();
}

// The writer's constructor throws file_error naming `path` and `kind`, on every rank.
void require_refused(const std::string& path, const std::string& kind) {
  CHECK_THROWS_WITH(h5part_writer(path),
                    Catch::Contains("'" + path + "' exists and is " + kind + ", not a regular file"));
  CHECK_THROWS_AS(h5part_writer(path), file_error);
  CHECK_FALSE(fs::exists(fs::symlink_status(path + ".partial")));
}
}  // namespace

TEST_CASE("paths that are not regular files are named by what they are") {
  const std::string folder = file_name("kinds", ".folder"), link = file_name("kinds", ".link");
  if (rank() == 0) {
    fs::remove_all(folder);
    fs::remove(link);
    fs::create_directory(folder);
    fs::create_symlink("nowhere", link);
  }
  barrier();
  CHECK(non_regular_kind(folder) == "a directory");
  CHECK(non_regular_kind(link) == "a symbolic link");  // even when it points nowhere
  CHECK(non_regular_kind(file_name("kinds_absent")).empty());
  CHECK(unwritable_folder_reason(folder + "/x.h5part").empty());
  CHECK(unwritable_folder_reason("kinds_no_folder/x.h5part") == "its folder 'kinds_no_folder' does not exist");
  CHECK_THROWS_AS(require_writable_folder("kinds_no_folder/x.h5part", "output"), file_error);
  CHECK_THROWS_WITH(require_replaceable(folder, "output"), Catch::StartsWith("output '" + folder + "' exists"));
  if (fs::exists("/dev/null")) CHECK(non_regular_kind("/dev/null") == "a character device");
}

TEST_CASE("the writer refuses a folder, a symbolic link, a fifo and a device before writing") {
  const std::string folder = file_name("refused", ".folder"), link = file_name("refused_link"),
                    target = file_name("refused_target"), fifo = file_name("refused_fifo");
  if (rank() == 0) {
    fs::remove_all(folder);
    fs::remove(link);
    fs::remove(fifo);
    fs::create_directory(folder);
    fs::create_symlink(target, link);
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  }
  write_text(target, "an earlier run's file");
  require_refused(folder, "a directory");
  require_refused(link, "a symbolic link");
  require_refused(fifo, "a fifo");
  if (fs::exists("/dev/full")) {
    CHECK_THROWS_WITH(h5part_writer("/dev/full"), Catch::Contains("is a character device"));
    CHECK(fs::is_character_file("/dev/full"));
  }
  // A checkpoint goes through the same writer.
  CHECK_THROWS_AS(write_checkpoint(folder, {0, 0, 1}, {}, [](h5part_writer&) {}), file_error);
  CHECK(fs::is_directory(folder));
  CHECK(fs::is_symlink(link));
  CHECK(contents(target) == "an earlier run's file");
}

TEST_CASE("the writer refuses a temporary path that is a symbolic link (HDF5 would follow it)") {
  const std::string path = file_name("partial_link"), target = file_name("partial_link_target");
  remove_files({path});
  if (rank() == 0) fs::create_symlink(target, path + ".partial");
  write_text(target, "not to be overwritten");
  CHECK_THROWS_WITH(h5part_writer(path),
                    Catch::Contains("temporary file '" + path + ".partial' exists and is a symbolic link"));
  CHECK(contents(target) == "not to be overwritten");
  CHECK_FALSE(fs::exists(path));
  remove_files({path});
}

TEST_CASE("finish() completes the file, commit() alone replaces the earlier one") {
  const std::string path = file_name("deferred");
  remove_files({path});
  write_text(path, "the earlier output");
  {
    h5part_writer out(path);
    write_one_step(out, 4.0);
    out.finish();
    CHECK(out.awaits_commit());
    CHECK(contents(path) == "the earlier output");
    // Destroyed without commit (the run's checks failed): both files stay.
  }
  CHECK(contents(path) == "the earlier output");
  {
    h5part_reader partial(path + ".partial");
    CHECK(partial.steps() == std::vector<std::int64_t>{0});
  }
  {
    h5part_writer out(path);
    write_one_step(out, 5.0);
    out.finish();
    out.commit();
    CHECK_FALSE(out.awaits_commit());
  }
  CHECK_FALSE(fs::exists(path + ".partial"));
  h5part_reader in(path);
  const auto x = in.read<double>(0, "x");
  CHECK(std::all_of(x.begin(), x.end(), [](double v) { return v == 5.0; }));
}

TEST_CASE("commit() refuses a final path that became a symbolic link during the run") {
  const std::string path = file_name("became_link"), target = file_name("became_link_target");
  remove_files({path});
  write_text(target, "kept");
  h5part_writer out(path);
  write_one_step(out, 1.0);
  out.finish();
  if (rank() == 0) fs::create_symlink(target, path);
  barrier();
  CHECK_THROWS_WITH(out.commit(), Catch::Contains("'" + path + "' exists and is a symbolic link"));
  CHECK(fs::is_symlink(path));
  CHECK(contents(target) == "kept");
  CHECK(fs::exists(path + ".partial"));
}

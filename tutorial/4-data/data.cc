// Tutorial chapter 4: the data model on the narray topology. A field is defined once per topology
// type and stored on every instance; each rank holds its OWNED entities and, around them, GHOST
// copies of its neighbours' entities. A task that reads ghosts (accessor<ro, ro>) after their
// owners changed makes the executor insert a ghost copy before it; nobody calls a copy by hand.
//
//   mpirun -np 2 tutorial_4_data
#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime.hh"
#include "flecsi_lite/topology/narray.hh"

#include <mpi.h>

#include <cstdint>

using namespace flecsi_lite;
using topology::narray;

namespace {
// Defined at namespace scope, once: the field "u" exists on every narray.
const field<double>::definition<narray> u{"u"};

// Owned values only (ghost privilege na by default): f(i), i < f.owned_size().
void set_owned(const narray& mesh, field<double>::accessor<wo> f, double scale) {
  forall(f.size(), [&](std::size_t i) { f(i) = scale * double(mesh.global_index(i)); });
}
// Owned and ghost values read: ghosts are local indices [owned_size(), size()), and
// mesh.neighbor(i, offset) maps an owned entity's neighbour to its local index.
bool ghosts_match(const narray& mesh, field<double>::accessor<ro, ro> f, double scale) {
  bool match = true;
  for (std::size_t i = f.owned_size(); i < f.size(); ++i) match &= f(i) == scale * double(mesh.global_index(i));
  for (std::size_t i = 0; i < f.owned_size(); ++i) {  // the periodic neighbours, through ghosts
    const std::size_t left = mesh.global_index(mesh.neighbor(i, -1));
    match &= left == (mesh.global_index(i) + mesh.global_size() - 1) % mesh.global_size();
  }
  return match;
}
bool all_ranks(bool mine) {
  int in = mine, out = 0;
  MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LAND, runtime::communicator());
  return out;
}
std::uint64_t copies() { return execution::executor::instance().ghost_copies_started(); }
}  // namespace

int main(int argc, char** argv) {
  runtime::runtime rt(argc, argv, runtime::options("Tutorial 4: fields, owned and ghost entities, ghost copies."));
  if (!rt.proceed()) return rt.exit_code();
  // 64 cells over the ranks in contiguous blocks, one ghost on each side, periodic.
  narray mesh(64, 1, true);
  log::info() << "rank 0 owns " << mesh.owned_size() << " cells from " << mesh.first_global() << " and holds "
              << mesh.ghost_size() << " ghosts";

  const std::uint64_t before = copies();
  execute<set_owned>(mesh, u(mesh), 1.0);  // owned values change: ghosts are stale
  bool correct = all_ranks(execute<ghosts_match>(mesh, u(mesh), 1.0).get());
  correct &= copies() == before + 1;                // the executor copied the ghosts once
  execute<ghosts_match>(mesh, u(mesh), 1.0).get();  // still current: no second copy
  correct &= copies() == before + 1;
  execute<set_owned>(mesh, u(mesh), 2.0);  // owners change again: the next read copies
  correct &= all_ranks(execute<ghosts_match>(mesh, u(mesh), 2.0).get());
  correct &= copies() == before + 2;
  correct &= mesh.ghost_size() == 2 && mesh.total_size() == mesh.owned_size() + 2;

  // Outside tasks, host_view waits for every pending launch and shows the values (for checks and
  // output only: computing belongs in tasks).
  auto view = host_view(u(mesh));
  for (std::size_t i = 0; i < mesh.owned_size(); ++i) correct &= view(i) == 2.0 * double(mesh.global_index(i));
  correct = all_ranks(correct);
  log::info() << "ghost copies inserted by the executor: " << copies() - before;
  if (!correct) log::error() << "tutorial 4: wrong ghost values or copy count";
  return correct ? 0 : 1;
}

// Build of the distributed gravity tree (locally essential trees, Warren & Salmon 1993): the local
// tree of the owned particles split as the global tree T splits, the shared top tree, this rank's
// target groups of T and the imports its walks need (gravity_top_tree.cc, gravity_essential.cc).
#include "flecsi_lite/topology/ntree/gravity/gravity_tree.hh"

namespace flecsi_lite::topology::ntree {

template<int D>
void gravity_tree<D>::build(const key_type* keys, const point<D>* x, const double* m, const double* h,
                            const double* acceleration_old, std::size_t n, const gravity_options& options,
                            MPI_Comm comm) {
  int size = 1, rank = 0;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  options_ = options;
  owned_x_.assign(x, x + n);
  owned_m_.assign(m, m + n);
  owned_h_.assign(h, h + n);
  tree_options tree;
  tree.bucket_size = options.bucket_size;
  tree.quadrupole = options.quadrupole;
  imported_nodes_ = imported_particles_ = top_nodes_ = 0;
  essential_ = detail::essential_sources<D>{};
  const detail::top_tree<D> no_top;
  const detail::straddling_cells no_cells;
  if (size == 1) {
    // T is the local tree.
    local_only_ = true;
    local_.build(keys, owned_x_.data(), owned_m_.data(), owned_h_.data(), n, tree);
    groups_ = detail::essential_groups<D>(no_top, local_, no_cells, acceleration_old, options.group_size, rank);
    return;
  }
  local_only_ = false;
  // A node straddling ranks is split by its global count, every other by its count here (all
  // of its particles are here): the local tree is T restricted to this rank's particles.
  detail::straddling_cells cells;
  cells.find<D>(keys, acceleration_old, n, options.bucket_size, comm);
  const std::size_t bucket = options.bucket_size;
  local_.build(keys, owned_x_.data(), owned_m_.data(), owned_h_.data(), n, tree,
               [&cells, bucket](const tree_node<D>& node) {
                 const std::size_t i = cells.index(node.key);
                 return i == detail::straddling_cells::npos ? node.size() > bucket : cells[i].split;
               });
  const detail::top_tree<D> top = detail::build_top_tree<D>(local_, cells, options.quadrupole, rank, comm);
  top_nodes_ = top.nodes.size();
  groups_ = detail::essential_groups<D>(top, local_, cells, acceleration_old, options.group_size, rank);
  detail::assemble_essential_tree<D>(top, local_, groups_, options, rank, comm, essential_);
  imported_nodes_ = essential_.imported_nodes;
  imported_particles_ = essential_.imported_particles;
}

template<int D>
gravity_sources<D> gravity_tree<D>::sources() const {
  if (local_only_) return gravity_sources_of<D>(local_);
  gravity_sources<D> view;
  view.nodes = essential_.nodes.data();
  view.node_count = essential_.nodes.size();
  view.quadrupoles = essential_.quadrupoles.empty() ? nullptr : essential_.quadrupoles.data();
  view.x = essential_.x.data();
  view.m = essential_.m.data();
  view.h = essential_.h.data();
  return view;
}

template class gravity_tree<1>;
template class gravity_tree<2>;
template class gravity_tree<3>;

}  // namespace flecsi_lite::topology::ntree

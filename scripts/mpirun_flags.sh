# Sourced by the scripts: the mpirun flags this machine needs (Open MPI refuses to run as root
# or to oversubscribe cores unless told).
FLECSPH_MPIRUN_FLAGS=()
if mpirun --version 2>/dev/null | grep -q "Open MPI"; then
  FLECSPH_MPIRUN_FLAGS+=(--oversubscribe)
  [ "$(id -u)" -eq 0 ] && FLECSPH_MPIRUN_FLAGS+=(--allow-run-as-root)
  export OMPI_MCA_btl_vader_single_copy_mechanism=none
fi

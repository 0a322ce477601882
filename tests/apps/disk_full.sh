#!/bin/sh
# A checkpoint or output written to a full disk: the app must exit with status 3 (not crash in
# HDF5's clean-up at MPI_Finalize) and leave the earlier complete file of that name byte for byte.
# The disk is a small tmpfs in a private mount namespace (unshare -m: no mount outlives the test),
# of several sizes, so that it fills at different points: in a dataset, in the metadata flush;
# where this shell may not make one (not root), the test is skipped (exit status 77). A file-size
# limit (ulimit -f) is no substitute: Open MPI's start-up files need more than the limit allows.
#
#   disk_full.sh KEY NAME MPIEXEC -n 2 FLAGS... -- APP ARGS...   (KEY: checkpoint_file or output_file)
set -u
key=$1 name=$2
shift 2
launcher=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do launcher="$launcher $1"; shift; done
shift
here=$(cd "$(dirname "$0")" && pwd)
folder=disk_full_$name
rm -rf "$folder" && mkdir -p "$folder"
target=$folder/earlier_$key.h5part
# The run: big enough (60000 particles, ~6 MB per file) to fill the disk.
run="exec $* --set particles=60000 --set end_time=0.001 --set $key=$target"
if [ "$key" = checkpoint_file ]; then run="$run --set checkpoint_every=1 --set output_file=none"; fi
if ! unshare -m true 2>/dev/null; then
  echo "disk_full.sh: cannot make a private tmpfs here (needs root): skipped"
  exit 77
fi
for size in 1m 2m 3m 4m; do
  echo "--- a disk of $size"
  rm -f "$target"
  unshare -m sh -c "mount -t tmpfs -o size=$size tmpfs '$folder' || exit 77
    exec sh '$here/expect_failure.sh' 3 '$target' \"cannot (write dataset .*|flush '$target.partial')\" -- $launcher sh -c \"$run\""
  code=$?
  [ "$code" -eq 0 ] || exit "$code"
done

#!/bin/sh
# A --trace file written to a full disk (issue 38, item 1: it used to be lost without a word): the
# trace is written beside and renamed, so the run says that it was not written, the earlier trace
# of that name stays byte for byte and no .partial is left. The disk is a 1 MB tmpfs in a private
# mount namespace (as disk_full.sh), filled before the run; skipped (77) where it cannot be made.
#
#   trace_disk_full.sh MPIEXEC -n RANKS FLAGS... -- APP ARGS...
set -u
launcher=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do launcher="$launcher $1"; shift; done
shift
folder=trace_disk_full
rm -rf "$folder" && mkdir -p "$folder"
if ! unshare -m true 2>/dev/null; then
  echo "trace_disk_full.sh: cannot make a private tmpfs here (needs root): skipped"
  exit 77
fi
# Inside the namespace: the earlier trace, then zeros until the disk is full, then the run.
unshare -m sh -c "mount -t tmpfs -o size=1m tmpfs '$folder' || exit 77
  echo 'an earlier trace' >'$folder/trace.json'
  dd if=/dev/zero of='$folder/filler' bs=4k 2>/dev/null
  output=\$($launcher $* --set output_file=none --set checkpoint_file=none --set max_steps=2 --trace '$folder/trace.json' 2>&1)
  code=\$?
  echo \"\$output\"
  echo \"exit status: \$code\"
  fail=0
  echo \"\$output\" | grep -q \"the --trace file '$folder/trace.json' was not written: cannot write '$folder/trace.json.partial'\" ||
    { echo 'FAIL: no message saying that the trace was not written'; fail=1; }
  [ \"\$(cat '$folder/trace.json')\" = 'an earlier trace' ] || { echo 'FAIL: the earlier trace changed'; fail=1; }
  [ ! -e '$folder/trace.json.partial' ] || { echo 'FAIL: a .partial trace is left'; fail=1; }
  exit \$fail"

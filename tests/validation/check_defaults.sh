#!/bin/sh
# The app without a parameter file runs the problem of its shipped parameter file: every used
# parameter has the same value (output_file aside) and the final particles are bitwise equal.
#   check_defaults.sh NAME COMPARE_H5PART APP PARAMETER_FILE [--set ...]
set -eu
name=$1 compare=$2 app=$3 file=$4
shift 4
rm -f "${name}_defaults.h5part" "${name}_file.h5part" "${name}_defaults.used.par" "${name}_file.used.par"
"$app" "$@" --set "output_file=${name}_defaults.h5part" --no-timers > /dev/null
"$app" "$file" "$@" --set "output_file=${name}_file.h5part" --no-timers > /dev/null
values() { sed 's/ *#.*//' "$1" | grep -v '^output_file' | grep -v '^$'; }
values "${name}_defaults.used.par" > "${name}_defaults.values"
values "${name}_file.used.par" > "${name}_file.values"
test "$(wc -l < "${name}_file.values")" -gt 20
if ! diff "${name}_defaults.values" "${name}_file.values"; then
  echo "$name: the defaults (<) differ from $file (>)"
  exit 1
fi
"$compare" "${name}_defaults.h5part" "${name}_file.h5part"

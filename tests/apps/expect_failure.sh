#!/bin/sh
# Runs a command that must fail: a non-zero exit status (exactly STATUS unless it is "any"), output
# matching every extended REGEX given, and the file KEEP (when not "-") unchanged: bad input must
# never lose or corrupt what an earlier run wrote.
#
#   expect_failure.sh STATUS KEEP REGEX... -- COMMAND ARGS...
set -u
status=$1 keep=$2
shift 2
patterns=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  patterns="$patterns$1
"
  shift
done
[ $# -gt 0 ] || { echo "expect_failure.sh: no command after --" >&2; exit 2; }
shift

if [ "$keep" != "-" ]; then
  echo "written by an earlier run" >"$keep"
  before=$(cksum <"$keep")
fi
output=$("$@" 2>&1)
code=$?
echo "$output"
echo "exit status: $code"
fail=0
if [ "$code" -eq 0 ]; then
  echo "FAIL: the command succeeded"; fail=1
elif [ "$status" != "any" ] && [ "$code" -ne "$status" ]; then
  echo "FAIL: exit status $code, expected $status"; fail=1
fi
printf '%s' "$patterns" | while IFS= read -r pattern; do
  printf '%s\n' "$output" | grep -Eq -- "$pattern" || { echo "FAIL: no output matches '$pattern'"; exit 1; }
done || fail=1
if [ "$keep" != "-" ]; then
  if [ ! -f "$keep" ] || [ "$(cksum <"$keep")" != "$before" ]; then
    echo "FAIL: $keep was changed or removed"; fail=1
  fi
fi
exit $fail

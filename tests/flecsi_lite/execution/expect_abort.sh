#!/bin/sh
# expect_abort.sh REGEX COMMAND...: COMMAND must exit with a non-zero status and print REGEX
# (stdout or stderr). The test's TIMEOUT catches a hang.
pattern=$1
shift
output=$("$@" 2>&1)
status=$?
printf '%s\n' "$output"
if [ "$status" -eq 0 ]; then echo "expect_abort: the command succeeded"; exit 1; fi
if ! printf '%s\n' "$output" | grep -Eq "$pattern"; then echo "expect_abort: no line matches '$pattern'"; exit 1; fi
echo "expect_abort: status $status and the message: as expected"

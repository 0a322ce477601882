#!/usr/bin/env bash
# Formats the project's C++ files with clang-format 14 and the root .clang-format.
#   scripts/format.sh            rewrite every C++ file in place
#   scripts/format.sh --check    list the files that are not formatted and exit 1 (test layout.format)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$here"
format=$(command -v clang-format-14 || command -v clang-format || true)
[ -n "$format" ] || { echo "format.sh: clang-format not found (Debian package clang-format)"; exit 2; }
if git rev-parse --git-dir >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files --cached --others --exclude-standard -- '*.cc' '*.hh')
else
  mapfile -t files < <(find apps benchmarks flecsi_lite specialization tests tutorial -name '*.cc' -o -name '*.hh')
fi
if [ "${1:-}" = --check ]; then
  bad=()
  for f in "${files[@]}"; do
    [ -f "$f" ] || continue
    "$format" --dry-run -Werror "$f" >/dev/null 2>&1 || bad+=("$f")
  done
  if ((${#bad[@]})); then
    printf 'format.sh: not formatted (run scripts/format.sh):\n'; printf '  %s\n' "${bad[@]}"; exit 1
  fi
  echo "format.sh: ${#files[@]} C++ files formatted"
else
  for f in "${files[@]}"; do [ -f "$f" ] && "$format" -i "$f"; done
fi

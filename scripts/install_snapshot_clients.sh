#!/usr/bin/env bash
# Installs, idempotently, the snapshot readers the client tests load our snapshots with
# (tests/clients/check_snapshots.py --client swiftsimio|yt|pynbody): swiftsimio, yt, pynbody and
# unyt from PyPI at exactly the versions of scripts/snapshot-clients.txt, in a venv of
# /usr/bin/python3 (Debian's, whose python3-venv scripts/install_deps.sh installs with
# FLECSPH_INSTALL_CLIENTS=1) at .deps/snapshot-clients: about 250 MB to download, 900 MB on disk,
# 3 minutes; a second run checks one file and installs nothing. scripts/build.sh runs it in the
# background while the code builds.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
requirements="$here/scripts/snapshot-clients.txt"
venv="$here/.deps/snapshot-clients"
# The copy of the requirements is written last: an interrupted install is redone from scratch,
# never used half-made.
if cmp -s "$requirements" "$venv/installed-requirements.txt"; then
  echo "install-snapshot-clients: snapshot readers already in $venv"
  exit 0
fi
echo "install-snapshot-clients: installing swiftsimio, yt, pynbody and unyt into $venv"
rm -rf "$venv"
mkdir -p "$here/.deps"
/usr/bin/python3 -m venv "$venv"
"$venv/bin/python" -m pip install --quiet --no-cache-dir --disable-pip-version-check -r "$requirements"
cp "$requirements" "$venv/installed-requirements.txt"
echo "install-snapshot-clients: done"

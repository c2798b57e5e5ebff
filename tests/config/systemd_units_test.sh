#!/usr/bin/env bash
# systemd_units_test.sh SOURCE_DIR BUILD_DIR: the unit files of config/systemd, with their install
# paths (/opt/vsl, /opt/vsl/build) pointed at this checkout and build, pass `systemd-analyze
# verify` (unit syntax, executables present, the target's dependencies resolve).
set -euo pipefail
src=${1:?source dir}
build=${2:?build dir}
command -v systemd-analyze >/dev/null || { echo "systemd-analyze not found (Debian package systemd)"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for unit in "$src"/config/systemd/*.service "$src"/config/systemd/*.target; do
  sed -e "s|/opt/vsl/build|$build|g" -e "s|/opt/vsl|$src|g" "$unit" >"$tmp/$(basename "$unit")"
done
for exe in $(sed -n 's/^ExecStart=\([^ ]*\).*/\1/p' "$tmp"/*.service); do
  [ -x "$exe" ] || { echo "not built: $exe"; exit 1; }
done
out=$(cd "$tmp" && systemd-analyze verify ./*.service ./*.target 2>&1 || true)
if [ -n "$out" ]; then
  echo "$out"
  exit 1
fi
echo "ok: $(ls "$tmp" | wc -l) unit files verify"

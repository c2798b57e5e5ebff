#!/usr/bin/env bash
# spy_decodes_log.sh TYPES_JAR LOG: lcm-spy (tools/vsl-spy's class path) under Xvfb decodes every
# channel of a recorded session (SpyDecodeCheck.java beside this file). Run from the source root.
set -euo pipefail
jar=${1:?types jar}
log=${2:?log file}
classpath=$(VSL_TYPES_JAR="$jar" tools/vsl-spy --classpath)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
javac -d "$tmp" -cp "$classpath" tests/pipeline/SpyDecodeCheck.java
# xvfb-run -a takes the first free display from the number given: each test that starts Xvfb
# searches from a number of its own (tests/lcmtypes/vsl_spy_test.sh: 140), so tests run at once
# (ctest -j) never pick the same one.
xvfb-run -a -n 170 -e "$tmp/xvfb.err" java -Djava.net.preferIPv4Stack=true -cp "$tmp:$classpath" \
  lcm.spy.SpyDecodeCheck "$(realpath "$log")" || {
  rc=$?
  echo "--- Xvfb errors:"
  cat "$tmp/xvfb.err" || true
  exit $rc
}

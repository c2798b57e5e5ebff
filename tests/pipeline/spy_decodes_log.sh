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
# xvfb-run -a picks a free display racily when several run at once (ctest -j): retry when the X
# server itself failed to start.
for attempt in 1 2 3; do
  : >"$tmp/xvfb.err"
  set +e
  xvfb-run -a -e "$tmp/xvfb.err" java -Djava.net.preferIPv4Stack=true -cp "$tmp:$classpath" \
    lcm.spy.SpyDecodeCheck "$(realpath "$log")"
  rc=$?
  set -e
  grep -qE 'Xvfb failed to start|already active' "$tmp/xvfb.err" || break
  sleep "$attempt"
done
exit $rc

#!/usr/bin/env bash
# Tests of tools/vsl-spy. Run from the repository root.
#
#   vsl_spy_test.sh help                 --help prints the usage, exit 0
#   vsl_spy_test.sh missing-jar          a missing types jar is a clear error, exit != 0
#   vsl_spy_test.sh type-database <jar>  lcm-spy's type database, on vsl-spy's class path, finds
#                                        every lcmtypes/*.lcm type by fingerprint
#   vsl_spy_test.sh xvfb <jar>           vsl-spy starts lcm-spy under Xvfb with --lcm-url passed
#                                        through; lcm-spy reports exactly one LCM type per
#                                        lcmtypes/*.lcm file; then it is stopped with SIGTERM
#
# lcm-spy (LCM 1.3.1) prints only the number of types it found ("Found N LCM types"), not their
# names; the type-database case checks the names.
set -euo pipefail

spy=tools/vsl-spy
java=${JAVA:-java}
unset CLASSPATH # lcm-spy scans $CLASSPATH too: keep the test to vsl-spy's own class path

fail() {
  echo "FAIL: $*"
  exit 1
}

lcm_type_names() {
  local f
  for f in lcmtypes/*.lcm; do basename "$f" .lcm; done
}

case "${1:-}" in
  help)
    out=$("$spy" --help) || fail "--help exited with $?"
    for want in "Usage: tools/vsl-spy" "--lcm-url" "VSL_TYPES_JAR" "--classpath"; do
      grep -qF -- "$want" <<<"$out" || fail "--help does not mention $want"
    done
    echo "ok: --help"
    ;;

  missing-jar)
    set +e
    err=$(VSL_TYPES_JAR=/nonexistent/vsl_lcmtypes.jar "$spy" 2>&1 >/dev/null)
    rc=$?
    set -e
    ((rc != 0)) || fail "vsl-spy exited 0 without a types jar"
    grep -qF "types jar not found: /nonexistent/vsl_lcmtypes.jar" <<<"$err" ||
      fail "unclear error: $err"
    grep -qF "run tools/test or cmake --build build first" <<<"$err" ||
      fail "the error does not say how to build the jar: $err"
    echo "ok: missing jar -> exit $rc: $err"
    ;;

  type-database)
    jar=${2:?types jar}
    classpath=$(VSL_TYPES_JAR="$jar" "$spy" --classpath)
    mapfile -t names < <(lcm_type_names)
    set +e
    out=$("$java" -cp "$classpath" tests/lcmtypes/SpyTypeDatabaseCheck.java "${names[@]}" 2>&1)
    rc=$?
    set -e
    echo "$out"
    ((rc == 0)) || fail "lcm-spy's type database misses vsl types (exit $rc)"
    grep -qx "Found ${#names[@]} LCM types" <<<"$out" ||
      fail "lcm-spy's type database should hold exactly the ${#names[@]} vsl types"
    ((
      $(grep -c '^ok: lcm-spy decodes' <<<"$out") == ${#names[@]}
    )) || fail "not every type checked"
    ;;

  xvfb)
    jar=${2:?types jar}
    command -v xvfb-run >/dev/null || fail "xvfb-run not found (Debian package xvfb)"
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    # xvfb-run -a takes the first free display from the number given: each test that starts Xvfb
    # searches from a number of its own (tests/pipeline/spy_decodes_log.sh: 170), so tests run
    # at once (ctest -j) never pick the same one.
    set +e
    xvfb-run -a -n 140 -e "$tmp/xvfb.err" bash "$0" xvfb-inner "$jar" "$tmp"
    rc=$?
    set -e
    if ((rc != 0)); then
      echo "--- Xvfb errors:"
      cat "$tmp/xvfb.err" || true
    fi
    exit $rc
    ;;

  xvfb-inner) # runs inside xvfb-run, DISPLAY set
    jar=${2:?types jar}
    tmp=${3:?temp dir}
    n_types=$(lcm_type_names | wc -l)
    port=$((20000 + $$ % 20000))
    url="udpm://239.255.76.67:$port?ttl=0"
    VSL_TYPES_JAR="$jar" "$spy" --lcm-url "$url" >"$tmp/spy.out" 2>"$tmp/spy.err" &
    pid=$!
    stop() {
      if kill -0 "$pid" 2>/dev/null; then
        kill -TERM "$pid" 2>/dev/null || true
        for _ in $(seq 50); do
          kill -0 "$pid" 2>/dev/null || break
          sleep 0.1
        done
        kill -0 "$pid" 2>/dev/null && kill -KILL "$pid" 2>/dev/null
      fi
      wait "$pid" 2>/dev/null || true
    }
    trap stop EXIT
    show() {
      echo "--- lcm-spy stdout:"
      cat "$tmp/spy.out"
      echo "--- lcm-spy stderr:"
      cat "$tmp/spy.err"
    }

    # lcm-spy prints, in this order: "Found N LCM types" (type database built), "Found N plugins"
    # (after its window was created), "LCM: TTL set to zero, ..." (LCM opened with our URL).
    ready=0
    for _ in $(seq 600); do # 60 s
      if ! kill -0 "$pid" 2>/dev/null; then
        show
        fail "lcm-spy exited early"
      fi
      if grep -q '^Found [0-9]* plugins' "$tmp/spy.out" &&
        grep -qF 'TTL set to zero' "$tmp/spy.out" "$tmp/spy.err"; then
        ready=1
        break
      fi
      sleep 0.1
    done
    ((ready)) || {
      show
      fail "lcm-spy did not start within 60 s"
    }
    sleep 1
    kill -0 "$pid" 2>/dev/null || {
      show
      fail "lcm-spy died after start-up"
    }
    show
    # --lcm-url reached lcm-spy: it listens on our port (default would be 7667).
    port_hex=$(printf ':%04X' "$port")
    awk -v p="$port_hex" 'NR > 1 && substr($2, length($2) - 4) == p { found = 1 } END { exit !found }' \
      /proc/net/udp /proc/net/udp6 2>/dev/null ||
      fail "lcm-spy does not listen on UDP port $port: --lcm-url was not passed through"
    grep -qx "Found $n_types LCM types" "$tmp/spy.out" ||
      fail "lcm-spy should find exactly the $n_types vsl types"
    if grep -Eq 'Exception|Bad LCM Type|Type Conflict|ClassDiscoverer ERR' \
      "$tmp/spy.out" "$tmp/spy.err"; then
      fail "lcm-spy reported errors"
    fi
    echo "ok: lcm-spy started on $url with $n_types vsl types"
    ;;

  *)
    echo "usage: $0 help | missing-jar | type-database <jar> | xvfb <jar>" >&2
    exit 2
    ;;
esac

#!/usr/bin/env bash
# install_check.sh SOURCE_DIR BUILD_DIR PORT: vsl as a user installs it (tests/install).
#  1. cmake --install into a temporary prefix: nothing lands outside it;
#  2. tests/install/consumer built against it with find_package(vsl), and with pkg-config; run;
#  3. cpack -G DEB: the packages vsl and vsl-dev, their control data (dependencies computed by
#     dpkg-shlibdeps, conffiles, maintainer scripts) checked;
#  4. vsl unpacked into a clean root (dpkg -x); its units pass systemd-analyze verify;
#  5. the unpacked daemons (root/usr/bin) with the unpacked configs (root/etc/vsl) run the demo
#     pipeline over loopback LCM (ttl=0, PORT) and localize the robot.
set -euo pipefail
src=${1:?source dir}
build=${2:?build dir}
port=${3:?LCM port}
tmp=$(mktemp -d)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
step() { echo "== $* (at ${SECONDS} s)"; }

step "cmake --install into $tmp/prefix"
cmake --install "$build" --prefix "$tmp/prefix" >"$tmp/install.log"
outside=$(grep -v "^$tmp/prefix/" "$build/install_manifest.txt" || true)
[ -z "$outside" ] || fail "installed outside the prefix: $outside"
for f in bin/vsl-localizer bin/vsl-spy bin/vsl-train-detector etc/vsl/vsl-localizer.yaml \
         lib/cmake/vsl/vslConfig.cmake lib/pkgconfig/vsl.pc include/vsl/world/world_model.hpp \
         include/vsl/pose_estimate_t.hpp share/vsl/config/worlds/kitchen.yaml \
         share/vsl/calib/armar3_sim.yaml share/java/vsl_lcmtypes.jar \
         share/vsl/lcmtypes/pose_estimate_t.lcm lib/systemd/system/vsl.target; do
  [ -e "$tmp/prefix/$f" ] || fail "not installed: $f"
done
"$tmp/prefix/bin/vsl-spy" --classpath | grep -q "$tmp/prefix/share/java/vsl_lcmtypes.jar" ||
  fail "vsl-spy does not find the installed types jar"

step "a consumer project: find_package(vsl CONFIG REQUIRED)"
cmake -S "$src/tests/install/consumer" -B "$tmp/consumer" -DCMAKE_PREFIX_PATH="$tmp/prefix" \
  -DCMAKE_BUILD_TYPE=Release >"$tmp/consumer.log" 2>&1 || { cat "$tmp/consumer.log"; fail "configure"; }
cmake --build "$tmp/consumer" >>"$tmp/consumer.log" 2>&1 || { cat "$tmp/consumer.log"; fail "build"; }
"$tmp/consumer/vsl_consumer" || fail "vsl_consumer"
"$tmp/consumer/vsl_consumer" "$tmp/prefix/share/vsl/config/worlds/kitchen.yaml" \
  "$tmp/prefix/etc/vsl/localizer.yaml" || fail "vsl_consumer with the installed localizer.yaml"

step "a consumer with pkg-config"
export PKG_CONFIG_PATH="$tmp/prefix/lib/pkgconfig"
# shellcheck disable=SC2046
c++ -std=c++20 -O1 "$src/tests/install/consumer/pkg_config_consumer.cpp" -o "$tmp/pc_consumer" \
  $(pkg-config --cflags --libs vsl) || fail "pkg-config build"
"$tmp/pc_consumer" "$(pkg-config --variable=datadir vsl)/config/worlds/kitchen.yaml" ||
  fail "pkg-config consumer"

step "cpack -G DEB"
(cd "$tmp" && cpack --config "$build/CPackConfig.cmake" -B "$tmp/deb" >"$tmp/cpack.log" 2>&1) ||
  { cat "$tmp/cpack.log"; fail "cpack"; }
runtime_deb=$(ls "$tmp"/deb/vsl_*.deb)
dev_deb=$(ls "$tmp"/deb/vsl-dev_*.deb)
dpkg-deb -I "$runtime_deb" >"$tmp/runtime.info"
dpkg-deb -I "$dev_deb" >"$tmp/dev.info"
grep "^ Depends:" "$tmp/runtime.info"
grep -q "^ Depends:.*liblcm" "$tmp/runtime.info" || fail "vsl: no computed dependency on liblcm"
grep -q "^ Depends:.*libopencv" "$tmp/runtime.info" || fail "vsl: no computed dependency on OpenCV"
grep -q "^ Depends:.*libgoogle-glog" "$tmp/runtime.info" || fail "vsl: no computed dependency on glog (Ceres)"
grep -q "^ Depends:.*vsl (= " "$tmp/dev.info" || fail "vsl-dev does not depend on vsl"
dpkg-deb -e "$runtime_deb" "$tmp/control"
for f in conffiles postinst prerm postrm; do [ -f "$tmp/control/$f" ] || fail "vsl: no $f"; done
for conf in /etc/vsl/vsl-localizer.yaml /etc/default/vsl /etc/sysctl.d/60-vsl-lcm.conf; do
  grep -qx "$conf" "$tmp/control/conffiles" || fail "vsl: $conf is not a conffile"
done
sh -n "$tmp/control/postinst" || fail "postinst syntax"

step "dpkg -x into a clean root"
root="$tmp/root"
dpkg -x "$runtime_deb" "$root"
dpkg -x "$dev_deb" "$root"
while read -r conf; do [ -f "$root$conf" ] || fail "conffile missing in the package: $conf"; done \
  <"$tmp/control/conffiles"
units="$root/usr/lib/systemd/system"
[ -d "$units" ] || units="$root/lib/systemd/system"
grep -q "^ExecStart=/usr/bin/vsl-localizer --config /etc/vsl/vsl-localizer.yaml" \
  "$units/vsl-localizer.service" || fail "unit: ExecStart is not the installed path"
# systemd-analyze verify checks that ExecStart exists: point the units at the unpacked root.
mkdir -p "$tmp/units"
for unit in "$units"/*; do
  sed -e "s|=/usr/bin/|=$root/usr/bin/|" -e "s| /etc/| $root/etc/|g" -e "s|=-/etc/|=-$root/etc/|" \
    "$unit" >"$tmp/units/$(basename "$unit")"
done
out=$(cd "$tmp/units" && systemd-analyze verify ./*.service ./*.target 2>&1 || true)
[ -z "$out" ] || { echo "$out"; fail "systemd-analyze verify"; }
echo "ok: $(ls "$tmp/units" | wc -l) units verify"

step "the demo pipeline from the unpacked root"
url="udpm://239.255.76.67:$port?ttl=0&recv_buf_size=4194304"
run() {  # run NAME CONFIG: an unpacked daemon with an unpacked config, in the background
  "$root/usr/bin/$1" --config "$root/etc/vsl/$2" --lcm-url "$url" 2>"$tmp/$1.log" &
  pids+=("$!")
}
run vsl-sim-head sim_head.yaml
run vsl-recognition recognition.yaml
run vsl-fusion fusion.yaml
run vsl-localizer vsl-localizer.yaml
if ! "$root/usr/bin/vsl-request" --lcm-url "$url" --timeout 120 \
  --wait-for vsl-sim-head,vsl-recognition,vsl-fusion,vsl-localizer >"$tmp/request.log" 2>&1; then
  cat "$tmp/request.log" "$tmp"/vsl-*.log
  fail "the unpacked pipeline did not localize"
fi
grep "^result:" "$tmp/request.log"
error=$(sed -n 's/^result:.*position_error_m=\([0-9.e-]*\).*/\1/p' "$tmp/request.log")
awk -v e="$error" 'BEGIN { exit !(e < 0.05) }' || fail "position error $error m"
echo "ok: installed, packaged, unpacked and localized"

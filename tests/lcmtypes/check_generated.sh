#!/usr/bin/env bash
# Every lcmtypes/*.lcm file (one struct per file, package vsl, struct named like the file) has a
# class in the types jar and a generated C++ header; the jar holds no class without a .lcm file.
# A .lcm file missing from VSL_LCM_TYPES in lcmtypes/CMakeLists.txt fails here.
#
# Usage: check_generated.sh <lcmtypes source dir> <types jar> <generated header dir> [jar tool]
set -euo pipefail

src_dir=$1
jar_file=$2
hpp_dir=$3
jar_tool=${4:-jar}
fix="add it to VSL_LCM_TYPES in lcmtypes/CMakeLists.txt and rebuild"
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

[[ -f "$jar_file" ]] || {
  echo "FAIL: types jar not found: $jar_file (build target vsl_lcmtypes_jar)"
  exit 1
}
shopt -s nullglob
lcm_files=("$src_dir"/*.lcm)
((${#lcm_files[@]} > 0)) || {
  echo "FAIL: no .lcm files in $src_dir"
  exit 1
}
classes=$("$jar_tool" tf "$jar_file")

for lcm in "${lcm_files[@]}"; do
  name=$(basename "$lcm" .lcm)
  grep -Eq '^[[:space:]]*package[[:space:]]+vsl[[:space:]]*;' "$lcm" ||
    fail "$lcm: not in package vsl"
  structs=$(grep -Ec '^[[:space:]]*struct[[:space:]]' "$lcm" || true)
  [[ "$structs" == 1 ]] || fail "$lcm: $structs struct declarations, want exactly one"
  grep -Eq "^[[:space:]]*struct[[:space:]]+${name}([[:space:]{]|\$)" "$lcm" ||
    fail "$lcm: the struct must be named $name, like its file"
  [[ "$name" == *_t ]] || fail "$lcm: type names end in _t"
  grep -qx "vsl/$name.class" <<<"$classes" || fail "$name: no vsl/$name.class in $jar_file; $fix"
  [[ -f "$hpp_dir/$name.hpp" ]] || fail "$name: no $hpp_dir/$name.hpp; $fix"
done

while read -r class; do
  name=${class#vsl/}
  name=${name%.class}
  [[ -f "$src_dir/$name.lcm" ]] || fail "$jar_file holds vsl/$name.class but there is no $name.lcm"
done < <(grep -E '^vsl/[^/]+\.class$' <<<"$classes" | grep -v '\$' || true)

if ((failures > 0)); then
  echo "$failures failure(s)"
  exit 1
fi
echo "ok: ${#lcm_files[@]} types, each in $(basename "$jar_file") and $hpp_dir"

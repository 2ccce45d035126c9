#!/usr/bin/env bash
# The codec's time under each fill-reducing ordering, on the shared meshes:
#   bash bench/codec_ordering.sh build/apps/gab [ERROR] [MESH_DIR]
# prints per mesh and ordering the median of 3 runs of CPU seconds (user +
# sys) of `gab compress --error ERROR --solver global --ordering O --threads
# 1` (the solver an ordering is for) and of decompressing its file, and the
# file's bytes. CPU seconds, not wall: they
# move less when the machine is shared. What kAuto's crossover in
# codec/src/pipeline/ordering_choice.cpp rests on (docs/tuning-codec.md).
set -euo pipefail
gab="$1"
err="${2:-1e-3}"
dir="${3:-$(dirname "$0")/../../shared/meshes}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cpu() { { /usr/bin/time -f "%U %S" "$@" > /dev/null; } 2>&1 | tail -1 | awk '{print $1 + $2}'; }
median3() { printf "%s\n" "$@" | sort -g | sed -n 2p; }
echo "mesh ordering encode_cpu_s decode_cpu_s bytes"
for m in bunny-small camel-head max-planck bunny horse nefertiti feline igea; do
  [ -f "$dir/$m.off" ] || continue
  for o in amd nd; do
    enc=() dec=()
    for _ in 1 2 3; do
      enc+=("$(cpu "$gab" compress -i "$dir/$m.off" -o "$tmp/f.gab" --error "$err" --solver global --ordering "$o" --threads 1)")
      dec+=("$(cpu "$gab" decompress -i "$tmp/f.gab" -o "$tmp/f.off" --threads 1)")
    done
    echo "$m $o $(median3 "${enc[@]}") $(median3 "${dec[@]}") $(stat -c %s "$tmp/f.gab")"
  done
done

#!/usr/bin/env bash
# Decode time and peak memory, gab against Draco, interleaved in one run:
# for each mesh, ROUNDS rounds of `gab decompress --threads 1` on every
# DIR/MESH-*.gab (bench/solver_compare --out DIR writes them) and of
# `draco_decoder` on DIR/MESH.drc (make it with draco_encoder -cl 10 -qp Q),
# each writing binary PLY; prints the median wall seconds and peak RSS.
#   bash bench/decode_timing.sh build/apps/gab DIR ROUNDS mesh...
set -euo pipefail
gab="$1" dir="$2" rounds="$3"
shift 3
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
for mesh in "$@"; do
  for ((r = 0; r < rounds; ++r)); do
    for file in "$dir/$mesh"-*.gab "$dir/$mesh.drc"; do
      [ -e "$file" ] || continue
      kind="$(basename "$file")"
      if [[ "$file" == *.drc ]]; then
        /usr/bin/time -f "$kind %e %M" draco_decoder -i "$file" -o "$dir/out.ply" > /dev/null 2>> "$log"
      else
        /usr/bin/time -f "$kind %e %M" "$gab" decompress -i "$file" -o "$dir/out.ply" --threads 1 > /dev/null 2>> "$log"
      fi
    done
  done
done
python3 - "$log" <<'PY'
import collections, statistics, sys
runs = collections.defaultdict(list)
for line in open(sys.argv[1]):
    parts = line.split()
    if len(parts) == 3 and (parts[0].endswith(".gab") or parts[0].endswith(".drc")):
        runs[parts[0]].append((float(parts[1]), int(parts[2])))
for kind, values in runs.items():
    print("%-28s %7.3f s %7.1f MB" % (kind, statistics.median(v[0] for v in values),
                                      statistics.median(v[1] for v in values) / 1024))
PY

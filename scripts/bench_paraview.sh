#!/usr/bin/env bash
# The ParaView plugin's benchmark: frame times of the Translucent Render View on 1, 2 and 4
# ranks (pvbatch under mpirun), on the dragon (dragon_vrip_res2, marble, 1000 mm per unit) and the
# airborne LiDAR tile (522,674 points in UTM metres, skin1), with ratios to 1 rank from the same
# run, each rank's ghost surfels and the bytes it put into the light-map reductions per frame.
#   bash scripts/bench_paraview.sh [OUT_DIR] [FRAMES]      (needs scripts/build.sh first)
# On a 2-core machine 4 ranks share the cores: the point is what crosses the network and that
# the images agree, not speed-up.
set -euo pipefail
cd "$(dirname "$0")/.."
data="${SSS_DATA_DIR:-../shared/data}"
out="${1:-build/bench_paraview}"
frames="${2:-3}"
mkdir -p "$out"
cloud() {  # name, file, material, mm per unit: a .vtp with the PCL glue's normals
  [ -f "$out/$1.vtp" ] && return 0
  build/programs/sss_render "$data/$2" --mm-per-unit "$4" --material "$3" --size 64x64 \
    --output "$out/$1_bake.png" --bake "$out/$1.ply" > "$out/$1_bake.log" 2>&1
  bash scripts/pvbatch.sh examples/paraview/baked_to_vtp.py "$out/$1.ply" "$out/$1.vtp" \
    2>&1 | grep wrote
}
cloud dragon dragon_vrip_res2.ply.gz marble 1000
cloud lidar CSite1_red1-utm.pcd skin1 1000
{
  echo "| cloud | ranks | first frame (s) | camera-only frame (s) | light-moving frame (s) | camera-only / 1 rank | light-moving / 1 rank |"
  echo "| --- | --- | --- | --- | --- | --- | --- |"
} > "$out/bench_paraview.md"
for spec in "dragon marble 1000" "lidar skin1 1000"; do
  set -- $spec
  for ranks in 1 2 4; do
    bash scripts/pvbatch.sh -np "$ranks" -v=1 examples/paraview/bench_ranks.py "$out/$1.vtp" \
      "$out/$1_$ranks.json" "$2" "$3" "$frames" > "$out/$1_$ranks.log" 2>&1
    grep -o "rank [0-9]*: [0-9]* own surfels.*bytes)" "$out/$1_$ranks.log" | sort -u \
      | sed "s/^/$1, $ranks ranks: /" || true
    grep -o "rank [0-9]*: [0-9]* bytes reduced this frame" "$out/$1_$ranks.log" | sort | uniq -c \
      | sed "s/^/$1, $ranks ranks, frames: /" || true
  done
  /usr/bin/python3 - "$out" "$1" >> "$out/bench_paraview.md" <<'PY'
import json, sys
out, name = sys.argv[1], sys.argv[2]
runs = {n: json.load(open("%s/%s_%d.json" % (out, name, n))) for n in (1, 2, 4)}
for n, r in runs.items():
    print("| %s | %d | %.2f | %.3f | %.3f | %.2f | %.2f |" % (name, n, r["first_frame_s"],
          r["camera_only_s"], r["light_moving_s"], r["camera_only_s"] / runs[1]["camera_only_s"],
          r["light_moving_s"] / runs[1]["light_moving_s"]))
PY
done
cat "$out/bench_paraview.md"

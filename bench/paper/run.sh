#!/usr/bin/env bash
# `wifislam paper` timed (issue "The paper reproduced whole by one command", speed).
#  1. The whole paper at the default 3 fps for SEEDS seeds, and the time per part from the
#     folder's timing.json. The goal: one seed in 30 min on 2 cores.
#  2. What sharing each twin's rendering and feature extraction between its runs gains, as a
#     ratio measured in the same run: one study (RTAB-Map on C Hall, 4 cases, 8 runs) made by
#     `wifislam paper --parts rtabmap --twins c_hall` in a folder of its own, and by
#     `wifislam study run` on the study file it wrote (which renders and extracts per case). Their
#     rows must be the same.
#
#   bench/paper/run.sh [build-dir] [output-dir] [seeds] [jobs]
#   (defaults: build/release, a temp dir, 1, 2)
set -euo pipefail
build=${1:-build/release}
out=${2:-$(mktemp -d)/paper}
seeds=${3:-1}
jobs=${4:-2}
bin="$build/apps/wifislam"

start=$(date +%s)
"$bin" paper -o "$out" --seeds "$seeds" --jobs "$jobs" -q >/dev/null
echo "1. wifislam paper --seeds $seeds --jobs $jobs: $(( $(date +%s) - start )) s wall"
/usr/bin/python3 - "$out/timing.json" <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))
for part, s in sorted(t.items()):
    print(f"   {part:45s} {s:7.0f} s")
print(f"   {'all':45s} {sum(t.values()):7.0f} s")
PY

one="$out-one-study"
start=$(date +%s)
"$bin" paper -o "$one" --parts rtabmap --twins c_hall --jobs "$jobs" -q --no-report
shared=$(( $(date +%s) - start ))
start=$(date +%s)
"$bin" study run "$one/studies/rtabmap-c_hall-seed1001.yaml" -o "$one/alone.sqlite" \
  --jobs "$jobs" -q
alone=$(( $(date +%s) - start ))
/usr/bin/python3 - "$one" "$shared" "$alone" <<'PY'
import sqlite3, sys
one, shared, alone = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
rows = lambda db: sqlite3.connect(db).execute(
    "SELECT * FROM results ORDER BY case_id, variant").fetchall()
same = rows(f"{one}/results/rtabmap-c_hall-seed1001.sqlite") == rows(f"{one}/alone.sqlite")
print(f"2. RTAB-Map on C Hall (8 runs): paper {shared:.0f} s, study run {alone:.0f} s: "
      f"ratio {shared / alone:.2f}; the same rows: {same}")
PY
echo "full results: $out, $one"

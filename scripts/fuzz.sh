#!/usr/bin/env bash
# Fuzzes one of wifislam's input parsers with libFuzzer (fuzz/fuzz_targets.hpp).
#
#   scripts/fuzz.sh TARGET SECONDS   fuzz TARGET (scene, dataset, trajectory, study) for
#                                    SECONDS, then merge what it found into fuzz/corpus/TARGET
#                                    (minimised)
#   scripts/fuzz.sh seeds [study]    (re)write the seed inputs fuzz/corpus/*/seed-* from the
#                                    shipped scenes, a dataset generated from
#                                    fuzz/seed_dataset_scene.yaml (needs the release build), and
#                                    the study files of fuzz/seed_studies/ and studies/; `seeds
#                                    study` only the study seeds (no build needed)
#
# Builds the `fuzz` preset (clang, ASan + UBSan) on first use; installs clang when it is missing.
# A crash, sanitizer report, hang (-timeout) or memory blow-up (-rss_limit_mb) is written to
# fuzz/crashes/TARGET/; commit it with its fix, and tests/fuzz replays it in the release suite.
# Run log with executions and coverage: build/fuzz/logs/TARGET-<time>.log.
set -euo pipefail
cd "$(dirname "$0")/.."

usage() { sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
[ $# -ge 1 ] || usage

# Largest input per target (libFuzzer -max_len): a scene file is a few kB; a dataset bundle holds
# a few 32x24 PNGs and the text files of a short route; a study file is a screenful.
max_len_of() {
  case "$1" in
    scene) echo 16384 ;;
    dataset) echo 65536 ;;
    trajectory) echo 8192 ;;
    study) echo 8192 ;;
    *) echo "fuzz.sh: unknown target '$1' (scene, dataset, trajectory, study)" >&2; exit 2 ;;
  esac
}

# The dataset bundle format of fuzz/dataset_bundle.hpp: "=== name" lines, each file's bytes, and
# one newline between sections.
pack_bundle() {
  local folder="$1" first=1 name
  while IFS= read -r name; do
    [ $first -eq 1 ] || printf '\n'
    first=0
    printf '=== %s\n' "$name"
    cat "$folder/$name"
  done < <(cd "$folder" && find . -type f -printf '%P\n' | LC_ALL=C sort)
}

# Study seeds: the hand-written ones as they are, and the project's studies with their base scene
# replaced by the study target's scratch copy of fuzz/seed_dataset_scene.yaml
# (fuzz/fuzz_targets.hpp).
write_study_seeds() {
  mkdir -p fuzz/corpus/study
  rm -f fuzz/corpus/study/seed-*
  local study
  for study in fuzz/seed_studies/*.yaml; do
    cp "$study" "fuzz/corpus/study/seed-$(basename "$study" .yaml)"
  done
  for study in studies/*.yaml; do
    [ -f "$study" ] || continue
    sed -E 's|^scene:.*$|scene: scene.yaml|' "$study" >"fuzz/corpus/study/seed-study-$(basename "$study" .yaml)"
  done
}

write_seeds() {
  local wifislam=build/release/apps/wifislam
  [ -x "$wifislam" ] || { echo "fuzz.sh: build the release preset first (scripts/build.sh)" >&2; exit 2; }
  # global: the EXIT trap runs after this function has returned
  seed_scratch="$(mktemp -d)"
  trap 'rm -rf -- "$seed_scratch"' EXIT
  mkdir -p fuzz/corpus/scene fuzz/corpus/dataset fuzz/corpus/trajectory
  rm -f fuzz/corpus/scene/seed-* fuzz/corpus/dataset/seed-* fuzz/corpus/trajectory/seed-*
  for scene in scenes/*.yaml fuzz/seed_dataset_scene.yaml; do
    cp "$scene" "fuzz/corpus/scene/seed-$(basename "$scene" .yaml)"
  done
  "$wifislam" generate fuzz/seed_dataset_scene.yaml -o "$seed_scratch/ours" --max-frames 4 >/dev/null
  pack_bundle "$seed_scratch/ours" >fuzz/corpus/dataset/seed-ours
  # The same dataset without its manifest (every file unchecked) and as a plain TUM folder.
  cp -r "$seed_scratch/ours" "$seed_scratch/unverified"
  rm -f "$seed_scratch/unverified/manifest.json" "$seed_scratch/unverified/images.sha256" \
    "$seed_scratch/unverified/.wifislam-output"
  pack_bundle "$seed_scratch/unverified" >fuzz/corpus/dataset/seed-unverified
  mkdir -p "$seed_scratch/tum"
  cp -r "$seed_scratch/ours/rgb" "$seed_scratch/ours/depth" "$seed_scratch/ours/rgb.txt" "$seed_scratch/ours/depth.txt" \
    "$seed_scratch/ours/groundtruth.txt" "$seed_scratch/tum/"
  pack_bundle "$seed_scratch/tum" >fuzz/corpus/dataset/seed-tum
  head -c 6000 "$seed_scratch/ours/groundtruth.txt" | sed '$d' >fuzz/corpus/trajectory/seed-groundtruth
  head -c 6000 "$seed_scratch/ours/odometry.txt" | sed '$d' >fuzz/corpus/trajectory/seed-odometry
  printf '# timestamp tx ty tz qx qy qz qw\n1305031102.175304 1.3405 0.6266 1.6575 0.6574 0.6126 -0.2949 -0.3248\n' \
    >fuzz/corpus/trajectory/seed-tum
  write_study_seeds
  ls fuzz/corpus/*/seed-* | wc -l | xargs echo "fuzz.sh: seed inputs written:"
}

if [ "$1" = seeds ]; then
  case "${2-}" in
    "") write_seeds ;;
    study) write_study_seeds; ls fuzz/corpus/study/seed-* | wc -l | xargs echo "fuzz.sh: study seeds written:" ;;
    *) usage ;;
  esac
  exit 0
fi

[ $# -eq 2 ] || usage
target="$1"
seconds="$2"
max_len="$(max_len_of "$target")"
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "fuzz.sh: SECONDS must be a whole number" >&2; exit 2; }

command -v clang++ >/dev/null || scripts/install-deps.sh --fuzz
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz --target "${target}_fuzzer"

driver="build/fuzz/fuzz/${target}_fuzzer"
work="build/fuzz/work/$target"
merged="build/fuzz/merged/$target"
log="build/fuzz/logs/$target-$(date -u +%Y%m%dT%H%M%SZ).log"
mkdir -p "$work" "$(dirname "$log")" "fuzz/crashes/$target" "fuzz/corpus/$target"

echo "fuzz.sh: fuzzing $target for $seconds s (log: $log)"
status=0
"$driver" -max_total_time="$seconds" -max_len="$max_len" -timeout=30 -rss_limit_mb=4096 \
  -print_final_stats=1 -artifact_prefix="fuzz/crashes/$target/" \
  "$work" "fuzz/corpus/$target" >"$log" 2>&1 || status=$?
grep -E '^(#[0-9]+ +DONE|stat::number_of_executed_units|stat::peak_rss_mb|INFO: Loaded|==[0-9]+==ERROR)' \
  "$log" || true

# Minimise: keep the inputs that together reach every edge the corpus and this run reached.
rm -rf -- "$merged"
mkdir -p "$merged"
"$driver" -merge=1 -max_len="$max_len" -timeout=30 -rss_limit_mb=4096 \
  "$merged" "fuzz/corpus/$target" "$work" >>"$log" 2>&1 || true
if [ -n "$(ls -A "$merged")" ]; then
  # Seeds keep their names; everything else is replaced by the minimised set, whose files
  # libFuzzer names by their SHA-1 (a seed's copy among them is skipped).
  seed_hashes="$(cd "fuzz/corpus/$target" && sha1sum seed-* 2>/dev/null | cut -d' ' -f1 || true)"
  find "fuzz/corpus/$target" -maxdepth 1 -type f ! -name 'seed-*' -delete
  for f in "$merged"/*; do
    grep -qx "$(basename "$f")" <<<"$seed_hashes" || cp "$f" "fuzz/corpus/$target/"
  done
fi
echo "fuzz.sh: corpus fuzz/corpus/$target: $(ls "fuzz/corpus/$target" | wc -l) inputs"
if [ $status -ne 0 ]; then
  echo "fuzz.sh: $target found a problem (exit $status); reproducer in fuzz/crashes/$target/" >&2
  exit 1
fi

#!/usr/bin/env python3
"""Calibrates the rtabmap front end's deterministic cost model (RtabmapCostModel,
slam/frontend/rtabmap/rtabmap_options.hpp) from run folders of `wifislam slam --frontend rtabmap`.

Each term is fitted against the thread CPU time of its own phase, which the front end records per
node in rtabmap_memory.csv, so the terms do not share one collinear regression:
  memory_update_cpu_ms = fixed + ms_per_word_comparison x word_comparisons
  likelihood_cpu_ms    = fixed + ms_per_likelihood_term x likelihood_terms
                               + ms_per_scored_node x scored
  posterior_cpu_ms     = fixed + ms_per_hypothesis x hypotheses
A verification is charged its mean wall-clock over the roles a node verifies in timing.json
(long_term, proximity, predecessor, relocalisation; OpenCV's matching runs on worker threads that
thread CPU time does not see). Frame-to-frame tracking (role tracking) is odometry, which
Rtabmap/TimeThr does not cover: RTAB-Map runs it in its own node. A node's fixed part adds the mean
feature extraction per frame (timing.json module feature_extraction), which RTAB-Map times inside
a node's processing (its memory update extracts the node's words).

Give runs of several map sizes (different scenes or thresholds) so that the counters vary
independently of each other; run them one at a time on an otherwise idle machine.

  bench/slam/rtabmap_cost_calibration.py RUN_DIR [RUN_DIR ...]

Prints the fitted values, their residuals, and for each run the ratio of the calibrated model's
total to the measured total (phase CPU + verification wall + feature extraction).
"""
import csv
import json
import math
import sys
from pathlib import Path


def least_squares(rows, columns, target):
    """Ordinary least squares with an intercept: returns (coefficients, rms residual)."""
    names = ["fixed"] + columns
    xs = [[1.0] + [float(r[c]) for c in columns] for r in rows]
    ys = [float(r[target]) for r in rows]
    n = len(names)
    ata = [[sum(x[i] * x[j] for x in xs) for j in range(n)] for i in range(n)]
    aty = [sum(x[i] * y for x, y in zip(xs, ys)) for i in range(n)]
    # Gaussian elimination with partial pivoting (no numpy on the target machines).
    m = [row[:] + [b] for row, b in zip(ata, aty)]
    for col in range(n):
        pivot = max(range(col, n), key=lambda r: abs(m[r][col]))
        m[col], m[pivot] = m[pivot], m[col]
        if abs(m[col][col]) < 1e-300:
            sys.exit(f"{target}: the counters do not vary; give runs of several map sizes")
        for r in range(n):
            if r != col:
                f = m[r][col] / m[col][col]
                m[r] = [a - f * b for a, b in zip(m[r], m[col])]
    coef = [m[i][n] / m[i][i] for i in range(n)]
    residual = [y - sum(c * v for c, v in zip(coef, x)) for x, y in zip(xs, ys)]
    rms = math.sqrt(sum(e * e for e in residual) / len(residual))
    return dict(zip(names, coef)), rms


def node_roles(timing):
    """timing.json roles of the verifications a node's processing makes (not tracking)."""
    return [v for k, v in timing.get("roles", {}).items() if k != "tracking"]


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        sys.exit(0 if len(sys.argv) >= 2 else 2)
    runs = []
    for arg in sys.argv[1:]:
        folder = Path(arg)
        memory, timing = folder / "rtabmap_memory.csv", folder / "timing.json"
        for f in (memory, timing):
            if not f.is_file():
                sys.exit(f"{f}: not found (a run folder of `wifislam slam --frontend rtabmap`)")
        with open(memory, newline="") as f:
            rows = list(csv.DictReader(f))
        for column in ("memory_update_cpu_ms", "likelihood_cpu_ms", "posterior_cpu_ms"):
            if rows and column not in rows[0]:
                sys.exit(f"{memory}: no column {column} (a run of an older build)")
        with open(timing) as f:
            runs.append((folder, rows, json.load(f)))

    rows = [r for _, rs, _ in runs for r in rs]
    scored_rows = [r for r in rows if int(r["scored"]) > 0]
    memory_fit, memory_rms = least_squares(rows, ["word_comparisons"], "memory_update_cpu_ms")
    likelihood_fit, likelihood_rms = least_squares(
        scored_rows, ["likelihood_terms", "scored"], "likelihood_cpu_ms")
    posterior_fit, posterior_rms = least_squares(scored_rows, ["hypotheses"], "posterior_cpu_ms")

    verification_s = comparisons = extraction_s = frames = 0.0
    for _, _, timing in runs:
        for role in node_roles(timing):
            verification_s += role["time_s"]
            comparisons += role["comparisons"]
        extraction = timing["modules"].get("feature_extraction", {"total_s": 0, "calls": 0})
        extraction_s += extraction["total_s"]
        frames += extraction["calls"]
    ms_per_verification = 1e3 * verification_s / comparisons if comparisons else 0.0
    ms_per_extraction = 1e3 * extraction_s / frames if frames else 0.0

    fixed = memory_fit["fixed"] + likelihood_fit["fixed"] * len(scored_rows) / len(rows) + \
        posterior_fit["fixed"] * len(scored_rows) / len(rows)
    model = {
        "ms_per_node": max(0.0, fixed) + ms_per_extraction,
        "ms_per_word_comparison": memory_fit["word_comparisons"],
        "ms_per_likelihood_term": likelihood_fit["likelihood_terms"],
        "ms_per_scored_node": likelihood_fit["scored"],
        "ms_per_hypothesis": posterior_fit["hypotheses"],
        "ms_per_verification": ms_per_verification,
    }
    print(f"{len(runs)} runs, {len(rows)} nodes ({len(scored_rows)} with a likelihood)")
    print(f"memory update: {memory_fit}  rms {memory_rms:.3f} ms")
    print(f"likelihood:    {likelihood_fit}  rms {likelihood_rms:.3f} ms")
    print(f"posterior:     {posterior_fit}  rms {posterior_rms:.3f} ms")
    print(f"verification:  {ms_per_verification:.3f} ms wall each ({comparisons:.0f})")
    print(f"extraction:    {ms_per_extraction:.3f} ms per frame ({frames:.0f})")
    print("cost model (--set cost_<name>=...):")
    for k, v in model.items():
        print(f"  {k} = {v:.4g}")

    print("run: model total / measured total (s), loop-closure share model / measured (s)")
    for folder, rs, timing in runs:
        measured = sum(float(r["memory_update_cpu_ms"]) + float(r["likelihood_cpu_ms"]) +
                       float(r["posterior_cpu_ms"]) for r in rs) * 1e-3
        measured += sum(role["time_s"] for role in node_roles(timing))
        measured += len(rs) * ms_per_extraction * 1e-3
        modelled = sum(model["ms_per_node"] +
                       model["ms_per_word_comparison"] * float(r["word_comparisons"]) +
                       model["ms_per_likelihood_term"] * float(r["likelihood_terms"]) +
                       model["ms_per_scored_node"] * float(r["scored"]) +
                       model["ms_per_hypothesis"] * float(r["hypotheses"]) +
                       model["ms_per_verification"] * float(r["verifications"]) for r in rs) * 1e-3
        lc_measured = sum(float(r["likelihood_cpu_ms"]) + float(r["posterior_cpu_ms"])
                          for r in rs) * 1e-3
        lc_measured += timing["roles"].get("long_term", {"time_s": 0.0})["time_s"]
        lc_modelled = sum(model["ms_per_likelihood_term"] * float(r["likelihood_terms"]) +
                          model["ms_per_scored_node"] * float(r["scored"]) +
                          model["ms_per_hypothesis"] * float(r["hypotheses"]) +
                          model["ms_per_verification"] * float(r["loop_verifications"])
                          for r in rs) * 1e-3
        print(f"  {folder}: {modelled:.2f} / {measured:.2f} = {modelled / measured:.2f};"
              f" loop closure {lc_modelled:.3f} / {lc_measured:.3f}"
              f" = {lc_modelled / lc_measured if lc_measured else float('nan'):.2f}")


if __name__ == "__main__":
    main()

"""examples/python/aliasing_sweep.py runs, at a small size, and writes its table and plot."""

import csv
import os
import subprocess
import sys

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples",
                       "python", "aliasing_sweep.py")


def test_the_sweep_writes_one_row_per_level_and_a_plot(tmp_path):
    out = tmp_path / "sweep"
    subprocess.run([sys.executable, EXAMPLE, "--levels", "0,1", "--fps", "1", "--max-frames",
                    "20", "--out", str(out)], check=True)
    with open(out / "results.csv") as f:
        rows = list(csv.DictReader(f))
    assert [float(r["aliasing"]) for r in rows] == [0.0, 1.0]
    for row in rows:
        assert float(row["vanilla_ate_rmse_m"]) >= 0
        assert float(row["wifi_ate_rmse_m"]) >= 0
    with open(out / "ate_vs_aliasing.png", "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"


def test_bad_levels_exit_2(tmp_path):
    result = subprocess.run([sys.executable, EXAMPLE, "--levels", "0,2", "--out",
                             str(tmp_path / "s")], capture_output=True, text=True)
    assert result.returncode == 2
    assert "aliasing" in result.stderr

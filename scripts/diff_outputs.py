#!/usr/bin/env python3
"""Compares two output snapshots (scripts/snapshot_outputs.sh) file by file.

    scripts/diff_outputs.py BEFORE AFTER [--show N]

Every file must be in both and byte-identical, except what measures time: a wall-clock or CPU
figure moves from one run to the next. Those are masked before comparing, by name, not by value:
JSON keys and CSV columns whose name says time (`*_s`, `*_ms`, `wall*`, `cpu*`, `*time*`),
Markdown table rows and columns about time, and on other lines about time the numbers that are
times (with a unit of time or a share of one: "12.3 s", "4.2 %", "105 fps"); counts on such a
line are compared. SQLite files are compared through the CSV
dumps the snapshot writes beside them (their `timing` table is wall-clock). Each snapshot's own
folder and binary (binary.path) are replaced by `<snapshot>` and `<wifislam>` in every file; cairo's
SVG surface ids (a process-wide counter) are masked. Exit 0 when nothing
else differs, 1 otherwise (with the differing files and their first differing lines).
"""
import argparse
import csv
import io
import json
import os
import re
import sys

TIME_NAME = re.compile(r"(_s$|_ms$|_s_|^wall|wall_|cpu|time|seconds|duration|elapsed|per_s$|_fps$)")
# Text lines that report measured time: "(12.3 s)", "12.3 s,", "in 12.3 s", "ms", "frames/s".
TIME_TEXT = re.compile(
    r"\b\d+(\.\d+)?(e[-+]?\d+)?\s*(s|ms|min|frames/s|cases/s|%)\b|"
    r"\b(time|wall|cpu|overhead|seconds)\b",
    re.IGNORECASE,
)
NUMBER = re.compile(r"-?\d+(\.\d+)?(e[-+]?\d+)?")
# On a line about time, the numbers that are times: those with a unit of time after them (a range
# "44-87 s" as one), a share of one ("12.1 %") or a ratio ("1.5x"), and those a time word names
# ("wall 12.3", "wall-clock 4", "time = 0.5"). Counts on the same line ("120 images ... (12 s)")
# are still compared.
_NUMBER_TEXT = r"\d+(?:\.\d+)?(?:e[-+]?\d+)?"
TIME_AFTER = re.compile(
    rf"(?<![\w.])-?{_NUMBER_TEXT}(?:-{_NUMBER_TEXT})?"
    r"(?=\s*(?:(?:s|sec|seconds|ms|min|fps|frames/s|cases/s)\b|%)|x\b)",
    re.IGNORECASE,
)
TIME_WORD_BEFORE = re.compile(rf"(\b(?:time|wall|wall-clock|cpu)\s*[:=]?\s*)-?{_NUMBER_TEXT}",
                              re.IGNORECASE)


def mask_times(line):
    return TIME_WORD_BEFORE.sub(lambda m: m.group(1) + "<n>", TIME_AFTER.sub("<n>", line))


def mask_json(value):
    if isinstance(value, dict):
        return {k: ("<time>" if TIME_NAME.search(k) else mask_json(v)) for k, v in value.items()}
    if isinstance(value, list):
        return [mask_json(v) for v in value]
    return value


def mask_csv(text):
    rows = list(csv.reader(io.StringIO(text)))
    if not rows:
        return text
    masked_columns = {i for i, name in enumerate(rows[0]) if TIME_NAME.search(name)}
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    for row in rows:
        writer.writerow(["<time>" if i in masked_columns and row is not rows[0] else v for i, v in enumerate(row)])
    return out.getvalue()


def mask_lines(text):
    """Masks the times on lines about time (mask_times), every number in Markdown table rows
    about time or under a heading about time, and table columns whose header says time."""
    out = []
    heading_about_time = False
    time_columns = None  # column indexes of the current table, once its header is read
    for line in text.split("\n"):
        if line.startswith("#"):
            heading_about_time = bool(TIME_TEXT.search(line))
        if not line.startswith("|"):
            time_columns = None
            # A time line's padding before a number follows the widths of the numbers before it:
            # collapsed with them (a line's indentation is kept and still compared).
            out.append(mask_times(re.sub(r"(?<=\S) {2,}(?=-?\d)", " ", line))
                       if TIME_TEXT.search(line) else line)
            continue
        cells = line.split("|")
        if time_columns is None:
            time_columns = {i for i, c in enumerate(cells) if TIME_NAME.search(c.strip()) or
                            c.strip() in ("seconds", "s", "ms")}
        elif heading_about_time or TIME_TEXT.search(line):
            cells = [NUMBER.sub("<n>", c) for c in cells]
        else:
            cells = [NUMBER.sub("<n>", c) if i in time_columns else c for i, c in enumerate(cells)]
        out.append("|".join(cells))
    return "\n".join(out)


def normalised(path, root):
    data = open(path, "rb").read().replace(os.path.abspath(root).encode(), b"<snapshot>")
    binary = open(os.path.join(root, "binary.path")).read().strip().encode()
    data = data.replace(binary, b"<wifislam>")
    name = os.path.basename(path)
    if name.endswith(".sqlite") or name.endswith(".sqlite-journal"):
        return None  # compared through the CSV dumps
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        return data
    if name.endswith(".svg"):
        return re.sub(r"surface\d+", "surface<n>", text)  # cairo's process-wide surface counter
    if name.endswith(".json"):
        try:
            return json.dumps(mask_json(json.loads(text)), indent=1, sort_keys=False)
        except json.JSONDecodeError:
            return text
    if name.endswith(".csv"):
        return mask_csv(text)
    if name.endswith((".md", ".stdout", ".txt.log")):
        return mask_lines(text)
    return text


def files_under(root):
    found = set()
    for folder, _, files in os.walk(root):
        for f in files:
            found.add(os.path.relpath(os.path.join(folder, f), root))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--show", type=int, default=4, help="differing lines shown per file")
    args = parser.parse_args()
    a, b = files_under(args.before), files_under(args.after)
    problems = 0
    for missing in sorted(a - b):
        print(f"only in {args.before}: {missing}")
        problems += 1
    for extra in sorted(b - a):
        print(f"only in {args.after}: {extra}")
        problems += 1
    same = 0
    for rel in sorted(a & b):
        x = normalised(os.path.join(args.before, rel), args.before)
        y = normalised(os.path.join(args.after, rel), args.after)
        if x == y:
            same += 1
            continue
        problems += 1
        print(f"differs: {rel}")
        if isinstance(x, str) and isinstance(y, str):
            shown = 0
            for i, (lx, ly) in enumerate(zip(x.split("\n"), y.split("\n"))):
                if lx != ly and shown < args.show:
                    print(f"  line {i + 1}:\n    - {lx[:200]}\n    + {ly[:200]}")
                    shown += 1
            if x.count("\n") != y.count("\n"):
                print(f"  lines: {x.count(chr(10))} vs {y.count(chr(10))}")
    print(f"{same} files equal (timings masked), {problems} differences")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

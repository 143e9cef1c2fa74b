"""Every C++ source and header of the project follows .clang-format (clang-format --dry-run).

    /usr/bin/python3 tests/style/clang_format_test.py <source root>

Exit 0 when every file is formatted; 1, naming each file and clang-format's first complaint
about it, when one is not; 2 when clang-format cannot be run. Fix: clang-format -i <file>.
Build folders (build*/) and hidden folders are not read. The clang-format is the one
scripts/install-deps.sh installs (Debian 12's, version 14): another version may break lines
otherwise.
"""

import os
import shutil
import subprocess
import sys

SOURCE_SUFFIXES = (".cpp", ".hpp")


def source_files(root):
    for folder, subfolders, files in os.walk(root):
        subfolders[:] = sorted(d for d in subfolders
                               if not d.startswith(".") and not d.startswith("build"))
        for name in sorted(files):
            if name.endswith(SOURCE_SUFFIXES):
                yield os.path.join(folder, name)


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    root = os.path.abspath(sys.argv[1])
    clang_format = shutil.which("clang-format")
    if clang_format is None:
        print("clang_format_test: clang-format is not installed (scripts/install-deps.sh "
              "installs it)", file=sys.stderr)
        return 2
    files = list(source_files(root))
    if not files:
        print(f"clang_format_test: no {' or '.join(SOURCE_SUFFIXES)} file under {root}",
              file=sys.stderr)
        return 2
    first_complaint = {}  # file -> "line:column" of clang-format's first complaint
    # Two hundred files per call keeps the command line short and the calls few.
    for start in range(0, len(files), 200):
        result = subprocess.run([clang_format, "--dry-run", "--Werror", *files[start:start + 200]],
                                cwd=root, capture_output=True, text=True)
        if result.returncode == 0:
            continue
        complaints = 0
        for line in result.stderr.splitlines():
            where, marker, _ = line.partition(": error: code should be clang-formatted")
            if marker:
                path, line_number, column = where.rsplit(":", 2)
                first_complaint.setdefault(path, f"{line_number}:{column}")
                complaints += 1
        if complaints == 0:  # clang-format failed for another reason
            print(result.stderr, file=sys.stderr)
            return 2
    for path, where in first_complaint.items():
        relative = os.path.relpath(path, root)
        print(f"not clang-formatted: {relative}:{where} (fix: clang-format -i {relative})")
    if first_complaint:
        print(f"{len(first_complaint)} of {len(files)} files do not follow .clang-format")
        return 1
    print(f"{len(files)} files follow .clang-format")
    return 0


if __name__ == "__main__":
    sys.exit(main())

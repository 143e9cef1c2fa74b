#!/usr/bin/python3
"""The layering of docs/layout.md, checked on the code (unittest, run by CTest).

- Every `#include "X/..."` in our code outside tests/, bench/, fuzz/ and examples/ names the
  includer's own library or one that docs/layout.md's layering table allows it.
- A library that includes another library's header links it: the include closure is within the
  closure of its CMake `DEPS`/`PRIVATE_DEPS` (wifislam_library in each folder's CMakeLists.txt).
- No header of ours includes itself through others (a cycle compiles under #pragma once, but
  whichever header is read first sees the other half-defined).

    /usr/bin/python3 tests/layering/layering_test.py SOURCE_DIR
"""

import os
import re
import sys
import unittest

SOURCE_DIR = None
SKIPPED_TOP = {"tests", "bench", "fuzz", "examples", "build", ".git", "scripts", "docs"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def layering_table(source_dir, marker="<!-- layering table"):
    """{library folder: set of folders it may include}, from docs/layout.md (or, with the
    public-headers marker, {library folder: set of its public headers})."""
    with open(os.path.join(source_dir, "docs", "layout.md")) as f:
        text = f.read()
    start = text.index(marker)
    table = {}
    for line in text[start:].splitlines()[1:]:
        if not line.startswith("|"):
            if table:
                break
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells[0] in ("library", "---", ""):
            continue
        library = cells[0].strip("`")
        table[library] = set(re.findall(r"`([^`]+)`", cells[1] if len(cells) > 1 else ""))
    return table


def library_of(path, libraries):
    """The longest library folder holding `path` (a path relative to the source dir)."""
    best = None
    for library in libraries:
        if path == library or path.startswith(library + "/"):
            if best is None or len(library) > len(best):
                best = library
    return best


def source_files(source_dir):
    for root, dirs, files in os.walk(source_dir):
        rel_root = os.path.relpath(root, source_dir)
        if rel_root == ".":
            dirs[:] = [d for d in dirs if d not in SKIPPED_TOP]
            continue
        for name in files:
            if name.endswith((".cpp", ".hpp", ".h", ".hpp.in")):
                yield os.path.normpath(os.path.join(rel_root, name))


def includes_by_file(source_dir):
    out = {}
    for path in source_files(source_dir):
        with open(os.path.join(source_dir, path), errors="replace") as f:
            out[path] = INCLUDE.findall(f.read())
    return out


def cmake_links(source_dir, libraries):
    """{library folder: set of library folders it links directly}, from wifislam_library()."""
    target_folder, deps = {}, {}
    for library in libraries:
        cmake = os.path.join(source_dir, library, "CMakeLists.txt")
        if not os.path.exists(cmake):
            continue
        with open(cmake) as f:
            text = f.read()
        for match in re.finditer(r"wifislam_library\((\w+)(.*?)\)", text, re.S):
            target_folder[match.group(1)] = library
            tokens = match.group(2).split()
            linked, keep = set(), False
            for token in tokens:
                if token in ("DEPS", "PRIVATE_DEPS"):
                    keep = True
                elif token == "SOURCES":
                    keep = False
                elif keep:
                    linked.add(token)
            deps[library] = linked
    return {lib: {target_folder[t] for t in linked if t in target_folder}
            for lib, linked in deps.items()}


def closure(graph, start):
    seen, todo = set(), [start]
    while todo:
        for nxt in graph.get(todo.pop(), ()):
            if nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    return seen


class Layering(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.table = layering_table(SOURCE_DIR)
        cls.includes = includes_by_file(SOURCE_DIR)

    def test_the_table_names_every_library_folder(self):
        for path in self.includes:
            self.assertIsNotNone(library_of(path, self.table),
                                 f"{path}: its folder has no row in docs/layout.md's table")

    def test_every_include_follows_an_arrow(self):
        breaks = []
        for path, targets in sorted(self.includes.items()):
            own = library_of(path, self.table)
            for target in targets:
                other = library_of(target, self.table)
                if other is None or other == own:
                    continue
                if other not in self.table[own]:
                    breaks.append(f"{path} includes {target}: {own} -> {other} is no arrow")
        self.assertEqual(breaks, [], "\n".join(breaks))

    def test_other_libraries_include_only_declared_public_headers(self):
        public = layering_table(SOURCE_DIR, "<!-- public headers")
        reached = []
        for path, targets in sorted(self.includes.items()):
            own = library_of(path, self.table)
            for target in targets:
                other = library_of(target, self.table)
                if other in public and other != own and target not in public[other]:
                    reached.append(f"{path} includes {target}, which {other} does not declare public")
        self.assertEqual(reached, [], "\n".join(reached))

    def test_a_library_links_what_it_includes(self):
        links = cmake_links(SOURCE_DIR, self.table)
        missing = []
        for library in sorted(links):
            linked = closure(links, library)
            included = set()
            for path, targets in self.includes.items():
                if library_of(path, self.table) != library:
                    continue
                for target in targets:
                    other = library_of(target, self.table)
                    if other and other != library and os.path.exists(
                            os.path.join(SOURCE_DIR, library_of(target, self.table))):
                        included.add((other, path, target))
            for other, path, target in sorted(included):
                if other in links and other not in linked:
                    missing.append(f"{library} includes {target} ({path}) but does not link {other}")
        self.assertEqual(missing, [], "\n".join(missing))

    def test_no_header_includes_itself_through_others(self):
        headers = {p: [t for t in targets if t in self.includes]
                   for p, targets in self.includes.items() if p.endswith(".hpp")}
        state, cycles = {}, []

        def visit(node, stack):
            state[node] = 1
            stack.append(node)
            for nxt in headers.get(node, ()):
                if state.get(nxt) == 1:
                    cycles.append(" -> ".join(stack[stack.index(nxt):] + [nxt]))
                elif nxt not in state:
                    visit(nxt, stack)
            stack.pop()
            state[node] = 2

        for header in sorted(headers):
            if header not in state:
                visit(header, [])
        self.assertEqual(cycles, [], "\n".join(cycles))


class TheCheckCanFail(unittest.TestCase):
    """The checks catch what they are for (so a broken parser cannot pass everything)."""

    def test_a_backward_arrow_is_not_in_the_table(self):
        table = layering_table(SOURCE_DIR)
        self.assertNotIn("slam", table["core"])
        self.assertNotIn("sim/generate", table["slam"])
        self.assertNotIn("slam", table["eval"])
        self.assertIn("core", table["slam"])
        self.assertEqual(library_of("radio_model/radio_map.hpp", table), "radio_model")
        self.assertEqual(library_of("interop/rosbag/rosbag_writer.hpp", table), "interop/rosbag")

    def test_public_headers_are_read(self):
        public = layering_table(SOURCE_DIR, "<!-- public headers")
        self.assertIn("slam/slam_options.hpp", public["slam"])
        self.assertNotIn("slam/graph/pose_graph.hpp", public["slam"])

    def test_links_are_read_from_cmake(self):
        links = cmake_links(SOURCE_DIR, layering_table(SOURCE_DIR))
        self.assertIn("core", closure(links, "study"))
        self.assertNotIn("slam", closure(links, "eval"))


if __name__ == "__main__":
    SOURCE_DIR = os.path.abspath(sys.argv.pop(1))
    unittest.main()

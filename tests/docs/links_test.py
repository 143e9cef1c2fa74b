#!/usr/bin/env python3
"""Every relative link in the project's Markdown files names a file or folder that exists
(unittest, run by CTest). Moving a page or a figure without following its links fails here, naming
the page, the line and the link.

Usage: links_test.py SOURCE_DIR
"""
import os
import re
import subprocess
import sys
import unittest

# [text](target) and ![alt](target); a target ends at the first space or ')'. Reference-style
# definitions "[x]: target" too.
INLINE_LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE_LINK = re.compile(r"^\s*\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+.*)?$")
CODE_SPAN = re.compile(r"`[^`]*`")


def tracked_markdown(source_dir):
    out = subprocess.run(["git", "-C", source_dir, "ls-files", "*.md"], check=True,
                         capture_output=True, text=True).stdout
    return [line for line in out.splitlines() if line]


def links_of(text):
    """(line number, target) of every link outside code blocks and code spans."""
    in_fence = False
    for number, line in enumerate(text.splitlines(), start=1):
        if line.lstrip().startswith("```"):
            in_fence = not in_fence
            continue
        if in_fence:
            continue
        plain = CODE_SPAN.sub("", line)
        for match in INLINE_LINK.finditer(plain):
            yield number, match.group(1)
        match = REFERENCE_LINK.match(plain)
        if match:
            yield number, match.group(1)


def is_relative(target):
    return not re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target) and not target.startswith("#")


def broken_links(source_dir, pages):
    broken = []
    for page in pages:
        with open(os.path.join(source_dir, page), encoding="utf-8") as f:
            text = f.read()
        for number, target in links_of(text):
            if not is_relative(target):
                continue
            path = target.split("#", 1)[0].split("?", 1)[0]
            if not path:
                continue
            resolved = os.path.normpath(os.path.join(source_dir, os.path.dirname(page), path))
            if not os.path.exists(resolved):
                broken.append(f"{page}:{number}: {target} (no {os.path.relpath(resolved, source_dir)})")
    return broken


class DocsLinks(unittest.TestCase):
    def test_every_relative_link_resolves(self):
        pages = tracked_markdown(SOURCE_DIR)
        self.assertGreater(len(pages), 20, "expected the project's Markdown pages")
        broken = broken_links(SOURCE_DIR, pages)
        self.assertEqual(broken, [], "broken links:\n" + "\n".join(broken))

    def test_a_link_to_a_missing_page_is_caught(self):
        # The checker itself: a page that links to a file that does not exist, and one that links
        # inside a code span (not a link), in a scratch folder the test removes.
        import shutil
        import tempfile
        scratch = tempfile.mkdtemp(prefix="wifislam_docs_links_")
        try:
            with open(os.path.join(scratch, "page.md"), "w") as f:
                f.write("see [there](missing/page.md) and `[not](a/link.md)`\n"
                        "and [here](page.md#top), [web](https://example.org)\n")
            self.assertEqual(broken_links(scratch, ["page.md"]),
                             ["page.md:1: missing/page.md (no missing/page.md)"])
        finally:
            shutil.rmtree(scratch)


if __name__ == "__main__":
    SOURCE_DIR = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.getcwd()
    unittest.main()

#!/usr/bin/env python3
"""Moves library folders into namespaces of their own and qualifies every use.

Usage: scripts/move_namespace.py [--adl NAME,...] REPO PARENT FOLDER:CHILD [FOLDER:CHILD ...]
Example: scripts/move_namespace.py --adl to_string . wifislam::sim sim/scene:scene sim/world:world

--adl names functions overloaded across namespaces (to_string): their unqualified calls are left
to argument-dependent lookup, which finds the moved overloads beside the moved types.

Each FOLDER's files (not its subfolders) declare in PARENT today; afterwards they declare in
PARENT::CHILD. The names each folder's headers declare at the top of PARENT are read from the
headers themselves, then every C++ file of the repository is rewritten token by token:

  - `sim::Scene` and `wifislam::sim::Scene` become `sim::scene::Scene`;
  - an unqualified `Scene` where PARENT is in scope (code inside PARENT, or after a
    `using namespace PARENT;`) becomes `scene::Scene`, except inside PARENT::CHILD itself.

Comments, string literals, preprocessor lines and the arguments of GoogleTest's TEST macros are
left alone, as are member accesses (`.x`, `->x`) and names after another qualifier. A lower-case
name (a function) is qualified only where it is called or instantiated (followed by `(` or `<`),
so a local variable of the same spelling keeps its meaning. A name declared by two of the moved
folders is reported and left for the compiler to point at, as are forward declarations of moved
names, which would otherwise declare new types.

The compiler is the final check, and scripts/snapshot_outputs.sh proves the outputs unchanged.
"""

import pathlib
import re
import sys

SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".cc", ".ipp"}
SKIPPED_DIRS = {"build", ".git", "third_party"}
KEYWORDS = set(
    """alignas alignof and asm auto bool break case catch char char16_t char32_t char8_t class
    co_await co_return co_yield concept const consteval constexpr constinit const_cast continue
    decltype default delete do double dynamic_cast else enum explicit export extern false float
    for friend goto if inline int long mutable namespace new noexcept not nullptr operator or
    private protected public register reinterpret_cast requires return short signed sizeof static
    static_assert static_cast struct switch template this thread_local throw true try typedef
    typeid typename union unsigned using virtual void volatile wchar_t while final override""".split()
)
# Keywords after which a name is an expression, so an unqualified use is still a use.
EXPRESSION_KEYWORDS = {"return", "case", "throw", "else", "do", "new", "co_return", "sizeof", "const",
                       "constexpr", "static", "inline", "typename", "friend", "virtual", "explicit",
                       "mutable", "volatile", "extern", "thread_local", "and", "or", "not", "public",
                       "protected", "private", "co_await", "co_yield", "struct", "class"}
TEST_MACROS = {"TEST", "TEST_F", "TEST_P", "TYPED_TEST", "INSTANTIATE_TEST_SUITE_P",
               "TYPED_TEST_SUITE", "TYPED_TEST_SUITE_P", "REGISTER_TYPED_TEST_SUITE_P"}

TOKEN_RE = re.compile(
    r"""(?P<pp>^[ \t]*\#(?:[^\n\\]|\\.)*(?:\\\n(?:[^\n\\]|\\.)*)*)
      |(?P<comment>//[^\n]*|/\*.*?\*/)
      |(?P<raw>R"(?P<delim>[^()\\ ]{0,16})\(.*?\)(?P=delim)")
      |(?P<string>(?:u8|u|U|L)?"(?:[^"\\\n]|\\.)*")
      |(?P<char>(?:u8|u|U|L)?'(?:[^'\\\n]|\\.)*')
      |(?P<ident>[A-Za-z_][A-Za-z_0-9]*)
      |(?P<number>\.?[0-9](?:[0-9A-Za-z_.']|[eEpP][+-])*)
      |(?P<punct>::|->|[^\sA-Za-z_0-9])
      |(?P<space>\s+)""",
    re.S | re.M | re.X,
)


class Token:
    __slots__ = ("kind", "text", "start")

    def __init__(self, kind, text, start):
        self.kind, self.text, self.start = kind, text, start


def tokenize(text):
    tokens = []
    for match in TOKEN_RE.finditer(text):
        kind = match.lastgroup
        if kind == "delim":
            kind = "raw"
        if kind in ("space",):
            continue
        if kind in ("comment", "pp", "raw", "string", "char"):
            kind = "skip"
        tokens.append(Token(kind, match.group(0), match.start()))
    return tokens


def code_tokens(tokens):
    return [t for t in tokens if t.kind != "skip"]


def namespace_path_at(code, i, stack):
    """Handles a `namespace` token at code[i]; returns (new index, frame or None for an alias)."""
    j = i + 1
    parts = []
    while j < len(code) and code[j].text not in ("{", "=", ";"):
        if code[j].kind == "ident" and code[j].text != "inline":
            parts.append(code[j].text)
        j += 1
    if j < len(code) and code[j].text == "{":
        base = stack[-1]["path"] if stack else ""
        path = "::".join([p for p in [base] + parts if p])
        return j, path
    return j, None


class Walker:
    """Walks code tokens, keeping the namespace path and using-directives in scope."""

    def __init__(self, code):
        self.code = code
        self.stack = [{"path": "", "ns": True, "usings": set()}]

    def frames(self):
        i = 0
        code = self.code
        while i < len(code):
            token = code[i]
            if token.text == "namespace" and not (i > 0 and code[i - 1].text == "using"):
                j, path = namespace_path_at(code, i, self.stack)
                if path is not None:
                    self.stack.append({"path": path, "ns": True, "usings": set()})
                i = j + 1
                continue
            if token.text == "using" and i + 1 < len(code) and code[i + 1].text == "namespace":
                j = i + 2
                name = []
                while j < len(code) and code[j].text != ";":
                    name.append(code[j].text)
                    j += 1
                self.stack[-1]["usings"].add("".join(name).lstrip(":"))
                yield i, token
                i = j + 1
                continue
            if token.text == "{":
                self.stack.append({"path": self.stack[-1]["path"], "ns": False, "usings": set()})
            elif token.text == "}":
                if len(self.stack) > 1:
                    self.stack.pop()
            yield i, token
            i += 1

    def path(self):
        return self.stack[-1]["path"]

    def using_directives(self):
        seen = set()
        for frame in self.stack:
            seen |= frame["usings"]
        return seen


def declared_names(text, parent):
    """Names a header declares directly in `parent` (types, functions, constants, namespaces)."""
    code = code_tokens(tokenize(text))
    walker = Walker(code)
    names, forwards = set(), set()
    paren = 0
    template_angles = 0
    in_head = False
    in_initializer = False
    for i, token in walker.frames():
        prev = code[i - 1].text if i > 0 else ""
        nxt = code[i + 1].text if i + 1 < len(code) else ""
        if token.text == "namespace" and prev == "using":
            continue
        frame = walker.stack[-1]
        if token.text == "(":
            paren += 1
        elif token.text == ")":
            paren -= 1
        at_parent = frame["ns"] and frame["path"] == parent and paren == 0
        if token.text == "namespace":
            # `namespace schema {` inside parent names a namespace that moves with the folder.
            if at_parent and nxt and code[i + 1].kind == "ident" and i + 2 < len(code) and code[i + 2].text == "{":
                names.add(nxt)
            continue
        if not at_parent:
            continue
        if token.text == "template":
            template_angles = 0
            continue
        if token.text == "<" and (prev == "template" or template_angles > 0):
            template_angles += 1
            continue
        if token.text == ">" and template_angles > 0:
            template_angles -= 1
            continue
        if template_angles > 0:
            continue
        if token.text in ("struct", "class", "union", "enum"):
            in_head = True
            j = i + 1
            while j < len(code) and code[j].text in ("class", "struct", "[", "]", "alignas"):
                j += 1
            if j < len(code) and code[j].kind == "ident":
                name = code[j].text
                after = code[j + 1].text if j + 1 < len(code) else ""
                if after == ";":
                    forwards.add(name)
                elif prev != "friend":
                    names.add(name)
            continue
        if token.text in ("{", ";"):
            in_head = False
            in_initializer = False
            continue
        if token.text == "=":
            if prev and code[i - 2].text == "using" and code[i - 1].kind == "ident":
                names.add(code[i - 1].text)
            in_initializer = True
            continue
        if in_head or in_initializer or token.kind != "ident" or token.text in KEYWORDS:
            continue
        if token.text.isupper() or prev in ("::", ".", "->", "operator", "~"):
            continue
        if nxt in ("(", "=", ";", "{", "["):
            names.add(token.text)
    # Nested namespaces: parent::X { ... }
    for match in re.finditer(r"namespace\s+" + re.escape(parent) + r"::(\w+)", text):
        names.add(match.group(1))
    # Re-exports (`using radio_model::WallMaterial;` at the top of parent): their uses elsewhere
    # name the namespace they come from, not the folder that re-exports them.
    reexports = {}
    body = re.search(r"namespace\s+" + re.escape(parent) + r"\s*\{(.*)", text, re.S)
    if body:
        for match in re.finditer(r"^using\s+((?:\w+::)+)(\w+)\s*;", body.group(1), re.M):
            reexports[match.group(2)] = match.group(1)[:-2]
    for name in reexports:
        names.discard(name)
    return names, forwards, reexports


def qualifier_chain(code, i):
    """The identifiers before code[i] joined by `::`, e.g. ['wifislam', 'sim'] for wifislam::sim::X."""
    chain = []
    j = i - 1
    while j >= 1 and code[j].text == "::" and code[j - 1].kind == "ident":
        chain.insert(0, code[j - 1].text)
        j -= 2
    return chain


def rewrite_file(text, parent, moved, children, where="?", reexports=None):
    """Returns text with the moved names qualified; `moved` maps name -> child, `reexports` maps a
    name parent re-exported with a using-declaration -> the namespace it comes from."""
    reexports = reexports or {}
    replaces = []
    tokens = tokenize(text)
    code = code_tokens(tokens)
    walker = Walker(code)
    parent_last = parent.split("::")[-1]
    parent_parts = parent.split("::")
    inserts = []
    macro_depth = None
    paren = 0
    for i, token in walker.frames():
        if token.text == "(":
            paren += 1
        elif token.text == ")":
            paren -= 1
            if macro_depth is not None and paren < macro_depth:
                macro_depth = None
        if token.kind == "ident" and token.text in TEST_MACROS and i + 1 < len(code) and code[i + 1].text == "(":
            macro_depth = paren + 1
            continue
        if macro_depth is not None:
            continue
        if token.kind != "ident" or (token.text not in moved and token.text not in reexports):
            continue
        if token.text in reexports:
            handle_reexport(code, i, walker, parent, reexports[token.text], inserts, replaces)
            continue
        child = moved[token.text]
        prev = code[i - 1].text if i > 0 else ""
        nxt = code[i + 1].text if i + 1 < len(code) else ""
        if prev in (".", "->", "~", "operator", "goto"):
            continue
        is_function = token.text[0].islower() and not token.text.startswith("k")
        is_namespace = token.text in children.values() or nxt == "::" and token.text.islower()
        if prev == "::":
            chain = qualifier_chain(code, i)
            if chain and chain[-1] == parent_last and parent_parts[-len(chain):] == chain:
                inserts.append((token.start, child + "::"))
            continue
        here = walker.path()
        visible = here == parent or here.startswith(parent + "::") or parent in walker.using_directives()
        if not visible:
            continue
        if here == parent + "::" + child or here.startswith(parent + "::" + child + "::"):
            continue
        if prev in ("struct", "class", "enum", "union") and nxt in (";", "{", ":"):
            print(f"{where}: forward declaration or definition of {token.text} at offset {token.start}: fix by hand", file=sys.stderr)
            continue
        if i > 0 and code[i - 1].kind == "ident" and prev not in EXPRESSION_KEYWORDS and not (prev == "using" and nxt != "="):
            # `Type name(...)`: a declaration of a local of the same spelling.
            continue
        if is_function and not is_namespace and nxt not in ("(", "<"):
            continue
        inserts.append((token.start, child + "::"))
    edits = [(position, position, prefix) for position, prefix in inserts] + replaces
    if not edits:
        return text
    out = []
    last = 0
    for start, end, replacement in sorted(edits):
        out.append(text[last:start])
        out.append(replacement)
        last = end
    out.append(text[last:])
    return "".join(out)


def handle_reexport(code, i, walker, parent, source, inserts, replaces):
    """`sim::WallMaterial` -> `radio_model::WallMaterial` (and `wifislam::sim::` ->
    `wifislam::radio_model::`); an unqualified use where parent is in scope gains `radio_model::`.
    Uses inside the re-exporting folder's namespace keep the using-declaration and are left alone."""
    token = code[i]
    source, reexporter = source
    prev = code[i - 1].text if i > 0 else ""
    if prev in (".", "->", "~", "operator"):
        return
    parent_parts = parent.split("::")
    if prev == "::":
        chain = qualifier_chain(code, i)
        if chain and chain[-1] == parent_parts[-1] and parent_parts[-len(chain):] == chain:
            sim_token = code[i - 2]
            replaces.append((sim_token.start, sim_token.start + len(sim_token.text), source))
        return
    if code[i - 1].kind == "ident" and prev == "using":
        return
    here = walker.path()
    if here == parent + "::" + reexporter or here.startswith(parent + "::" + reexporter + "::"):
        return  # the using-declaration is in scope here
    if here.startswith(parent) or parent in walker.using_directives():
        inserts.append((token.start, source + "::"))


def repo_sources(repo):
    for path in sorted(repo.rglob("*")):
        if path.suffix in SOURCE_SUFFIXES and path.is_file():
            if not any(part in SKIPPED_DIRS for part in path.relative_to(repo).parts):
                yield path


def main(argv):
    adl = set()
    if len(argv) > 2 and argv[1] == "--adl":
        adl = set(argv[2].split(","))
        argv = argv[:1] + argv[3:]
    if len(argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    repo = pathlib.Path(argv[1]).resolve()
    parent = argv[2]
    children = {}
    for spec in argv[3:]:
        folder, _, child = spec.partition(":")
        if not child or not (repo / folder).is_dir():
            print(f"move_namespace: '{spec}' is not FOLDER:CHILD with FOLDER a folder of {repo}", file=sys.stderr)
            return 2
        children[folder] = child

    owners = {}
    reexports = {}
    for folder, child in children.items():
        for header in sorted((repo / folder).glob("*.hpp")):
            names, _, reexported = declared_names(header.read_text(), parent)
            for name in names - {child}:
                owners.setdefault(name, set()).add(child)
            reexports.update({name: (source, child) for name, source in reexported.items()})
    moved = {}
    for name, owned_by in sorted(owners.items()):
        if name in adl:
            continue
        if len(owned_by) == 1:
            moved[name] = next(iter(owned_by))
        else:
            print(f"move_namespace: '{name}' is declared by {sorted(owned_by)}: left alone", file=sys.stderr)

    # 1. The folders' own files declare in the child namespace.
    opening = re.compile(r"(namespace\s+)" + re.escape(parent) + r"(?=(::\w+)?(?:::\w+)*\s*\{)")
    closing = re.compile(r"(//\s*namespace\s+)" + re.escape(parent) + r"\b(?=(::\w+)?)")
    for folder, child in children.items():
        for path in sorted((repo / folder).iterdir()):
            if path.suffix in SOURCE_SUFFIXES:
                text = path.read_text()
                # A folder's nested namespace of the child's own name (rtabmap's internals in
                # parent::rtabmap) merges into the child rather than nesting twice.
                text = opening.sub(lambda m: m.group(1) + parent + ("" if m.group(2) == "::" + child else "::" + child), text)
                text = closing.sub(lambda m: m.group(1) + parent + ("" if m.group(2) == "::" + child else "::" + child), text)
                path.write_text(text)

    # 2. Every use is qualified.
    changed = 0
    for path in repo_sources(repo):
        text = path.read_text()
        new_text = rewrite_file(text, parent, moved, children, path.relative_to(repo), reexports)
        if new_text != text:
            path.write_text(new_text)
            changed += 1
    print(f"move_namespace: {len(moved)} names moved into {len(children)} namespaces; {changed} files rewritten")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

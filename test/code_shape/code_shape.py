#!/usr/bin/python3
"""The product code's shape (doc/design.md): no function longer than --max-lines lines in
sf_filter/ and sf_estimation/ (tests and benchmarks excluded), no include cycle between the
directories of sf_filter/include/sf_filter, and neither of node/ and replay/ including the other.

Usage: code_shape.py [--root DIR] [--max-lines N]
Prints one line per violation and exits 1 when there is one. Standard library only: a
tokenizer that knows C++'s comments, literals and braces, not a parser, so that the check runs
without a build (clang-tidy's readability-function-size needs the compile commands).

A function is a brace block opened after a parameter list (or a lambda's capture list), not after
if/for/while/switch/catch; its length counts its lines from its name (or capture list) to its
closing brace, so that a constructor's initialiser list counts as well.
"""

import argparse
import os
import re
import sys

PRODUCT_DIRS = ("sf_filter/include", "sf_filter/src", "sf_estimation/include", "sf_estimation/src")
SOURCE_SUFFIXES = (".hpp", ".cpp", ".h")
INCLUDE_ROOT = "sf_filter/include/sf_filter"
CONTROL = {"if", "for", "while", "switch", "catch"}
QUALIFIERS = {"const", "noexcept", "override", "final", "mutable", "constexpr", "volatile", "&",
              "&&"}
TOKEN = re.compile(r"""
    (?P<newline>\n)
  | (?P<space>[ \t\r\f\v]+)
  | (?P<comment>//[^\n]*|/\*.*?\*/)
  | (?P<string>(?:u8|u|U|L)?R"(?P<delim>[^(\s]*)\(.*?\)(?P=delim)"
              |(?:u8|u|U|L)?"(?:\\.|[^"\\\n])*"|'(?:\\.|[^'\\\n])*')
  | (?P<word>[A-Za-z_][A-Za-z_0-9]*)
  | (?P<number>\.?[0-9](?:[eEpP][+-]|[0-9A-Za-z_.'])*)
  | (?P<op>->|::|&&|\|\||[{}()\[\];,:<>=&*~!?%^|+\-./])
""", re.VERBOSE | re.DOTALL)


def tokens(text):
    """(token, line) pairs of `text` without comments, literals' contents and preprocessor
    lines (a macro's body is not a function of the product)."""
    out = []
    line = 1
    pos = 0
    at_line_start = True
    while pos < len(text):
        if at_line_start:
            m = re.match(r"[ \t]*#", text[pos:pos + 200])
            if m:  # a directive, with its continuation lines
                end = pos
                while True:
                    nl = text.find("\n", end)
                    if nl < 0:
                        end = len(text)
                        break
                    if text[nl - 1] == "\\":
                        line += 1
                        end = nl + 1
                        continue
                    end = nl
                    break
                pos = end
                continue
        m = TOKEN.match(text, pos)
        if not m:
            out.append((text[pos], line))  # anything else (e.g. `@`, `$`) is a token of its own
            pos += 1
            at_line_start = False
            continue
        kind = m.lastgroup if m.lastgroup != "delim" else "string"
        value = m.group(0)
        if kind == "newline":
            line += 1
            at_line_start = True
        elif kind in ("space",):
            pass
        elif kind == "comment":
            line += value.count("\n")
        elif kind == "string":
            out.append(('""', line))
            line += value.count("\n")
            at_line_start = False
        else:
            out.append((value, line))
            at_line_start = False
        pos = m.end()
    return out


def _matching_open(toks, close_index, open_char, close_char):
    depth = 0
    for i in range(close_index, -1, -1):
        t = toks[i][0]
        if t == close_char:
            depth += 1
        elif t == open_char:
            depth -= 1
            if depth == 0:
                return i
    return None


def _skip_qualifiers(toks, i):
    """Index of the last token before the qualifiers and trailing return type that end at i."""
    while i >= 0:
        t = toks[i][0]
        if t in QUALIFIERS:
            i -= 1
        elif t == ")" and i >= 1:  # noexcept(...)
            j = _matching_open(toks, i, "(", ")")
            if j is not None and j >= 1 and toks[j - 1][0] == "noexcept":
                i = j - 2
            else:
                return i
        else:
            # A trailing return type: words, ::, <>, commas, & and * back to `->`.
            j = i
            while j >= 0 and (re.match(r"^[A-Za-z_0-9]+$", toks[j][0]) or
                              toks[j][0] in ("::", "<", ">", ",", "&", "*", "&&")):
                j -= 1
            if j >= 0 and j < i and toks[j][0] == "->":
                i = j - 1
                continue
            return i
    return i


def function_start(toks, brace):
    """Index of the token that starts the function whose body opens at toks[brace], or None
    when the block is not a function's body."""
    i = _skip_qualifiers(toks, brace - 1)
    if i < 0:
        return None
    t = toks[i][0]
    if t == "]":  # a lambda without parameter list
        return _matching_open(toks, i, "[", "]")
    if t not in (")", "}"):
        return None
    # Walk back over a constructor's initialiser list to the parameter list.
    while True:
        opener = _matching_open(toks, i, "(" if toks[i][0] == ")" else "{",
                                toks[i][0])
        if opener is None or opener == 0:
            return None
        before = opener - 1
        name = toks[before][0]
        if toks[i][0] == ")":
            if name in CONTROL or (name == "constexpr" and before >= 1
                                   and toks[before - 1][0] == "if"):
                return None
            if name == "]":  # a lambda's parameter list
                return _matching_open(toks, before, "[", "]")
        if not re.match(r"^[A-Za-z_~][A-Za-z_0-9]*$|^>$|^\)$|^\]$", name):
            return None
        # the name, qualified or templated
        j = before
        if name == ">":
            j = _matching_open(toks, j, "<", ">")
            if j is None:
                return None
            j -= 1
        while j >= 2 and toks[j - 1][0] == "::":
            j -= 2
        if j >= 1 and toks[j - 1][0] == "~":
            j -= 1
        sep = toks[j - 1][0] if j >= 1 else ""
        if sep in (",", ":") and toks[i][0] in (")", "}"):
            k = _skip_qualifiers(toks, j - 2)
            if k >= 0 and toks[k][0] in (")", "}") and (sep == "," or toks[k][0] == ")"):
                if sep == ":" and toks[k][0] == ")":
                    i = k  # the parameter list before the initialiser list
                    continue
                i = k
                continue
        if toks[i][0] == "}":
            return None
        return j


def long_functions(path, max_lines):
    with open(path, encoding="utf-8", errors="replace") as f:
        toks = tokens(f.read())
    found = []
    stack = []
    for index, (t, line) in enumerate(toks):
        if t == "{":
            start = function_start(toks, index)
            stack.append(None if start is None else (toks[start][1], toks[start - 1][0]
                                                      if start else ""))
        elif t == "}" and stack:
            entry = stack.pop()
            if entry is None:
                continue
            first_line, _ = entry
            lines = line - first_line + 1
            if lines > max_lines:
                found.append((first_line, lines))
    return found


def product_files(root):
    for top in PRODUCT_DIRS:
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, top)):
            dirnames.sort()
            for name in sorted(filenames):
                if name.endswith(SOURCE_SUFFIXES):
                    yield os.path.join(dirpath, name)


def function_violations(root, max_lines):
    out = []
    for path in product_files(root):
        for first_line, lines in long_functions(path, max_lines):
            out.append("%s:%d: function of %d lines (more than %d)" %
                       (os.path.relpath(path, root), first_line, lines, max_lines))
    return out


INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]sf_filter/([^/">]+)/', re.MULTILINE)


def directory_graph(root):
    """{directory: {directory it includes: first file that does}} of sf_filter's headers; a file
    at the top of sf_filter/include/sf_filter is a node of its own."""
    graph = {}
    base = os.path.join(root, INCLUDE_ROOT)
    for dirpath, _, filenames in os.walk(base):
        for name in sorted(filenames):
            path = os.path.join(dirpath, name)
            rel = os.path.relpath(path, base)
            source = rel.split(os.sep)[0]
            with open(path, encoding="utf-8", errors="replace") as f:
                for target in INCLUDE.findall(f.read()):
                    if target != source:
                        graph.setdefault(source, {}).setdefault(target, rel)
    return graph


def include_cycles(graph):
    """Strongly connected components of more than one directory (Tarjan)."""
    index, low, on_stack, stack, components = {}, {}, set(), [], []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, {})):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                components.append(sorted(component))

    for v in sorted(set(graph) | {w for ts in graph.values() for w in ts}):
        if v not in index:
            visit(v)
    return components


def cycle_violations(root):
    graph = directory_graph(root)
    out = []
    for component in include_cycles(graph):
        edges = ["%s -> %s (%s)" % (a, b, graph[a][b]) for a in component
                 for b in sorted(graph.get(a, {})) if b in component]
        out.append("include cycle between %s: %s" % (", ".join(component), "; ".join(edges)))
    return out


# The online node and the offline replay share what they share from the layers below them
# (core/, definition/, io/): neither includes the other (doc/design.md, "Layers").
SEPARATE = (("node", "replay"), ("replay", "node"))


def layer_violations(root):
    graph = directory_graph(root)
    return ["%s includes %s (%s): they share what they share from a lower layer" %
            (a, b, graph[a][b]) for a, b in SEPARATE if b in graph.get(a, {})]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                       "..", ".."))
    parser.add_argument("--max-lines", type=int, default=60)
    args = parser.parse_args(argv)
    problems = (function_violations(args.root, args.max_lines) + cycle_violations(args.root) +
                layer_violations(args.root))
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

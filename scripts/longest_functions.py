#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): The CGAL Symmetry_transform developers
"""Prints the longest functions of the C++ files of a folder (default: include/), longest first.

usage: scripts/longest_functions.py [FOLDER_OR_FILE ...] [--top N] [--max-lines L]

A function's length is the number of lines of its body, from the line of its opening brace to the
line of its closing brace (a body on one line counts 1), after comments, string and character
literals and preprocessor lines are removed. Functions are the definitions at namespace or class
scope (free functions, member functions, constructors, operators); a lambda or a local class counts
in the function that holds it. Each line printed reads "LINES  FILE:LINE  NAME".

--top N        prints the N longest (default 10).
--max-lines L  prints instead every function longer than L lines, and exits with status 1 if there
               is one (the house limit is 60: the ctest test function_length).
"""
import argparse
import os
import re
import sys

CONTROL = {"if", "for", "while", "switch", "catch", "return", "sizeof", "decltype", "alignof", "noexcept"}
QUALIFIERS = re.compile(r"^(\s*(const|volatile|noexcept(\s*\(\))?|override|final|mutable|&&|&|throw\s*\(\s*\)))*\s*$")


def strip_code(text):
    """The text with comments, literals and preprocessor lines blanked out, newlines kept, so that
    positions and line numbers are those of the file."""
    out, i, n = [], 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c == "#":  # a directive, with its continuation lines
            j = i
            while j < n and (text[j] != "\n" or text[j - 1] == "\\"):
                j += 1
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
            continue
        if c == "\n":
            at_line_start = True
            out.append(c)
            i += 1
            continue
        if not c.isspace():
            at_line_start = False
        two = text[i:i + 2]
        if two == "//":
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif two == "/*":
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif c == "R" and text[i + 1:i + 2] == '"' and not (i > 0 and (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append('R""' + re.sub(r"[^\n]", " ", text[i + 3:j]))
            i = j
            continue
        elif c in "\"'" and not (c == "'" and i > 0 and text[i - 1].isalnum()):  # not a digit separator
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(c + re.sub(r"[^\n]", " ", text[i + 1:j - 1]) + c)
            i = j
            continue
        else:
            out.append(c)
            i += 1
            continue
        out.append(re.sub(r"[^\n]", " ", text[i:j]))
        i = j
    return "".join(out)


def matching(text, i, open_char, close_char):
    """The index of the character closing the group that opens at text[i]."""
    depth = 0
    for j in range(i, len(text)):
        if text[j] == open_char:
            depth += 1
        elif text[j] == close_char:
            depth -= 1
            if depth == 0:
                return j
    return len(text) - 1


def without_templates(head):
    """The head without its leading template<...> clauses, access labels and attributes."""
    while True:
        head = head.lstrip()
        m = re.match(r"(public|private|protected)\s*:(?!:)|\[\[.*?\]\]", head, re.S)
        if m:
            head = head[m.end():]
            continue
        if not re.match(r"template\s*<", head):
            return head
        depth, j = 0, head.index("<")
        for j in range(head.index("<"), len(head)):
            depth += {"<": 1, ">": -1}.get(head[j], 0)
            if depth == 0:
                break
        head = head[j + 1:]


def top_level(head, characters):
    """Whether one of `characters` occurs in `head` outside parentheses and brackets."""
    depth = 0
    for k, c in enumerate(head):
        depth -= {")": 1, "]": 1}.get(c, 0)
        opening = depth == 0 and c in characters
        depth += {"(": 1, "[": 1}.get(c, 0)
        if opening:
            if c == "=" and (head[k + 1:k + 2] == "=" or head[k - 1:k] in "<>!=" or "operator" in head[max(0, k - 12):k]):
                continue
            return True
    return False


def parameter_list(head):
    """(name, index of the opening parenthesis of the parameter list) of a function head, or None."""
    for m in re.finditer(r"\(", head):
        before = head[:m.start()].rstrip()
        if before.endswith("operator"):  # operator()(...): the first group is the name
            continue
        word = re.search(r"(operator\s*(\(\s*\)|[^\w\s(]+)|~?[A-Za-z_]\w*)$", before)
        if word is None or word.group(1) in CONTROL or word.group(1) in ("alignas", "__attribute__"):
            return None if word is not None and word.group(1) in CONTROL else None
        # The name with its qualification (Class::f, Class<T>::f).
        qualified = re.search(r"((?:[A-Za-z_]\w*(?:<[^<>()]*>)?\s*::\s*)*" + re.escape(word.group(1)) + r")$", before)
        return re.sub(r"\s+", "", qualified.group(1)), m.start()
    return None


def classify(head):
    """What a brace opens, from the text before it at namespace or class scope: "namespace",
    "class", "function" (with its name and the position of its parameter list) or "other" (an initializer, an enumeration...)."""
    h = without_templates(head)
    if re.match(r"(inline\s+)?namespace\b|extern\s+\"", h):
        return "namespace", None
    if re.match(r"(class|struct|union)\b", h) and not top_level(h, "("):
        return "class", None
    if re.match(r"enum\b", h) or top_level(h, "=") or not top_level(h, "("):
        return "other", None
    found = parameter_list(h)
    if found is None:
        return "other", None
    name, start = found
    tail = h[matching(h, start, "(", ")") + 1:].strip()
    tail = re.sub(r"noexcept\s*\(.*\)", "noexcept", tail, flags=re.S)
    where = len(head) - len(h) + start  # of the parameter list, in `head`
    if QUALIFIERS.match(tail) or tail.startswith("->") or tail.endswith("try"):
        return "function", (name, where)
    if re.match(r":(?!:)", tail) and tail[-1:] in (")", "}"):  # after a constructor's initializer list
        return "function", (name, where)
    return "other", None


def functions(path):
    """(lines, line of the parameter list, name) of each function of a file."""
    code = strip_code(open(path, encoding="utf-8", errors="replace").read())
    found, scopes, head_start, i = [], [], 0, 0
    while i < len(code):
        c = code[i]
        if c == "(":  # braces between parentheses (a default argument {}, a lambda) open no scope
            i = matching(code, i, "(", ")")
        elif c == ";":
            head_start = i + 1
        elif c == "}":
            if scopes:
                scopes.pop()
            head_start = i + 1
        elif c == "{":
            kind, function = classify(code[head_start:i])
            if kind in ("namespace", "class"):
                scopes.append(kind)
                head_start = i + 1
            else:
                end = matching(code, i, "{", "}")
                following = code[end + 1:].lstrip()[:1]
                if kind == "function":
                    name, where = function
                    found.append((code.count("\n", i, end) + 1, code.count("\n", 0, head_start + where) + 1, name))
                    head_start = end + 1
                elif following not in (";", ",", ")", "{", "}"):  # not an initializer: a handler, a macro
                    head_start = end + 1
                i = end  # after an initializer, the head goes on
        i += 1
    return found


def headers(paths):
    for path in paths:
        if os.path.isfile(path):
            yield path
        for folder, _, files in os.walk(path):
            for f in sorted(files):
                if f.endswith((".h", ".hpp", ".cpp")):
                    yield os.path.join(folder, f)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("paths", nargs="*")
    parser.add_argument("--top", type=int, default=10)
    parser.add_argument("--max-lines", type=int)
    args = parser.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    paths = args.paths or [os.path.join(root, "include")]
    rows = sorted(((lines, path, line, name) for path in headers(paths) for lines, line, name in functions(path)),
                  key=lambda r: (-r[0], r[1], r[2]))
    shown = [r for r in rows if r[0] > args.max_lines] if args.max_lines is not None else rows[:args.top]
    for lines, path, line, name in shown:  # paths relative to the repository when inside it
        shown_path = os.path.relpath(os.path.abspath(path), root)
        print("%4d  %s:%d  %s" % (lines, path if shown_path.startswith("..") else shown_path, line, name))
    if args.max_lines is not None:
        print("%d function(s) of %d longer than %d lines" % (len(shown), len(rows), args.max_lines))
        return 1 if shown else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Reports source files over 400 lines and functions over 60 lines.

Usage: tools/check_sizes.py [--max-file-lines N] [--max-function-lines N] [DIR...]

Scans the .cpp and .hpp files under each DIR (default: src/ of the
repository) and prints one line for each file longer than the file limit
and each function longer than the function limit, then exits 1 if there
was any (0 if none). This is the "Sizes" rule of issue 21: no source file
over about 400 lines, no function over about 60.

A function's length runs from the first line of its header (the text after
the previous ';', '{' or '}', comments skipped) to the line of its closing
brace, both included.

It is a heuristic, not a C++ parser. It removes comments, string and
character literals (raw strings included) and preprocessor lines, then
counts braces. A '{' opened directly inside a namespace, a class, a struct,
a union, an extern "C" block or at file level starts a function when the
text before it, less any `template <...>` head, ends in ')' (optionally
followed by const, noexcept, override, final, & or &&, or a trailing return
type) or in a constructor's initializer list; braces that initialise a
member in that list (`: y_{x}`) are skipped. Functions defined inside class
bodies are counted like the others. Its limits:
  - macros that expand to braces or function headers confuse it, and a
    preprocessor conditional that opens a brace in both branches counts it
    twice (the preprocessor lines are dropped, both branches kept);
  - a lambda or local class inside a function counts as part of that
    function, never on its own; a lambda at namespace level (a variable
    initialised with one) is not counted at all;
  - a header whose requires-clause does not end in ')' (requires C<T>) is
    not recognised, so that function is missed;
  - a brace initialiser at namespace or class level whose text before it
    ends in ')' (rare) may be taken for a function;
  - a digit separator (1'000) is recognised only inside a token that starts
    with a digit;
  - the name it prints is the last identifier before the header's first
    '(' (with the arguments when it is a macro such as TEST(Suite, Name)),
    so operators and templates are named loosely.
"""

import argparse
import os
import re
import sys

SCOPE_WORDS = re.compile(r"\b(namespace|class|struct|union|enum)\b")
CONTROL_WORDS = re.compile(r"^\s*(if|for|while|switch|catch|do|else|return)\b")


def is_digit_separator(text, i):
    """Whether the ' at text[i] separates digits (1'000, 0xFF'FF)."""
    if i == 0 or i + 1 >= len(text) or not text[i + 1].isalnum():
        return False
    start = i
    while start > 0 and (text[start - 1].isalnum() or text[start - 1] in "'._"):
        start -= 1
    return text[start].isdigit()


def strip_code(text):
    """Blanks comments, literals and preprocessor lines, keeping newlines."""
    out = []
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c == "#":
            # A preprocessor line, with its continuations.
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append(" \n")
                    i += 2
                    continue
                out.append(" ")
                i += 1
            continue
        if c == "\n":
            out.append(c)
            at_line_start = True
            i += 1
            continue
        if not c.isspace():
            at_line_start = False
        if text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
            continue
        if text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append("".join(ch if ch == "\n" else " " for ch in text[i:end]))
            i = end
            continue
        raw = re.match(r'(?:u8|u|U|L)?R"([^()\\ ]{0,16})\(', text[i:i + 24])
        if raw and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            close = ")" + raw.group(1) + '"'
            end = text.find(close, i + raw.end())
            end = n if end < 0 else end + len(close)
            out.append('""' + "".join(ch if ch == "\n" else " " for ch in text[i + 2:end]))
            i = end
            continue
        if c == "'" and is_digit_separator(text, i):
            out.append(c)
            i += 1
            continue
        if c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + (c if j < n else ""))
            i = j + 1
            continue
        out.append(c)
        i += 1
    return "".join(out)


def function_name(header):
    """The identifier before the header's first '(' ('?' if none); a macro
    such as TEST(Suite, Name) with its arguments."""
    paren = header.find("(")
    if paren < 0:
        return "?"
    names = re.findall(r"[A-Za-z_~][A-Za-z_0-9:~]*(?:\s*operator\s*\S+)?", header[:paren])
    if not names:
        return "?"
    name = names[-1]
    if re.fullmatch(r"[A-Z][A-Z0-9_]+", name):
        close = header.find(")", paren)
        name += " ".join(header[paren:close + 1].split()) if close > 0 else ""
    return name


def without_template_heads(text):
    """The text less its `template <...>` heads (nested brackets allowed)."""
    while True:
        found = re.search(r"\btemplate\s*<", text)
        if not found:
            return text
        depth, at = 0, found.end() - 1
        while at < len(text):
            depth += {"<": 1, ">": -1}.get(text[at], 0)
            at += 1
            if depth == 0:
                break
        text = text[:found.start()] + text[at:]


def is_function_header(header):
    """Whether the text before a '{' reads as a function's header."""
    text = without_template_heads(" ".join(header.split())).strip()
    if not text or CONTROL_WORDS.match(text) or SCOPE_WORDS.search(text.split("(")[0]):
        return False
    # A constructor's initializer list: cut it at the ':' after the ')'.
    depth = 0
    for at, ch in enumerate(text):
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
            if depth == 0:
                rest = text[at + 1:].lstrip()
                if rest.startswith(":") and not rest.startswith("::"):
                    text = text[:at + 1]
                    break
    text = re.sub(r"->.*$", "", text).rstrip()  # trailing return type
    text = re.sub(r"(\s*\b(const|noexcept|override|final|mutable|volatile)\b|\s*&&?)+$", "", text).rstrip()
    text = re.sub(r"\bnoexcept\s*\(.*\)$", "", text).rstrip()
    if not text.endswith(")") or "(" not in text:
        return False
    before_paren = text[:text.find("(")]
    return "=" not in before_paren or "operator" in before_paren


def in_initializer_list(header):
    """Whether a '{' after `header` brace-initialises a member in a
    constructor's initializer list (S(int x) : y_{x} {)."""
    text = header.rstrip()
    return bool(re.search(r"\)\s*:(?!:)", text)) and bool(text) and (text[-1].isalnum() or text[-1] in "_>")


def functions(code):
    """(name, first line, last line) of each function in stripped code."""
    found = []
    stack = []  # per open brace: ("scope" | "function" | "block" | "init", name, first line)
    header_start = 0  # offset where the current header text begins
    line = 1
    line_at = []  # line number of each offset
    for ch in code:
        line_at.append(line)
        if ch == "\n":
            line += 1
    for at, ch in enumerate(code):
        if ch not in "{};":
            continue
        in_function = any(kind not in ("scope", "init") for kind, _, _ in stack)
        if ch == "{":
            header = code[header_start:at]
            if in_function:
                stack.append(("block", "", 0))
            elif in_initializer_list(header):
                stack.append(("init", "", 0))
                continue  # the header goes on after the member's braces
            elif is_function_header(header):
                first = header_start + (len(header) - len(header.lstrip()))
                stack.append(("function", function_name(header), line_at[min(first, at)]))
            elif SCOPE_WORDS.search(header) or re.search(r'\bextern\s*"', header) or not header.strip():
                stack.append(("scope", "", 0))
            else:
                stack.append(("block", "", 0))  # an initialiser, an enum's values
        elif ch == "}":
            if stack:
                kind, name, first = stack.pop()
                if kind == "function":
                    found.append((name, first, line_at[at]))
                elif kind == "init":
                    continue
        elif stack and stack[-1][0] == "init":
            continue
        header_start = at + 1
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dirs", nargs="*")
    parser.add_argument("--max-file-lines", type=int, default=400)
    parser.add_argument("--max-function-lines", type=int, default=60)
    args = parser.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    dirs = args.dirs or [os.path.join(root, "src")]

    problems = []
    for top in dirs:
        paths = []
        for folder, _, names in os.walk(top):
            paths += [os.path.join(folder, n) for n in names if n.endswith((".cpp", ".hpp"))]
        for path in sorted(paths):
            with open(path, encoding="utf-8", errors="replace") as f:
                text = f.read()
            shown = os.path.relpath(path, root)
            lines = text.count("\n") + (0 if text.endswith("\n") or not text else 1)
            if lines > args.max_file_lines:
                problems.append(f"{shown}: {lines} lines (file limit {args.max_file_lines})")
            for name, first, last in functions(strip_code(text)):
                length = last - first + 1
                if length > args.max_function_lines:
                    problems.append(f"{shown}:{first}: function {name} is {length} lines "
                                    f"(limit {args.max_function_lines})")
    for p in problems:
        print(p)
    print(f"check_sizes: {len(problems)} over the limits" if problems else "check_sizes: all within the limits")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Lists every function in the given C++ files longer than --max lines, as file:line.

A function is what clang-format leaves at column 0: a line that opens a definition (not
a comment, preprocessor line, namespace, type, template header or declaration) up to the
next line that is a lone "}". Its length counts both. Exits 1 when one is too long.
Usage: long_functions.py --max 60 FILE_OR_FOLDER...
"""
import argparse
import pathlib
import re
import sys

NOT_A_DEFINITION = re.compile(r"^(\s|#|//|/\*|\*|}|namespace\b|class\b|struct\b|enum\b|union\b|template\b|using\b|"
                              r"extern\b|typedef\b|static_assert\b|$)")


def functions(path):
    """(first line, line count, signature) of each column-0 definition in `path`."""
    lines = path.read_text(encoding="utf-8", errors="replace").split("\n")
    i = 0
    while i < len(lines):
        line = lines[i]
        if NOT_A_DEFINITION.match(line) or "(" not in line or line.rstrip().endswith(";"):
            i += 1
            continue
        # The signature may run over several lines; the body opens with a "{" at the end of one.
        # A definition on one line ("... { return x; }") ends where it starts.
        j = i
        while j < len(lines) and not lines[j].rstrip().endswith(("{", ";", "}")):
            j += 1
        if j == len(lines) or not lines[j].rstrip().endswith("{"):
            i = j + 1
            continue
        k = j + 1
        while k < len(lines) and lines[k] != "}":
            k += 1
        yield i + 1, k - i + 1, line.strip()
        i = k + 1


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--max", type=int, required=True)
    parser.add_argument("paths", nargs="+")
    args = parser.parse_args()
    files = []
    for p in map(pathlib.Path, args.paths):
        files += sorted(p.rglob("*.cpp")) + sorted(p.rglob("*.h")) if p.is_dir() else [p]
    long_ones = [(f, line, n, sig) for f in files for line, n, sig in functions(f) if n > args.max]
    for f, line, n, sig in long_ones:
        print(f"{f}:{line}: {n} lines (at most {args.max}): {sig}")
    print(f"{len(files)} files, {len(long_ones)} functions over {args.max} lines")
    return 1 if long_ones else 0


if __name__ == "__main__":
    sys.exit(main())

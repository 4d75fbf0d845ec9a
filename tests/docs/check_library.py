#!/usr/bin/env python3
"""Checks docs/materials.md against the standard library it documents.

Every name a library file assigns at the start of a line must be named in the page (in
backquotes), every file of stdlib/ must have a row in its table of files, every image the
page shows must exist, and every swatch in docs/materials/ must be shown: a name added to
the library without its documentation and swatch, or a swatch left behind by a name taken
out, fails here.

usage: check_library.py REPOSITORY
"""
import os
import re
import sys

ASSIGNMENT = re.compile(r"^([A-Za-z][A-Za-z0-9_]*) = ", re.M)
IMAGE = re.compile(r"!\[[^\]]*\]\(([^)]+)\)")


def main():
    root = sys.argv[1]
    page_path = os.path.join(root, "docs", "materials.md")
    page = open(page_path, encoding="utf-8").read()
    prose = re.sub(r"^```.*?^```", "", page, flags=re.M | re.S)
    quoted = set(re.findall(r"`([^`]+)`", prose))
    named = set()
    for snippet in quoted:
        named.update(re.findall(r"[A-Za-z][A-Za-z0-9_]*", snippet))
    problems = []

    library = os.path.join(root, "stdlib")
    names = 0
    for file in sorted(os.listdir(library)):
        if not file.endswith(".crt"):
            continue
        if file not in quoted:
            problems.append(f"stdlib/{file} has no row in the page's table of files")
        text = open(os.path.join(library, file), encoding="utf-8").read()
        for name in ASSIGNMENT.findall(text):
            names += 1
            if name not in named:
                problems.append(f"{name} (stdlib/{file}) is not documented")

    shown = set()
    for target in IMAGE.findall(page):
        path = os.path.normpath(os.path.join(root, "docs", target))
        shown.add(path)
        if not os.path.isfile(path):
            problems.append(f"the page shows {target}, which does not exist")
    swatches = os.path.join(root, "docs", "materials")
    for folder, _, files in os.walk(swatches):
        for file in files:
            path = os.path.normpath(os.path.join(folder, file))
            if path not in shown:
                problems.append(f"{os.path.relpath(path, root)} is not shown on the page")

    for problem in problems:
        print(f"docs/materials.md: {problem}")
    print(f"{names} library names, {len(shown)} images checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Fails, naming a cycle and the includes that make it, if the folders of
core/ include each other in a cycle. A folder depends on another when one
of its files includes a header of the other: `#include "core/X/..."`."""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parent.parent
include = re.compile(r'^\s*#\s*include\s+"core/([a-z_]+)/[^"]+"', re.M)

edges = {}  # folder -> {folder it includes: an example "file -> header"}
for path in sorted((root / "core").rglob("*")):
    if path.suffix not in (".h", ".cpp") or len(path.relative_to(root / "core").parts) < 2:
        continue
    folder = path.relative_to(root / "core").parts[0]
    for match in include.finditer(path.read_text()):
        target = match.group(1)
        if target != folder:
            edges.setdefault(folder, {}).setdefault(target, f"{path.relative_to(root)} includes core/{target}/...")

# Depth-first search; a grey folder met again closes a cycle.
state, stack = {}, []


def visit(folder):
    state[folder] = "grey"
    stack.append(folder)
    for target in sorted(edges.get(folder, {})):
        if state.get(target) == "grey":
            cycle = stack[stack.index(target):] + [target]
            print("core/ folders include each other in a cycle: " + " -> ".join(cycle))
            for a, b in zip(cycle, cycle[1:]):
                print(f"  {a} -> {b}: {edges[a][b]}")
            sys.exit(1)
        if target not in state:
            visit(target)
    stack.pop()
    state[folder] = "black"


for folder in sorted(edges):
    if folder not in state:
        visit(folder)
print(f"no cycle among {len(set(edges) | {t for e in edges.values() for t in e})} core/ folders")

#!/usr/bin/env python3
"""Finds pairs of modules that import each other, in every crate of the workspace.

    python3 scripts/module-cycles.py

A module's imports are its `crate::a::b` paths, `crate::{a, b}` lists and `super::` paths
outside comments and outside its `#[cfg(test)] mod tests`, each resolved to the longest module
path of the crate it names. Two modules that import each other are printed, one pair a line, and
the exit status is 2; with none it is 0. A module and its own submodules do not count.
"""
import os
import re
import sys

CRATES = ["core", "std-film", "lab", "cli", "capi", "web", "gpu", "examples"]


def module_name(root, path):
    parts = os.path.relpath(path, root)[:-3].split("/")
    if parts[-1] in ("mod", "lib", "main"):
        parts = parts[:-1]
    return "::".join(parts)


def cycles(root):
    sources = {}
    for folder, _, files in os.walk(root):
        for f in files:
            if f.endswith(".rs"):
                path = os.path.join(folder, f)
                with open(path, encoding="utf-8") as fh:
                    sources[module_name(root, path)] = fh.read()
    names = set(sources)

    def resolve(parts):
        for k in range(len(parts), 0, -1):
            cand = "::".join(parts[:k])
            if cand in names:
                return cand
        return None

    edges = set()
    for m, src in sources.items():
        src = "\n".join(l for l in src.split("\n") if not l.strip().startswith("//"))
        cut = src.find("#[cfg(test)]\nmod tests")
        if cut >= 0:
            src = src[:cut]
        targets = [r.split("::") for r in re.findall(r"crate::([a-z_0-9]+(?:::[a-z_0-9]+)*)", src)]
        for group in re.findall(r"crate::\{([^}]*)\}", src):
            targets += [[x.strip().split("::")[0]] for x in group.split(",") if x.strip()]
        parent = m.split("::")[:-1]
        for r in re.findall(r"super::([a-z_0-9]+)", src):
            targets.append(parent + [r])
        for group in re.findall(r"super::\{([^}]*)\}", src):
            targets += [parent + [x.strip().split("::")[0]] for x in group.split(",") if x.strip()]
        for t in targets:
            top = resolve(t)
            if top is None or top == m or m.startswith(top + "::") or top.startswith(m + "::"):
                continue
            edges.add((m, top))
    return sorted((a, b) for (a, b) in edges if (b, a) in edges and a < b)


def main():
    os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    found = False
    for crate in CRATES:
        root = os.path.join(crate, "src")
        if not os.path.isdir(root):
            continue
        for a, b in cycles(root):
            print(f"{crate}: {a} and {b} import each other")
            found = True
    if found:
        sys.exit(2)
    print("no two modules import each other")


if __name__ == "__main__":
    main()

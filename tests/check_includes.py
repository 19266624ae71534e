#!/usr/bin/env python3
"""Check the package's include graph: no dpoly/ file includes a mesophyll/ file, and no cycle.

    check_includes.py SRC_DIR

A node is a style or helper (name.h and name.cpp together), an edge A -> B that one of A's
files includes B's header. Prints the offending edges or cycle and exits 1; standard library only.
"""
import pathlib
import re
import sys


def include_graph(src):
    names = {p.stem for p in src.glob("*.h")}
    graph = {name: set() for name in names | {p.stem for p in src.glob("*.cpp")}}
    for path in list(src.glob("*.h")) + list(src.glob("*.cpp")):
        for included in re.findall(r'^#include "([^"]+)\.h"', path.read_text(), re.M):
            if included in names and included != path.stem:
                graph[path.stem].add(included)
    return graph


def generic(name):
    return "dpoly" in name and "mesophyll" not in name


def find_cycle(graph):
    state, stack = {}, []

    def visit(node):
        state[node] = "open"
        stack.append(node)
        for nxt in sorted(graph[node]):
            if state.get(nxt) == "open":
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        state[node] = "done"
        stack.pop()
        return None

    for node in sorted(graph):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return None


def main():
    graph = include_graph(pathlib.Path(sys.argv[1]))
    wrong = [f"{a} -> {b}" for a in sorted(graph) for b in sorted(graph[a])
             if generic(a) and "mesophyll" in b]
    cycle = find_cycle(graph)
    for edge in wrong:
        print(f"a generic dpoly file includes a mesophyll file: {edge}")
    if cycle:
        print("include cycle: " + " -> ".join(cycle))
    edges = sum(len(v) for v in graph.values())
    print(f"{len(graph)} files, {edges} include edges: "
          f"{'OK' if not wrong and not cycle else 'FAILED'}")
    return 1 if wrong or cycle else 0


if __name__ == "__main__":
    sys.exit(main())

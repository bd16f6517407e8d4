#!/usr/bin/python3
"""Fails (exit 1) if an include in micro/ runs upward between its layers.

micro's folders are layers, bottom first (micro/CMakeLists.txt says what each
holds); a file may include from its own layer and the ones below. Prints every
upward edge as 'file:line: layer -> layer (include)'.

Usage: scripts/check_micro_layers.py [SOURCE_DIR]
"""
import os
import re
import sys

LAYERS = [
    {"numerics", "geometry"},
    {"contact"},
    {"model"},
    {"dynamics", "packing"},
    {"analysis"},
    {"protocol"},
    {"io"},
    {"results"},
    {"sweep"},
    {"input"},
    {"app"},
]
RANK = {folder: rank for rank, layer in enumerate(LAYERS) for folder in layer}
INCLUDE = re.compile(r'^\s*#\s*include\s+"micro/([^/"]+)/')


def main():
    root = os.path.join(sys.argv[1] if len(sys.argv) > 1 else ".", "micro")
    upward, unknown = [], set()
    for folder in sorted(os.listdir(root)):
        path = os.path.join(root, folder)
        if not os.path.isdir(path):
            continue
        if folder not in RANK:
            unknown.add(folder)
            continue
        for directory, _, files in os.walk(path):
            for name in sorted(files):
                if not name.endswith((".h", ".cpp")):
                    continue
                source = os.path.join(directory, name)
                with open(source, encoding="utf-8") as f:
                    for number, line in enumerate(f, 1):
                        match = INCLUDE.match(line)
                        if not match:
                            continue
                        target = match.group(1)
                        if target not in RANK:
                            unknown.add(target)
                        elif RANK[target] > RANK[folder]:
                            upward.append(f"{os.path.relpath(source, os.path.dirname(root))}:"
                                          f"{number}: {folder} -> {target} ({line.strip()})")
    for folder in sorted(unknown):
        print(f"micro/{folder}: a folder that is no layer (add it to LAYERS)")
    for edge in upward:
        print(edge)
    if upward or unknown:
        print(f"{len(upward)} upward include(s)")
        return 1
    print("micro layers: no upward include")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Joins flow-curve tables of sweeps over the same packings (e.g. the explicit
high-rate part and the implicit low-rate part) into one table for `bridge fit`.

    /usr/bin/python3 scripts/join_flow_curves.py [--no-structure] OUT.csv A.csv B.csv ...

The tables must have the same columns; their provenance lines are kept; a
state point in two tables is refused. --no-structure leaves out the r_m and f_m
columns (too noisy to fit at N = 250 and 10 strain: docs/bridge.md)."""
import os
import sys


def without_structure(line):
    cells = line.split(",")
    return ",".join(cells[:-4])


def main(out, inputs, structure):
    comments, header, rows, seen = [], None, [], set()
    for path in inputs:
        with open(path) as f:
            lines = f.read().splitlines()
        comments += [f"# from {path}: {line[1:].strip()}" for line in lines if line.startswith("#")]
        data = [line for line in lines if line and not line.startswith("#")]
        if not structure:
            if not data[0].endswith("f_m_se [E*R^2]"):
                sys.exit(f"{path}: no structure columns to leave out")
            data = [without_structure(line) for line in data]
        if header is None:
            header = data[0]
        elif data[0] != header:
            sys.exit(f"{path}: columns differ from {inputs[0]}")
        for row in data[1:]:
            key = tuple(row.split(",")[:3] if "seed" in header else row.split(",")[:2])
            if key in seen:
                sys.exit(f"{path}: state point {key} appears twice")
            seen.add(key)
            rows.append(row)
    with open(out + ".partial", "w") as f:
        f.write("\n".join(comments + [header] + rows) + "\n")
    os.replace(out + ".partial", out)  # whole or not at all


if __name__ == "__main__":
    args = sys.argv[1:]
    structure = "--no-structure" not in args
    args = [a for a in args if a != "--no-structure"]
    if len(args) < 3:
        sys.exit(__doc__)
    main(args[0], args[1:], structure)

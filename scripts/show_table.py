#!/usr/bin/env python3
"""Prints chosen columns of a result table, by name, aligned, for the terminal.

    show_table.py TABLE.csv NAME [NAME ...] [--rows N] [--every N]

Each column is headed "name [unit]" and its numbers keep 4 significant
digits: what a reader takes in at a glance (the table keeps them all).
"""

import argparse
import sys

from result_table import read_rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("table")
    parser.add_argument("names", nargs="+", help="columns, by name (without the unit)")
    parser.add_argument("--rows", type=int, default=0, help="at most this many rows (0: all)")
    parser.add_argument("--every", type=int, default=0,
                        help="every N-th row and the last one (0: all); a glance at a long table")
    args = parser.parse_args()
    with open(args.table, encoding="utf-8") as f:
        rows, _ = read_rows(f.read().splitlines())
    if not rows:
        sys.exit(f"show_table: error: {args.table} has no rows")
    keys = []
    for name in args.names:
        key = next((k for k in rows[0] if k == name or k.startswith(name + " [")), None)
        if key is None:
            sys.exit(f"show_table: error: {args.table} has no column '{name}'; it has: "
                     + ", ".join(rows[0]))
        keys.append(key)

    def cell(text):
        try:
            return f"{float(text):.4g}"
        except ValueError:
            return text

    shown = rows[:args.rows] if args.rows else rows
    if args.every > 1:
        shown = [r for i, r in enumerate(shown) if i % args.every == 0 or i == len(shown) - 1]
    table = [keys] + [[cell(r[k]) for k in keys] for r in shown]
    widths = [max(len(line[c]) for line in table) for c in range(len(keys))]
    for line in table:
        print("  ".join(text.rjust(width) for text, width in zip(line, widths)))


if __name__ == "__main__":
    main()

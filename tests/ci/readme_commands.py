#!/usr/bin/env python3
"""readme_commands.py CEMV README: the README's command table renders as one
table: every row of it is in one block of table lines after its header, no
command row stands outside that block, every row has the table's three
cells, and every command of `cemv --help` has a row.
"""
import re
import subprocess
import sys


def cells(row):
    return [c for c in re.split(r"(?<!\\)\|", row.strip())[1:-1]]


def main():
    cemv, readme = sys.argv[1], sys.argv[2]
    lines = open(readme, encoding="utf-8").read().split("\n")
    start = lines.index("| command | what it does | exit status |")
    end = start
    while end < len(lines) and lines[end].startswith("|"):
        end += 1
    table = lines[start:end]
    stray = [i + 1 for i, l in enumerate(lines) if l.startswith("| `cemv") and not start <= i < end]
    if stray:
        sys.exit(f"{readme}: command rows outside the command table, lines {stray}")
    for row in table:
        if len(cells(row)) != 3:
            sys.exit(f"{readme}: row with {len(cells(row))} cells: {row[:60]}")
    listed = set()
    for row in table[2:]:
        listed.update(re.findall(r"`cemv ([a-z-]+)", cells(row)[0]))
    out = subprocess.run([cemv, "--help"], capture_output=True, text=True).stdout
    commands = re.findall(r"^  ([a-z-]+) ", out.split("Subcommands:")[1], re.M)
    missing = [c for c in commands if c not in listed]
    if missing:
        sys.exit(f"{readme}: no row for {missing}")
    print(f"{len(table) - 2} rows, {len(commands)} commands, one table")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""flags_in_messages.py CEMV SOURCE_DIR: every flag a message names exists on
the command that prints it.

Walks the string literals of cli/, formats/ and sheets/ (comments left out),
finds each `--flag` in them, maps the literal to the commands that can print
it, and checks that `cemv COMMAND --help` lists the flag. A literal that says
`cemv COMMAND` names the flags of that command. Which commands print the
messages of a file:
  - cli/cmd_*.cpp: the command whose `add_subcommand` region holds the
    literal; the helpers above the first region belong to every command of
    the file;
  - any other file: the table READERS below (a file that names a flag and is
    not in it is itself a failure, so that a new message cannot go unchecked).
Exit 1 listing every flag a command lacks."""
import os
import re
import subprocess
import sys

# The commands whose input reaches each shared file (reader or helper).
READERS = {
    "cli/main.cpp": ["cemv"],
    "cli/commands.hpp": ["*"],  # --quiet, added to the commands that print
    "cli/check_gate.cpp": ["check"],
    "cli/sheet_layout_options.cpp": ["import-csv", "import-workbook"],
    "csv.cpp": ["import-csv"],
    "csv_grid.cpp": ["import-csv", "import-workbook"],
    "csv_grid.hpp": ["import-csv", "import-workbook"],
    "csv_grid_elements.cpp": ["import-csv", "import-workbook"],
    "csv_grid_orientation.cpp": ["import-csv", "import-workbook"],
    "csv_grid_headers.cpp": ["import-csv", "import-workbook"],
    "csv_grid_attributes.cpp": ["import-csv", "import-workbook"],
    "csv_grid_shape.cpp": ["import-csv", "import-workbook"],
    "sheet_layout.cpp": ["import-csv", "import-workbook"],
    "workbook_grid.cpp": ["import-workbook"],
    "text_encoding.cpp": ["import-csv"],
    "scenario.cpp": ["simulate"],
    "cli/plc_program.cpp": ["plc-check", "replay", "evidence"],
}

FLAG = re.compile(r"(?<![\w-])--([a-z][a-z0-9-]*)")
CEMV_COMMAND = re.compile(r"\bcemv ([a-z][a-z-]*)")


def literals(text):
    """(line, literal) of every string literal, comments left out."""
    out, i, line, n = [], 0, 1, len(text)
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            i += 1
        elif text.startswith("//", i):
            while i < n and text[i] != "\n":
                i += 1
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            line += text.count("\n", i, end)
            i = end
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            open_paren = text.find("(", i + 2)
            delim = text[i + 2:open_paren]
            end = text.find(")" + delim + '"', open_paren)
            end = n if end < 0 else end
            out.append((line, text[open_paren + 1:end]))
            line += text.count("\n", i, end)
            i = end + len(delim) + 2
        elif c == "'":
            j = i + 1
            while j < n and text[j] != "'":
                j += 2 if text[j] == "\\" else 1
            i = j + 1
        elif c == '"':
            j, buf = i + 1, []
            while j < n and text[j] != '"':
                if text[j] == "\\":
                    buf.append(text[j:j + 2])
                    j += 2
                else:
                    buf.append(text[j])
                    j += 1
            out.append((line, "".join(buf)))
            i = j + 1
        else:
            i += 1
    return out


def regions(text):
    """[(start line, command)] of each add_subcommand of a cmd file."""
    found = []
    for m in re.finditer(r'add_subcommand\(\s*"([a-z][a-z-]*)"', text):
        found.append((text.count("\n", 0, m.start()) + 1, m.group(1)))
    return found


def main():
    cemv, root = sys.argv[1], sys.argv[2]
    helps = {}

    def help_of(command):
        if command not in helps:
            args = [cemv, "--help"] if command == "cemv" else [cemv, command, "--help"]
            r = subprocess.run(args, capture_output=True, text=True)
            helps[command] = r.stdout + r.stderr if r.returncode == 0 else None
        return helps[command]

    all_commands = sorted({c for d in ["cli"] for f in os.listdir(os.path.join(root, d)) if f.startswith("cmd_")
                           for _, c in regions(open(os.path.join(root, d, f)).read())})
    failures, checked = [], 0
    for folder in ["cli", "formats", "sheets"]:
        base = os.path.join(root, folder)
        if not os.path.isdir(base):
            continue
        for name in sorted(os.listdir(base)):
            if not name.endswith((".cpp", ".hpp")):
                continue
            path = f"{folder}/{name}"
            text = open(os.path.join(base, name)).read()
            spans = regions(text) if name.startswith("cmd_") else []
            for line, lit in literals(text):
                flags = FLAG.findall(lit)
                if not flags:
                    continue
                named = CEMV_COMMAND.search(lit)
                if named and named.group(1) in all_commands:
                    commands = [named.group(1)]
                elif spans:
                    before = [c for start, c in spans if start <= line]
                    commands = [before[-1]] if before else [c for _, c in spans]
                elif path in READERS or name in READERS:
                    commands = READERS.get(path) or READERS[name]
                else:
                    failures.append(f"{path}:{line}: names --{flags[0]}, but no command is known to print "
                                    f"its messages (add the file to READERS in {os.path.basename(__file__)})")
                    continue
                if commands == ["*"]:
                    continue
                for command in commands:
                    help_text = help_of(command)
                    if help_text is None:
                        failures.append(f"{path}:{line}: 'cemv {command} --help' fails")
                        continue
                    for flag in flags:
                        checked += 1
                        if not re.search(r"(?<![\w-])--" + re.escape(flag) + r"(?![\w-])", help_text):
                            failures.append(f"{path}:{line}: names --{flag}, which 'cemv {command}' lacks: "
                                            f"{lit.strip()[:100]!r}")
    for f in failures:
        print("FAIL:", f)
    if failures:
        print(f"{len(failures)} messages name a flag their command lacks")
        return 1
    print(f"every flag named in a message exists on its command: {checked} checked")
    return 0


if __name__ == "__main__":
    sys.exit(main())

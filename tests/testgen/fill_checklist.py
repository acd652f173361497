#!/usr/bin/env python3
"""Fills a field checklist (cemv-field-checklist/1) as a field team would:
every step OK with initials and date, or only the steps of some tests, and
optionally a deviation at TEST/STEP.

fill_checklist.py IN.csv OUT.csv [--tests F001,F002] [--deviation F001/3:TEXT]
"""
import csv
import sys


def main(argv):
    src, dst = argv[1], argv[2]
    tests, deviation = None, None
    i = 3
    while i < len(argv):
        if argv[i] == "--tests":
            tests = set(argv[i + 1].split(","))
        elif argv[i] == "--deviation":
            where, text = argv[i + 1].split(":", 1)
            test, step = where.split("/")
            deviation = (test, step, text)
        i += 2
    with open(src, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    header = None
    out = []
    for row in rows:
        if row and row[0].startswith("#"):
            out.append(row)
            continue
        if header is None:
            header = row
            out.append(row)
            continue
        r = dict(zip(header, row))
        if tests is None or r["test"] in tests:
            r["result"] = "OK"
            if deviation and r["test"] == deviation[0] and r["step"] == deviation[1]:
                r["result"] = deviation[2]
            r["initials"] = "JS"
            r["date"] = "2026-03-02"
        out.append([r[h] for h in header])
    with open(dst, "w", newline="", encoding="utf-8") as f:
        csv.writer(f, lineterminator="\n").writerows(out)


if __name__ == "__main__":
    main(sys.argv)

#!/usr/bin/env python3
"""run_sheetgen.py: the generated contractor sheets through cemv.

    run_sheetgen.py --cemv CEMV --soffice SOFFICE --work DIR --first S --count N [--jobs J]

Generates the sheets of seeds S .. S+N-1 (sheetgen.py), has LibreOffice save
each as XLSX, ODS and the CSV of its matrix sheet (one soffice run per
format, all files at once), and imports every file without a layout:
`cemv import-workbook` (with --sheet when a hidden previous revision is there
too) and `cemv import-csv`. Each import must either exit 0 with exactly the
matrix the sheet means (sheet_SEED.expected.json: causes by sheet id with
their description, tags, voting, SIL, setpoint and notes; effects by sheet id
with their output tags, description, SIL and action; every intersection with
its type and footnote), or exit 2 with an error placed in the file
(FILE:LINE:COL or FILE:SHEET:ROW:COL). It prints how many were read right,
refused and misread, each misread with its seed and the difference, and
exits 1 when one was misread or failed otherwise.
"""
import argparse
import concurrent.futures
import json
import os
import re
import resource
import shutil
import struct
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import sheetgen  # noqa: E402

CSV_FILTER = "csv:Text - txt - csv (StarCalc):44,34,76,1,,0,false,true,false,false,false,-1"
FORMATS = ("xlsx", "ods", "csv")


def single(v):
    return struct.unpack("f", struct.pack("f", float(v)))[0]


# ----------------------------------------------------------- the projection

def note_parts(note):
    """The sheet id and the other values of an imported element's note
    ('sheet id: 7; Action: CLOSE; Remarks: hardwired')."""
    parts = [p for p in (note or "").split("; ") if p]
    sheet_id = None
    if parts and parts[0].startswith("sheet id: "):
        sheet_id = parts.pop(0)[len("sheet id: "):]
    return sheet_id, sorted(p.split(": ", 1)[1] if ": " in p else p for p in parts)


def project(m):
    """The imported matrix as the generator writes what a sheet means: keyed by
    sheet ids, so that names and numbers (derived by the import) do not count,
    but every fact the sheet states does."""
    causes, effects, cause_key, effect_key = {}, {}, {}, {}

    def key_of(table, sheet_id, name):
        key = sheet_id if sheet_id is not None else "(no sheet id: %s)" % name
        while key in table:
            key += " (again)"
        return key

    for c in m.get("causes", []):
        sheet_id, notes = note_parts(c.get("note"))
        key = key_of(causes, sheet_id, c.get("name"))
        cause_key[c["id"]] = key
        a = c.get("analog")
        causes[key] = {
            "description": c.get("description", ""), "tags": [t["name"] for t in c.get("tags", [])],
            "function": c.get("function", "normal"), "sil": c.get("sil", 0),
            "analog": None if a is None else {"limit_type": a.get("limit_type"), "limit": single(a.get("limit", 0)),
                                              "unit": a.get("unit", "")},
            "notes": notes,
        }
    for e in m.get("effects", []):
        sheet_id, notes = note_parts(e.get("note"))
        key = key_of(effects, sheet_id, e.get("name"))
        effect_key[e["id"]] = key
        effects[key] = {
            "description": e.get("description", ""), "tags": [t["name"] for t in e.get("tags", [])],
            "sil": e.get("sil", 0), "notes": notes,
        }
    inter = sorted([cause_key.get(x["cause"], "?"), effect_key.get(x["effect"], "?"), x["type"], x.get("note", "")]
                   for x in m.get("intersections", []))
    return {"causes": causes, "effects": effects, "intersections": inter}


def normalise(expected):
    e = json.loads(json.dumps(expected))
    for c in e["causes"].values():
        if c["analog"]:
            c["analog"]["limit"] = single(c["analog"]["limit"])
    e["intersections"] = sorted(e["intersections"])
    return e


def difference(want, got, limit=8):
    """What differs, one line each, the first `limit` of them."""
    out = []
    for table in ("causes", "effects"):
        w, g = want[table], got[table]
        missing = [k for k in w if k not in g]
        extra = [k for k in g if k not in w]
        if missing:
            out.append("%s missing: %s" % (table, ", ".join(missing[:8]) + (" ..." if len(missing) > 8 else "")))
        if extra:
            out.append("%s not in the sheet: %s" % (table, ", ".join(extra[:8]) + (" ..." if len(extra) > 8 else "")))
        for k in w:
            if k in g and w[k] != g[k]:
                for field in w[k]:
                    if w[k][field] != g[k].get(field):
                        out.append("%s %s %s: expected %s, read %s" % (table[:-1], k, field,
                                                                       json.dumps(w[k][field], ensure_ascii=False),
                                                                       json.dumps(g[k].get(field), ensure_ascii=False)))
    wi = {tuple(x) for x in want["intersections"]}
    gi = {tuple(x) for x in got["intersections"]}
    for x in sorted(wi - gi)[:4]:
        out.append("intersection missing: cause %s / effect %s %s %s" % x)
    for x in sorted(gi - wi)[:4]:
        out.append("intersection not in the sheet: cause %s / effect %s %s %s" % x)
    if len(wi ^ gi) > 8:
        out.append("... %d intersections differ" % len(wi ^ gi))
    more = len(out) - limit
    return out[:limit] + (["... and %d more differences" % more] if more > 0 else [])


# ------------------------------------------------------------ LibreOffice

def convert(soffice, work, files, to):
    """One soffice run for every file: XLSX, ODS, or every sheet as CSV."""
    outdir = os.path.join(work, to)
    home = os.path.join(work, "lo-" + to)
    os.makedirs(outdir, exist_ok=True)
    os.makedirs(home, exist_ok=True)
    env = dict(os.environ, HOME=home)
    target = CSV_FILTER if to == "csv" else to
    cmd = [soffice, "-env:UserInstallation=file://" + home + "/profile", "--headless", "--norestore",
           "--nolockcheck", "--convert-to", target, "--outdir", outdir] + files
    log = open(os.path.join(work, "soffice-%s.log" % to), "w")
    return subprocess.Popen(cmd, env=env, stdout=log, stderr=subprocess.STDOUT)


# ----------------------------------------------------------------- imports

def import_one(cemv, work, info, fmt):
    stem = info["stem"]
    folder = os.path.join(work, fmt)
    out = os.path.join(work, "json", "%s.%s.json" % (stem, fmt))
    if fmt == "csv":
        name = "%s-%s.csv" % (stem, info["sheet"])
        cmd = [cemv, "import-csv", name, "-o", out]
    else:
        name = "%s.%s" % (stem, fmt)
        cmd = [cemv, "import-workbook", name, "-o", out]
        if info["needs_sheet"]:
            cmd += ["--sheet", info["sheet"]]
    if not os.path.exists(os.path.join(folder, name)):
        return {"status": "failed", "why": "LibreOffice wrote no %s" % name, "file": name}
    try:
        r = subprocess.run(cmd, cwd=folder, capture_output=True, text=True, timeout=120)
    except subprocess.TimeoutExpired:
        return {"status": "failed", "why": "no answer within 120 s", "file": name}
    result = {"file": name, "exit": r.returncode, "stderr": r.stderr}
    if r.returncode == 0:
        try:
            got = project(json.load(open(out, encoding="utf-8")))
        except (OSError, ValueError, KeyError) as e:
            result.update(status="failed", why="exit 0 but no readable matrix: %s" % e)
            return result
        want = normalise(info["csv" if fmt == "csv" else "workbook"])
        if got == want:
            result["status"] = "read"
        else:
            result.update(status="misread", diff=difference(want, got))
        return result
    if r.returncode == 2:
        place = re.compile(r"^" + re.escape(name) + r":(?:[^\n]*:)?\d+(?::\d+)?: error: ", re.M)
        first = next((l for l in r.stderr.splitlines() if ": error: " in l), "")
        if place.search(r.stderr):
            result.update(status="refused", why=first)
        else:
            result.update(status="failed", why="exit 2 without a place in the file: " + first)
        if os.path.exists(out):
            result.update(status="failed", why="refused, yet a matrix was written")
        return result
    result.update(status="failed", why="exit %d: %s" % (r.returncode, r.stderr.strip()[-300:]))
    return result


def coverage(infos):
    """One line on what the sheets exercised."""
    f = [i["features"] for i in infos]

    def tally(key):
        counts = {}
        for x in f:
            counts[x[key]] = counts.get(x[key], 0) + 1
        return ", ".join("%s %d" % (k, counts[k]) for k in sorted(counts, key=str))
    deleted = [d for x in f for d in x["deleted"]]
    return ("covered: effect header rows %s (%d orders); unlabelled rows %s; number row %s; on the attribute header "
            "row %s; banner %s; %d voting groups (%d merged); %d footnoted marks; deleted rows: %d by a word, %d struck "
            "through, %d both; %d hidden previous revisions; largest %d rows, %d columns" % (
                tally("header_rows"), len({x["order"] for x in f}), tally("unlabelled"), tally("number_row"),
                tally("shared"), tally("banner"), sum(x["groups"] for x in f), sum(x["merged_groups"] for x in f),
                sum(x["footnoted_marks"] for x in f), deleted.count("word"), deleted.count("strike"),
                deleted.count("both"), sum(x["hidden_previous"] for x in f), max(x["rows"] for x in f),
                max(x["columns"] for x in f)))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--cemv", required=True)
    p.add_argument("--soffice", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--first", type=int, default=1)
    p.add_argument("--count", type=int, default=200)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--verbose", action="store_true", help="print every refusal too")
    p.add_argument("--reuse", action="store_true",
                   help="import again the files an earlier run left in --work (another cemv, the same sheets)")
    a = p.parse_args()
    cemv = os.path.abspath(a.cemv)
    work = os.path.abspath(a.work)
    gen = os.path.join(work, "gen")
    seeds = list(range(a.first, a.first + a.count))
    started = time.monotonic()
    if a.reuse:
        shutil.rmtree(os.path.join(work, "json"), ignore_errors=True)
        os.makedirs(os.path.join(work, "json"))
        infos = [json.load(open(os.path.join(gen, "sheet_%d.expected.json" % seed), encoding="utf-8"))
                 for seed in seeds]
    else:
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(gen)
        os.makedirs(os.path.join(work, "json"))
        infos = [sheetgen.write(seed, gen) for seed in seeds]
        files = [os.path.join(gen, i["stem"] + ".fods") for i in infos]
        runs = [convert(a.soffice, work, files, to) for to in FORMATS]
        for to, run in zip(FORMATS, runs):
            if run.wait(timeout=900) != 0:
                print("LibreOffice failed converting to %s:" % to)
                print(open(os.path.join(work, "soffice-%s.log" % to)).read()[-2000:])
                return 1

    converted = time.monotonic()
    tasks = [(info, fmt) for info in infos for fmt in FORMATS]
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        results = list(pool.map(lambda t: import_one(cemv, work, t[0], t[1]), tasks))

    finished = time.monotonic()
    counts = {fmt: {"read": 0, "refused": 0, "misread": 0, "failed": 0} for fmt in FORMATS}
    by_status = {"read": [], "refused": [], "misread": [], "failed": []}
    for (info, fmt), r in zip(tasks, results):
        counts[fmt][r["status"]] += 1
        by_status[r["status"]].append((info, fmt, r))
    # Each misread sheet once, with the formats that read it alike.
    misread = {}
    for info, fmt, r in by_status["misread"]:
        misread.setdefault((info["seed"], tuple(r["diff"])), (info, []))[1].append(fmt)
    for (seed, diff), (info, fmts) in sorted(misread.items()):
        print("MISREAD seed %d %s: exit 0 with another matrix; %s" % (seed, ", ".join(fmts), info["describe"]))
        for line in diff:
            print("    " + line)
    for info, fmt, r in by_status["failed"]:
        print("FAILED seed %d %s (%s): %s; %s" % (info["seed"], fmt, r["file"], r["why"], info["describe"]))
    if a.verbose:
        for info, fmt, r in by_status["refused"]:
            print("refused seed %d %s: %s" % (info["seed"], fmt, r["why"][:220]))
    with open(os.path.join(work, "report.json"), "w", encoding="utf-8") as f:
        json.dump([{"seed": info["seed"], "format": fmt, "file": r.get("file"), "status": r["status"],
                    "why": r.get("why", ""), "difference": r.get("diff", [])} for (info, fmt), r in zip(tasks, results)],
                  f, indent=1, ensure_ascii=False)
    total = {k: sum(c[k] for c in counts.values()) for k in ("read", "refused", "misread", "failed")}
    for fmt in FORMATS:
        c = counts[fmt]
        print("%-4s: %d read right without a layout, %d refused with a place, %d misread, %d failed" %
              (fmt, c["read"], c["refused"], c["misread"], c["failed"]))
    misread_seeds = sorted({info["seed"] for info, _, _ in by_status["misread"]})
    refused_seeds = sorted({info["seed"] for info, _, _ in by_status["refused"]})
    print(coverage(infos))
    cpu = resource.getrusage(resource.RUSAGE_CHILDREN)
    print("time: %.0f s generating and converting (LibreOffice), %.0f s importing; %.0f s of CPU in LibreOffice and cemv" %
          (converted - started, finished - converted, cpu.ru_utime + cpu.ru_stime))
    print("seeds misread: %s" % (" ".join(map(str, misread_seeds)) or "none"))
    print("seeds refused: %s" % (" ".join(map(str, refused_seeds)) or "none"))
    print("sheetgen: %d imports of %d sheets (seeds %d-%d): %d read right without a layout, %d refused with a place, "
          "%d misread, %d failed" % (len(tasks), len(seeds), seeds[0], seeds[-1], total["read"], total["refused"],
                                     total["misread"], total["failed"]))
    return 1 if total["misread"] or total["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())

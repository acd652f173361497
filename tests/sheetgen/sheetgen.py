#!/usr/bin/env python3
"""sheetgen.py: a seeded generator of contractor-style cause & effect sheets.

    sheetgen.py SEED [SEED...] --out DIR      one sheet per seed
    sheetgen.py --first S --count N --out DIR the sheets of seeds S .. S+N-1

Each seed gives DIR/sheet_SEED.fods (a flat ODS: a cover, a revision history,
perhaps a hidden sheet with the previous revision, the C&E matrix sheet) and
DIR/sheet_SEED.expected.json: the matrix the sheet means, as the projection
that run_sheetgen.py compares with what `cemv import-workbook` and `cemv
import-csv` make of it (tests/sheetgen/README.md). The same seed gives the
same bytes on every machine: everything comes from random.Random(seed).

What it varies is what contractors send (docs/csv.md "Vendor sheets"): the
stacked effect header (2 to 4 rows of description, action, output tag and SIL
in any order, labelled or not, one of them perhaps on the row of the cause
attribute headers), an effect number row or none, a CAUSES/EFFECTS banner or
none, the spellings of the attribute headers, voting groups over 2-3 rows
(merged or not, marks merged, repeated or on the first row), several tags in
one cell, setpoints with units and trip sides, footnoted marks with a legend,
deleted rows (struck through, DELETED, or both), notes rows, padding, and
sizes up to 400 rows and 100 columns.
"""
import argparse
import json
import os
import random
import struct
import sys
from xml.sax.saxutils import escape

MAX_ROWS = 400
MAX_COLUMNS = 100
MAX_CAUSES = 128  # 3.4

# ---------------------------------------------------------------- vocabulary

# voting -> (tags, function of cemv-matrix/1), with the spellings docs/csv.md accepts.
VOTINGS = {(1, 2): "or", (1, 3): "or", (2, 2): "and", (3, 3): "and", (2, 3): "2oo3"}


def voting_text(rng, m, n):
    return rng.choice([f"{m}oo{n}", f"{m}oo{n}", f"{m}oo{n}", f"{m} oo {n}", f"{m} out of {n}", f"{m}/{n}"])


HEADERS = {  # cause attribute column headers, as contractors spell them
    "id": ["Item", "Item No.", "No.", "Ref.", "Cause No.", "Item", "Pos."],
    "description": ["Description", "Cause description", "Service", "Description", "Initiator description"],
    "tag": ["Tag", "Tag No.", "Instrument Tag", "Instrument", "Loop No.", "Tag no", "Initiator tag"],
    "setpoint": ["Setpoint", "Set point", "Trip setting", "Trip point", "SP", "Trip setpoint", "Trip value"],
    "unit": ["Unit", "Units", "EU", "UOM", "Eng. units"],
    "voting": ["Voting", "Vote", "Voting logic", "MooN", "Logic", "Voting"],
    "sil": ["SIL", "SIL rating", "Required SIL", "SIL"],
    "trip_side": ["Trip direction", "H/L", "Trip side", "Hi/Lo"],
    "remarks": ["Remarks", "Notes", "Comment", "Remarks"],
}

EFFECT_LABELS = {  # labels of the stacked effect header rows
    "description": ["Effect description", "Description", "Service", "Final element description", "Description"],
    "action": ["Action", "Final action", "Safe state", "Action", "Actions"],
    "tag": ["Final element tag", "Output tag", "Tag No.", "Instrument Tag", "Tag", "Equipment tag"],
    "sil": ["SIL", "SIL rating", "Required SIL", "SIL"],
    "number": ["Effect No.", "Item", "No."],
}

BANNERS = [("CAUSES", "EFFECTS"), ("CAUSE", "EFFECT"), ("INITIATORS", "FINAL ELEMENTS"), ("Causes", "Effects")]

EQUIPMENT = ["feed drum", "separator", "flare KO drum", "reactor", "stripper", "surge drum", "absorber",
             "fuel gas drum", "condensate tank", "deaerator", "slug catcher", "test separator", "inlet scrubber",
             "export pipeline", "glycol contactor", "storage tank", "degasser", "charge drum", "flash drum"]
MEASURES = [  # (measurement, instrument letter, units, range)
    ("pressure", "PT", ["barg", "kPa", "psig", "bar"], (0.5, 150.0)),
    ("level", "LT", ["%", "mm"], (5.0, 95.0)),
    ("temperature", "TT", ["°C", "degC", "°F"], (-40.0, 450.0)),
    ("flow", "FT", ["m3/h", "t/h", "kg/s", "Sm3/d"], (1.0, 900.0)),
    ("differential pressure", "PDT", ["mbar", "kPa"], (1.0, 500.0)),
]
HIGH_WORDS = ["high", "high-high", "HH", "high high", "HI"]
LOW_WORDS = ["low", "low-low", "LL", "low low", "LO"]
DISCRETE = [  # (description, tag letters, setpoint text or None)
    ("Manual emergency shutdown", "HS", None), ("ESD pushbutton in control room", "HS", None),
    ("Fire detected in {eq} area", "BS", None), ("Gas detected at {eq}", "GD", None),
    ("Loss of instrument air", "PSL", "closed"), ("{eq} inlet valve not open", "ZSO", "open"),
    ("Field ESD pushbutton at {eq}", "HS", None), ("Flame failure at {eq}", "BSL", None),
    ("Loss of cooling water", "FSL", "open"), ("Motor overload trip", "XA", "ON"),
]
ACTIONS = {  # action spellings: the vocabulary of the issue (CLOSE, OPEN, STOP, TRIP, START, DE-ENERGISE)
    "CLOSE": ["CLOSE", "Close", "CLOSE"], "OPEN": ["OPEN", "Open"], "STOP": ["STOP", "Stop"],
    "TRIP": ["TRIP", "Trip"], "START": ["START", "Start"],
    "DE-ENERGISE": ["DE-ENERGISE", "De-energise", "DE-ENERGIZE"],
}
FINAL_ELEMENTS = [  # (tag letters, action, description)
    ("XV", "CLOSE", "Close {eq} inlet valve"), ("XV", "CLOSE", "Close {eq} outlet valve"),
    ("SDV", "CLOSE", "Close {eq} shutdown valve"), ("ESDV", "CLOSE", "Close {eq} emergency shutdown valve"),
    ("BDV", "OPEN", "Open {eq} blowdown valve"), ("XV", "OPEN", "Open {eq} vent valve"),
    ("P", "STOP", "Stop {eq} pump"), ("K", "TRIP", "Trip {eq} compressor"), ("H", "TRIP", "Trip {eq} heater"),
    ("P", "START", "Start firewater pump at {eq}"), ("XY", "DE-ENERGISE", "De-energise {eq} solenoid"),
    ("SOV", "DE-ENERGISE", "De-energise {eq} trip solenoid"), ("MOV", "CLOSE", "Close {eq} isolation valve"),
    ("M", "STOP", "Stop {eq} agitator motor"),
]
FOOTNOTES = ["Trip delayed 10 s during start-up (start-up timer in the BPCS)",
             "Override with the cabinet key switch during maintenance only",
             "Bypassed automatically below minimum flow", "Valve closes within 12 s (tested annually)",
             "Reset from the field panel only", "Inhibited while the unit is on standby",
             "Alarm in the BPCS before the trip"]
REMARKS = ["see P&ID 100-PID-004", "new in this revision", "field switch", "hardwired", "proof test 12 months",
           "setpoint per LOPA", "shared with unit 200"]


def float_text(v):
    t = ("%.2f" % v).rstrip("0").rstrip(".")
    return "0" if t in ("-0", "") else t


def single(v):
    """The IEEE single precision of a number, as REAL limits are (6.3.1)."""
    return struct.unpack("f", struct.pack("f", float(v)))[0]


# -------------------------------------------------------------------- model

class Cause:
    def __init__(self):
        self.item = ""           # the sheet id as written
        self.item_number = None  # written as a number cell
        self.description = ""
        self.tags = []           # the tags, in order
        self.tags_in_one_cell = False
        self.tag_cell = ""       # that one cell's text
        self.voting = ""         # the voting cell as written ("" none)
        self.function = "normal"
        self.setpoint = None     # (cell text, number cell?) or None
        self.analog = None       # {"limit_type", "limit", "unit"} or None
        self.unit = ""
        self.trip_side = ""
        self.sil_text = ""
        self.sil = 0
        self.remarks = ""
        self.notes = []          # the note values the import keeps (besides the sheet id)
        self.deleted = None      # None, "word", "strike", "both"
        self.merged = True       # a group's cells merged over its rows
        self.marks_on = "merged"  # a group's marks: "merged", "repeated", "first"

    def rows(self):
        return 1 if self.tags_in_one_cell else len(self.tags)


class Effect:
    def __init__(self):
        self.number = ""
        self.tag = ""
        self.description = ""
        self.action = ""       # as written
        self.sil_text = ""
        self.sil = 0


class Mark:
    def __init__(self, kind, footnote=None):
        self.kind = kind          # N S V R X
        self.footnote = footnote  # key or None

    def text(self):
        return self.kind + (self.footnote or "")


class Sheet:
    pass


# --------------------------------------------------------------- generation

def sil_cell(rng, sil):
    if sil == 0:
        return rng.choice(["-", "0", "n/a", "-"])
    return rng.choice([str(sil), str(sil), str(sil), f"SIL {sil}", f"SIL{sil}"])


def generate(seed):
    rng = random.Random(seed)
    s = Sheet()
    s.seed = seed
    s.stem = f"sheet_{seed}"
    s.rev = rng.choice("BCDEF")
    s.prev_rev = chr(ord(s.rev) - 1)
    s.sheet_name = rng.choice(["SIS Matrix", "C&E", "ESD Cause & Effect", "SIS C&E", "Matrix"]) + \
        rng.choice(["", f" rev {s.rev}", f" Rev. {s.rev}"])
    s.hidden_previous = rng.random() < 0.3
    s.cover = rng.random() < 0.7
    s.history = rng.random() < 0.5
    s.pad_columns = 1 if rng.random() < 0.15 else 0
    s.title_rows = rng.choice([0, 1, 2, 3, 3])
    s.banner = rng.choice([None, None, "both", "both", "effects", "corner"])
    s.banner_words = rng.choice(BANNERS)
    s.unit_no = rng.choice([1, 2, 3, 4, 5, 6, 7, 8, 9]) * 100 + rng.choice([0, 0, 10, 50])
    s.tag_sep = rng.choice(["-", "-", "-", "_"])

    size = rng.random()
    if size < 0.04:
        s.size = "huge"
    elif size < 0.14:
        s.size = "large"
    elif size < 0.45:
        s.size = "medium"
    else:
        s.size = "small"

    choose_attributes(rng, s)
    choose_effect_header(rng, s)
    make_effects(rng, s)
    make_causes(rng, s)
    make_marks(rng, s)
    s.notes_row = rng.random() < 0.35
    return s


def choose_attributes(rng, s):
    attrs = ["setpoint", "voting", "sil", "trip_side", "remarks"]
    chosen = [a for a, p in zip(attrs, [0.8, 0.75, 0.7, 0.15, 0.25]) if rng.random() < p]
    if s.size in ("large", "huge") and "voting" not in chosen:
        chosen.append("voting")
    if "trip_side" in chosen and "setpoint" not in chosen:
        chosen.remove("trip_side")
    middle = ["description", "tag"] if rng.random() < 0.7 else ["tag", "description"]
    rest = [a for a in chosen if a != "setpoint"]
    rng.shuffle(rest)
    if "setpoint" in chosen:
        at = rng.randrange(len(rest) + 1)
        rest[at:at] = ["setpoint", "unit"]
    s.attributes = ["id"] + middle + rest
    s.headers = {a: rng.choice(HEADERS[a]) for a in s.attributes}
    # The sheet says which axis holds the causes: a banner, a cause attribute or a cause word.
    if s.banner not in ("both", "corner") and not any(a in s.attributes for a in ("setpoint", "voting", "trip_side")):
        s.headers["description"] = "Cause description"


def choose_effect_header(rng, s):
    s.number_row = rng.choice(["none", "none", "none", "shared", "shared", "own"])
    kinds = ["description", "action", "tag", "sil"]
    count = rng.choice([2, 3, 3, 4, 4])
    if s.number_row != "none" and rng.random() < 0.15:
        chosen = rng.sample(["description", "action", "sil"], min(count, 3))
    else:
        chosen = ["tag"] + rng.sample(["description", "action", "sil"], count - 1)
    rng.shuffle(chosen)
    if s.number_row == "own":
        chosen.insert(rng.randrange(len(chosen) + 1), "number")
    s.effect_rows = chosen
    # One effect header row may stand on the row of the cause attribute headers
    # (the last one, and one that can be told by its content: not the SIL row).
    s.shared = None
    if s.number_row == "shared":
        s.shared = "number"
    elif chosen[-1] in ("tag", "description", "action", "number") and rng.random() < 0.3:
        s.shared = chosen[-1]
    s.label_place = rng.choice(["first", "first", "last"])
    s.effect_labels = {}
    for k in chosen:
        if k == s.shared:
            continue
        if k == "sil" or k == "number" or rng.random() < 0.85:
            s.effect_labels[k] = rng.choice(EFFECT_LABELS[k])


def limits(s):
    columns = MAX_COLUMNS - s.pad_columns - len(s.attributes)
    return {
        "small": ((3, 15), (2, 10)),
        "medium": ((15, 60), (8, 40)),
        "large": ((60, 110), (40, columns)),
        "huge": ((124, 128), (columns - 5, columns)),
    }[s.size]


def make_effects(rng, s):
    n = rng.randint(*limits(s)[1])
    s.effects = []
    used = set()
    # Tags of two or more digits, as plants number them (XV-11, P-302, BDV-2017).
    base = rng.choice([10, 100, 300, 1000, 2000]) if rng.random() < 0.5 else s.unit_no
    k = 0
    for i in range(n):
        letters, action, text = rng.choice(FINAL_ELEMENTS)
        e = Effect()
        while True:
            k += 1
            suffix = "A" if rng.random() < 0.1 else ""
            tag = f"{letters}{s.tag_sep}{base + k}{suffix}"
            if tag.replace("-", "_").upper() not in used:
                break
        used.add(tag.replace("-", "_").upper())
        e.tag = tag
        e.number = str(i + 1)
        eq = rng.choice(EQUIPMENT)
        e.description = text.format(eq=eq)
        if rng.random() < 0.25:
            e.description += f" {tag}"
        e.description = e.description[0].upper() + e.description[1:]
        e.action = rng.choice(ACTIONS[action])
        e.sil = rng.choice([0, 1, 1, 2, 2, 3])
        e.sil_text = sil_cell(rng, e.sil)
        s.effects.append(e)


def make_causes(rng, s):
    lo, hi = limits(s)[0]
    n = rng.randint(lo, hi)
    group_rate = {"small": 0.2, "medium": 0.25, "large": 0.45, "huge": 0.97}[s.size] if "voting" in s.attributes else 0
    # The largest sheets reach 400 rows: nearly every cause a group of three transmitters.
    votings = [v for v in VOTINGS if v[1] == 3] if s.size == "huge" else list(VOTINGS)
    fixed = len(s.effect_rows) + s.title_rows + 12  # header, banner, notes, legend
    id_style = rng.choice(["number"] * 7 + ["C-%02d", "I%03d", "C%d"])
    s.causes = []
    rows = fixed
    tag_no = rng.randint(1, 20)
    deleted_left = rng.choice([0, 0, 1, 1, 2, 3]) + (2 if s.size in ("large", "huge") else 0)
    for i in range(n):
        c = Cause()
        c.item = str(i + 1) if id_style == "number" else id_style % (i + 1)
        c.item_number = i + 1 if id_style == "number" else None
        if rng.random() < group_rate:
            m, k = rng.choice(votings)
            c.function = VOTINGS[(m, k)]
            c.voting = voting_text(rng, m, k)
        else:
            k = 1
            c.voting = rng.choice(["1oo1", "1oo1", "-", ""]) if "voting" in s.attributes else ""
        analog = "setpoint" in s.attributes and rng.random() < 0.75
        tag_no += rng.randint(1, 3)
        if analog:
            measure, letters, units, (a, b) = rng.choice(MEASURES)
            eq = rng.choice(EQUIPMENT)
            side = rng.choice(["high", "low"])
            word = rng.choice(HIGH_WORDS if side == "high" else LOW_WORDS)
            c.description = f"{eq} {measure} {word}"
            value = rng.uniform(a, b)
            value = round(value, rng.choice([0, 0, 1, 2])) if abs(value) < 1000 else round(value)
            text = float_text(value)
            c.unit = rng.choice(units)
            if rng.random() < 0.1:
                c.setpoint = (("> " if side == "high" else "< ") + text, False)
            else:
                c.setpoint = (text, True)
            c.analog = {"limit_type": side, "limit": single(float(text)), "unit": c.unit}
            if "trip_side" in s.attributes:
                c.trip_side = rng.choice(["H", "HH", "HIGH"] if side == "high" else ["L", "LL", "LOW"])
        else:
            text, letters, state = rng.choice(DISCRETE)
            c.description = text.format(eq=rng.choice(EQUIPMENT))
            if "setpoint" in s.attributes:
                if state and rng.random() < 0.6:
                    c.setpoint = (state, False)
                    c.notes.append(state)
                else:
                    c.setpoint = ("-", False)
                c.unit = "-"
            if "trip_side" in s.attributes:
                c.trip_side = "-"
        c.description = c.description[0].upper() + c.description[1:]
        base = f"{letters}{s.tag_sep}{s.unit_no // 100}{tag_no:03d}"
        c.tags = [base] if k == 1 else [base + chr(ord("A") + j) for j in range(k)]
        if k > 1 and rng.random() < (0.02 if s.size == "huge" else 0.15):
            c.tags_in_one_cell = True
            c.tag_cell = rng.choice([base + "A/" + "/".join(chr(ord("B") + j) for j in range(k - 1)), ", ".join(c.tags)])
        c.merged = rng.random() < 0.85
        c.marks_on = rng.choice(["merged", "merged", "repeated", "first"]) if c.merged else rng.choice(["repeated", "first"])
        if "sil" in s.attributes:
            c.sil = rng.choice([0, 1, 1, 2, 2, 3])
            c.sil_text = sil_cell(rng, c.sil)
        if "remarks" in s.attributes and rng.random() < 0.3:
            c.remarks = rng.choice(REMARKS)
            c.notes.append(c.remarks)
        if deleted_left and c.rows() == 1 and rng.random() < 0.2:
            deleted_left -= 1
            c.deleted = rng.choice(["word", "strike", "both"])
            if c.deleted != "strike":
                if "remarks" in s.attributes and rng.random() < 0.3:
                    c.remarks = rng.choice(["DELETED", f"Deleted rev. {s.rev}"])
                else:
                    c.description += rng.choice([f" (DELETED Rev. {s.rev})", " - DELETED", " (deleted)"])
        if rows + c.rows() > MAX_ROWS:
            break
        rows += c.rows()
        s.causes.append(c)


def make_marks(rng, s):
    s.marks = {}
    s.footnotes = {}
    if rng.random() < 0.45:
        style = rng.choice(["paren", "star"])
        keys = ["(1)", "(2)", "(3)"] if style == "paren" else ["*", "**"]
        for key in keys[:rng.randint(1, len(keys))]:
            s.footnotes[key] = rng.choice(FOOTNOTES)
    per_cause = {"small": (1, 3), "medium": (1, 4), "large": (1, 5), "huge": (1, 6)}[s.size]
    n_eff = len(s.effects)

    def mark():
        kind = rng.choices(["N", "S", "R", "V", "X"], [45, 40, 8, 5, 2])[0]
        note = rng.choice(sorted(s.footnotes)) if s.footnotes and rng.random() < 0.12 else None
        return Mark(kind, note)

    # Each cause trips a few effects near its own place (sheets run diagonally), each effect has a cause.
    for ci, c in enumerate(s.causes):
        centre = ci * n_eff // max(1, len(s.causes))
        for _ in range(rng.randint(*per_cause)):
            ei = min(n_eff - 1, max(0, centre + rng.randint(-3, 3)))
            s.marks[(ci, ei)] = mark()
    active = [ci for ci, c in enumerate(s.causes) if c.deleted is None]
    for ei in range(n_eff):
        if not any((ci, ei) in s.marks for ci in active):
            s.marks[(rng.choice(active), ei)] = mark()
    # A footnote nobody uses is still in the legend: a legend lists what the sheet may use.


# --------------------------------------------------------------- expectation

def effect_sheet_id(s, e):
    return e.number if s.number_row != "none" else e.tag


def expected(s, csv):
    """The matrix the sheet means, as the projection run_sheetgen.py compares:
    causes and effects by sheet id, intersections by the pair of sheet ids.
    From a CSV a row deleted by strikethrough alone is an active row (the CSV
    keeps no formatting, docs/csv.md "Deleted rows")."""
    causes = {}
    keep = []
    for ci, c in enumerate(s.causes):
        if c.deleted in ("word", "both") or (c.deleted == "strike" and not csv):
            continue
        keep.append(ci)
        notes = list(c.notes)
        causes[c.item] = {
            "description": c.description, "tags": c.tags, "function": c.function, "sil": c.sil,
            "analog": c.analog, "notes": sorted(notes),
        }
    effects = {}
    for e in s.effects:
        effects[effect_sheet_id(s, e)] = {
            "description": e.description if "description" in s.effect_rows else "",
            "tags": [e.tag] if "tag" in s.effect_rows else ["E_" + e.number],
            "sil": e.sil if "sil" in s.effect_rows else 0,
            "notes": [e.action] if "action" in s.effect_rows else [],
        }
    inter = []
    for (ci, ei), m in sorted(s.marks.items()):
        if ci not in keep:
            continue
        note = ""
        if m.footnote:
            note = m.footnote + " " + s.footnotes[m.footnote]
        inter.append([s.causes[ci].item, effect_sheet_id(s, s.effects[ei]), m.kind, note])
    return {"causes": causes, "effects": effects, "intersections": inter}


# ------------------------------------------------------------------ writing

class Cell:
    def __init__(self, text, style="cell", number=None, rows=1, columns=1):
        self.text, self.style, self.number, self.rows, self.columns = text, style, number, rows, columns


COVERED = "covered"


class Grid:
    def __init__(self):
        self.rows = []

    def put(self, r, c, cell):
        while len(self.rows) <= r:
            self.rows.append({})
        self.rows[r][c] = cell
        for dr in range(cell.rows):
            for dc in range(cell.columns):
                if dr or dc:
                    while len(self.rows) <= r + dr:
                        self.rows.append({})
                    self.rows[r + dr][c + dc] = COVERED

    def xml(self):
        out = []
        for row in self.rows:
            cells = []
            last = max(row) if row else -1
            c = 0
            while c <= last:
                cell = row.get(c)
                if cell is None:
                    run = 1
                    while c + run <= last and row.get(c + run) is None:
                        run += 1
                    cells.append('<table:table-cell table:number-columns-repeated="%d"/>' % run if run > 1
                                 else "<table:table-cell/>")
                    c += run
                    continue
                if cell is COVERED:
                    cells.append("<table:covered-table-cell/>")
                else:
                    attrs = ' table:style-name="%s"' % cell.style
                    if cell.rows > 1:
                        attrs += ' table:number-rows-spanned="%d"' % cell.rows
                    if cell.columns > 1:
                        attrs += ' table:number-columns-spanned="%d"' % cell.columns
                    if cell.text == "":
                        cells.append("<table:table-cell%s/>" % attrs)
                    elif cell.number is not None:
                        cells.append('<table:table-cell%s office:value-type="float" office:value="%s"><text:p>%s</text:p>'
                                     "</table:table-cell>" % (attrs, cell.number, escape(cell.text)))
                    else:
                        cells.append('<table:table-cell%s office:value-type="string"><text:p>%s</text:p>'
                                     "</table:table-cell>" % (attrs, escape(cell.text)))
                c += 1
            out.append("<table:table-row>" + "".join(cells) + "</table:table-row>")
        return "\n".join(out)


def matrix_grid(s, causes, effects, marks, struck_allowed=True):
    """The matrix sheet as a Grid: title, banner, effect header rows, the
    attribute header row, the cause rows, a notes row and the legend."""
    g = Grid()
    c0 = s.pad_columns
    attrs = s.attributes
    na = len(attrs)
    d0 = c0 + na  # first effect column
    r = 0
    titles = ["CAUSE AND EFFECT MATRIX - SAFETY INSTRUMENTED SYSTEM",
              f"Unit {s.unit_no} - document {s.unit_no}-CE-001, revision {s.rev}"]
    for t in range(s.title_rows):
        if t < 2:
            g.put(r, c0, Cell(titles[t], "title" if t == 0 else "sub", columns=min(na + len(effects), 12)))
        r += 1
    if s.banner:
        cw, ew = s.banner_words
        if s.banner == "both":
            g.put(r, c0, Cell(cw, "band", columns=na))
            g.put(r, d0, Cell(ew, "band", columns=len(effects)))
        elif s.banner == "effects":
            g.put(r, d0, Cell(ew, "band", columns=len(effects)))
        else:  # corner: the causes' word at the left, the effects' word beside the effect columns
            g.put(r, c0, Cell(cw, "band"))
            g.put(r, d0 - 1, Cell(ew, "band"))
        r += 1
    values = {
        "description": lambda e: Cell(e.description, "rot"),
        "action": lambda e: Cell(e.action, "eff"),
        "tag": lambda e: Cell(e.tag, "eff"),
        "sil": lambda e: Cell(e.sil_text, "eff", number=e.sil_text if e.sil_text.isdigit() else None),
        "number": lambda e: Cell(e.number, "eff", number=e.number),
    }
    for kind in s.effect_rows:
        if kind == s.shared:
            continue
        label = s.effect_labels.get(kind)
        if label:
            if s.label_place == "first":
                g.put(r, c0, Cell(label, "rowlabel", columns=na))
            else:
                g.put(r, d0 - 1, Cell(label, "rowlabel"))
        for j, e in enumerate(effects):
            g.put(r, d0 + j, values[kind](e))
        r += 1
    for i, a in enumerate(attrs):
        g.put(r, c0 + i, Cell(s.headers[a], "head"))
    if s.shared:
        for j, e in enumerate(effects):
            g.put(r, d0 + j, values[s.shared](e))
    r += 1
    for ci, c in causes:
        struck = c.deleted in ("strike", "both") and struck_allowed
        n = c.rows()
        span = n if c.merged else 1
        st = "struck" if struck else "cell"
        for i, a in enumerate(attrs):
            col = c0 + i
            if a == "tag":
                if c.tags_in_one_cell:
                    g.put(r, col, Cell(c.tag_cell, st))
                else:
                    for k, t in enumerate(c.tags):
                        g.put(r + k, col, Cell(t, st))
                continue
            if a == "id":
                cell = Cell(c.item, st, number=c.item if c.item_number else None)
            elif a == "description":
                cell = Cell(c.description, st)
            elif a == "setpoint":
                text, number = c.setpoint
                cell = Cell(text, st, number=text if number else None)
            elif a == "unit":
                cell = Cell(c.unit, st)
            elif a == "voting":
                cell = Cell(c.voting, st)
            elif a == "sil":
                cell = Cell(c.sil_text, st, number=c.sil_text if c.sil_text.isdigit() else None)
            elif a == "trip_side":
                cell = Cell(c.trip_side, st)
            else:
                cell = Cell(c.remarks, st)
            cell.rows = span if cell.text else 1
            g.put(r, col, cell)
        for j in range(len(effects)):
            m = marks.get((ci, j))
            mst = "struckmark" if struck else "mark"
            if m is None:
                continue
            if n > 1 and c.marks_on == "merged" and c.merged:
                g.put(r, d0 + j, Cell(m.text(), mst, rows=n))
            elif n > 1 and c.marks_on == "repeated":
                for k in range(n):
                    g.put(r + k, d0 + j, Cell(m.text(), mst))
            else:
                g.put(r, d0 + j, Cell(m.text(), mst))
        r += n
    if s.notes_row:
        r += 1
        g.put(r, c0, Cell("Notes: marks with a footnote are explained below; SIL per the LOPA of the unit.", "note"))
        r += 1
    if s.footnotes:
        r += 1
        for key in sorted(s.footnotes):
            g.put(r, c0, Cell(key, "note"))
            g.put(r, c0 + 1, Cell(s.footnotes[key], "note"))
            r += 1
    # Every row as wide as the grid, so that LibreOffice writes every field of every CSV line.
    return g


STYLES = """<office:automatic-styles>
<style:style style:name="ta_hidden" style:family="table"><style:table-properties table:display="false"/></style:style>
<style:style style:name="title" style:family="table-cell"><style:text-properties fo:font-size="14pt" fo:font-weight="bold"/></style:style>
<style:style style:name="sub" style:family="table-cell"><style:text-properties fo:font-style="italic"/></style:style>
<style:style style:name="band" style:family="table-cell"><style:table-cell-properties fo:background-color="#1f4e79" fo:border="0.5pt solid #000000"/><style:paragraph-properties fo:text-align="center"/><style:text-properties fo:font-weight="bold" fo:color="#ffffff"/></style:style>
<style:style style:name="rowlabel" style:family="table-cell"><style:table-cell-properties fo:background-color="#d9e2f3" fo:border="0.5pt solid #000000"/><style:paragraph-properties fo:text-align="end"/><style:text-properties fo:font-weight="bold"/></style:style>
<style:style style:name="head" style:family="table-cell"><style:table-cell-properties fo:background-color="#d9e2f3" fo:border="0.5pt solid #000000" fo:wrap-option="wrap"/><style:text-properties fo:font-weight="bold"/></style:style>
<style:style style:name="rot" style:family="table-cell"><style:table-cell-properties fo:background-color="#fff2cc" fo:border="0.5pt solid #000000" style:rotation-angle="90"/></style:style>
<style:style style:name="eff" style:family="table-cell"><style:table-cell-properties fo:background-color="#fff2cc" fo:border="0.5pt solid #000000"/><style:paragraph-properties fo:text-align="center"/></style:style>
<style:style style:name="cell" style:family="table-cell"><style:table-cell-properties fo:border="0.5pt solid #000000"/></style:style>
<style:style style:name="mark" style:family="table-cell"><style:table-cell-properties fo:border="0.5pt solid #000000"/><style:paragraph-properties fo:text-align="center"/><style:text-properties fo:font-weight="bold"/></style:style>
<style:style style:name="struck" style:family="table-cell"><style:table-cell-properties fo:background-color="#eeeeee" fo:border="0.5pt solid #000000"/><style:text-properties style:text-line-through-style="solid" style:text-line-through-type="single" fo:color="#7f7f7f"/></style:style>
<style:style style:name="struckmark" style:family="table-cell"><style:table-cell-properties fo:background-color="#eeeeee" fo:border="0.5pt solid #000000"/><style:paragraph-properties fo:text-align="center"/><style:text-properties fo:font-weight="bold" style:text-line-through-style="solid" style:text-line-through-type="single" fo:color="#7f7f7f"/></style:style>
<style:style style:name="note" style:family="table-cell"><style:text-properties fo:font-style="italic"/></style:style>
<style:style style:name="plain" style:family="table-cell"/>
</office:automatic-styles>"""

HEAD = """<?xml version="1.0" encoding="UTF-8"?>
<office:document xmlns:office="urn:oasis:names:tc:opendocument:xmlns:office:1.0" xmlns:style="urn:oasis:names:tc:opendocument:xmlns:style:1.0" xmlns:text="urn:oasis:names:tc:opendocument:xmlns:text:1.0" xmlns:table="urn:oasis:names:tc:opendocument:xmlns:table:1.0" xmlns:fo="urn:oasis:names:tc:opendocument:xmlns:xsl-fo-compatible:1.0" office:version="1.3" office:mimetype="application/vnd.oasis.opendocument.spreadsheet">
"""


def table(name, grid, hidden=False):
    style = ' table:style-name="ta_hidden"' if hidden else ""
    return '<table:table table:name="%s"%s>\n%s\n</table:table>' % (escape(name, {'"': "&quot;"}), style, grid.xml())


def cover(s):
    g = Grid()
    rows = [("Project", f"Unit {s.unit_no} revamp"), ("Document", f"{s.unit_no}-CE-001"), ("Revision", s.rev),
            ("Status", "Issued for construction"), ("Prepared by", "Process Automation Contractors Ltd.")]
    g.put(0, 0, Cell(f"Unit {s.unit_no} Safety Instrumented System", "title", columns=2))
    for i, (k, v) in enumerate(rows):
        g.put(i + 2, 0, Cell(k, "head"))
        g.put(i + 2, 1, Cell(v, "plain"))
    return g


def history(s):
    g = Grid()
    g.put(0, 0, Cell("Revision history", "title", columns=4))
    for j, h in enumerate(["Rev", "Date", "Description", "By"]):
        g.put(2, j, Cell(h, "head"))
    for i in range(ord(s.rev) - ord("A") + 1):
        rev = chr(ord("A") + i)
        for j, v in enumerate([rev, f"2024-0{i + 1}-1{i}", "Issued for review" if i == 0 else "Updated after HAZOP",
                               "J. Okafor"]):
            g.put(3 + i, j, Cell(v, "plain"))
    return g


def previous_revision(s):
    """The previous revision's grid: fewer causes, no deletions yet."""
    rng = random.Random(s.seed * 7919 + 1)
    causes = [(ci, c) for ci, c in enumerate(s.causes) if c.deleted is None]
    causes = causes[:max(1, len(causes) - rng.randint(0, 2))]
    marks = {k: v for k, v in s.marks.items() if rng.random() < 0.9}
    return matrix_grid(s, causes, s.effects, marks)


def fods(s):
    tables = []
    if s.cover:
        tables.append(table("Cover", cover(s)))
    if s.history:
        tables.append(table("Revision history", history(s)))
    if s.hidden_previous:
        tables.append(table(s.previous_sheet_name(), previous_revision(s), hidden=True))
    tables.append(table(s.sheet_name, matrix_grid(s, list(enumerate(s.causes)), s.effects, s.marks)))
    return HEAD + STYLES + "\n<office:body><office:spreadsheet>\n" + "\n".join(tables) + \
        "\n</office:spreadsheet></office:body></office:document>\n"


Sheet.previous_sheet_name = lambda s: f"Rev {s.prev_rev} (superseded)"


def describe(s):
    """One line on what the sheet varies, for the test's report."""
    return (f"{s.size}, {len(s.causes)} cause items x {len(s.effects)} effects; effect header "
            f"{'/'.join(s.effect_rows)}" + (f" ({s.shared} on the attribute header row)" if s.shared else "") +
            f"; banner {s.banner or 'none'}; labels {s.label_place}; attributes {','.join(s.attributes)}" +
            (f"; footnotes {' '.join(sorted(s.footnotes))}" if s.footnotes else "") +
            (f"; deleted {','.join(c.deleted for c in s.causes if c.deleted)}" if any(c.deleted for c in s.causes) else "") +
            ("; hidden previous revision" if s.hidden_previous else ""))


def features(s, grid):
    """What the sheet exercises, for the coverage line of the test, and a
    check that it stays within the limits the generator promises."""
    rows = len(grid.rows)
    columns = max((max(r) + 1 for r in grid.rows if r), default=0)
    active = [c for c in s.causes if c.deleted is None]
    assert rows <= MAX_ROWS and columns <= MAX_COLUMNS and len(active) <= MAX_CAUSES, (s.seed, rows, columns)
    assert all(len(c.tags) <= 3 for c in s.causes), s.seed
    groups = [c for c in s.causes if len(c.tags) > 1]
    return {
        "header_rows": len([k for k in s.effect_rows if k != "number"]),
        "order": "/".join(k for k in s.effect_rows if k != "number"),
        "number_row": s.number_row, "shared": s.shared or "none", "banner": s.banner or "none",
        "unlabelled": len([k for k in s.effect_rows if k != s.shared and k not in s.effect_labels]),
        "groups": len(groups), "merged_groups": len([c for c in groups if c.merged and not c.tags_in_one_cell]),
        "footnoted_marks": len([m for m in s.marks.values() if m.footnote]),
        "deleted": sorted(c.deleted for c in s.causes if c.deleted),
        "hidden_previous": s.hidden_previous, "rows": rows, "columns": columns,
    }


def write(seed, out):
    s = generate(seed)
    with open(os.path.join(out, s.stem + ".fods"), "w", encoding="utf-8") as f:
        f.write(fods(s))
    info = {
        "seed": seed, "stem": s.stem, "sheet": s.sheet_name, "needs_sheet": s.hidden_previous,
        "describe": describe(s), "workbook": expected(s, csv=False), "csv": expected(s, csv=True),
        "features": features(s, matrix_grid(s, list(enumerate(s.causes)), s.effects, s.marks)),
    }
    with open(os.path.join(out, s.stem + ".expected.json"), "w", encoding="utf-8") as f:
        json.dump(info, f, indent=1, ensure_ascii=False, sort_keys=True)
        f.write("\n")
    return info


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("seeds", nargs="*", type=int)
    p.add_argument("--first", type=int)
    p.add_argument("--count", type=int, default=0)
    p.add_argument("--out", required=True)
    a = p.parse_args()
    seeds = list(a.seeds) + (list(range(a.first, a.first + a.count)) if a.first is not None else [])
    if not seeds:
        p.error("give seeds, or --first S --count N")
    os.makedirs(a.out, exist_ok=True)
    for seed in seeds:
        info = write(seed, a.out)
        print(f"{info['stem']}: {info['describe']}")


if __name__ == "__main__":
    main()

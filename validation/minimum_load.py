"""SKF's minimum load factors of the catalogue bearings -> materials/minimum_load.toml.

Source: SKF *Rolling bearings*, PUB BU/P1 17000/1 EN (October 2018), as transcribed in github.com/ArtemFilin1990/Mar
02_Термины_и_основы/Теория/типы подшипников/Rolling_bearings_1.md (commit 68b9707fc46f43fa4d0c070323c23237becbce8b,
one printed cell a line, decimal commas, a space the thousands separator: "0,000 224" = 0.000224):

* "Requisite minimum load" (p. 106) and, for deep groove ball bearings (p. 254, lines 30590-30700),
  F_rm = k_r (nu n / 1000)^(2/3) (d_m / 100)^2 [kN]: the series' factors k_r were read by hand from the
  product tables 1.1 (lines 31628-40400; one value per series at bores 10-60 mm) and are kept here as they were
  committed (``DEEP_GROOVE``), not extracted;
* single row angular contact ball bearings, single or in tandem ("Loads", p. 398, lines 74856-74940), and single
  direction thrust ball bearings ("Loads", p. 469, lines 94124-94160): the minimum axial load
  F_am = A (n / 1000)^2 [kN], n in r/min, A the minimum (axial) load factor of the product tables.  (Angular
  contact pairs back-to-back or face-to-face take a minimum radial load with k_r instead: not on file.)

Extracted rows (``--extract``, validation/data/minimum_load_skf2018.csv, each value's line):

* table 3.1 "Single row angular contact ball bearings" (lines 75528-83813), nine pairs of printed pages: the
  first page of a pair has per row ``[d] D B C C0 Pu n_ref n_lim mass`` and two designation cells (universally
  matchable, basic design / sealed; "–" where none), d only on a size's first row; the second page
  ("Calculation factors") has per row, in the same order, ``[d] d1 d2 D1,D2 D5 r1,2 r3,4 a da da Da Db ra rb A
  kr`` ("–" a cell without a value).  A row of the second page is matched to the first page's row of the same
  position; a pair is used only where the second page holds exactly the cells the first page's rows ask (16
  with d, 15 without) and every d it prints equals the first page's, else the extraction stops naming the page;
* table 5.1 "Single direction thrust ball bearings" (lines 94269-95990): a row is its designation's line
  (511xx, 512xx, 513xx) and the nine or ten values above it, ``[d] D H C C0 Pu A n_ref n_lim mass``
  (as validation/maker_speeds.py ``--extract-thrust`` reads the same table for the speeds).

Rules (what the generator does, and why):

* angular contact: each catalogue designation of the 40° series 72B / 73B (``7205B``; the seed's ``7210`` is a
  7210 B) takes SKF's ``72xx BE`` row with a polyamide cage (``BECBP``, universally matchable) or, without one,
  with a steel cage (``BEP``); without either, the first open ``BE`` row of its size (not a capped ``BE-2RZ``
  one): A differs by cage and variant (7209 BECBP 0.012, BECBY 0.0128, 7209 AC (25°) 0.00496), and the
  polyamide or steel cage is the catalogue's basic design;
* thrust: each 511, 512, 513 catalogue designation takes the table's row of the same designation
  (51205-3ball is no SKF designation: none);
* a row whose d x D x B (thrust: d x D x H) differs from the catalogue's is not used (named in the output);
* the deep groove factors are kept as committed (``DEEP_GROOVE``).

Checked once by hand (not by the script): the A of the 63 rows of table 5.1 extracted here equal, row for row, those
of the SKF General Catalogue's Russian edition (2006 data; github.com/ArtemFilin1990/Mar 07_Бренды_и_каталоги/
Бренды/каталоги/Общий_каталог_подшипников_SKF.md, commit b623d8e, the rows validation/maker_speeds.py reads) — so
A is not monotonic in size where SKF prints it so in both editions (51112 0.077 > 51113 0.06; 51205 0.015 > 51206
0.013; 51208 0.058 > 51209 0.038).  The 2006 edition has no A for angular contact bearings (no cross-check);
the 72B / 73B values taken grow with size in each series.  One row not used looks odd: 7205 ACCBM (25°) prints
A 0.00656, four times the 7205 BE's 0.00159, where every other AC row is below its BE row.

Run:  python validation/minimum_load.py                       (writes materials/minimum_load.toml)
      python validation/minimum_load.py --extract SKF2018_MD   (rewrites validation/data/minimum_load_skf2018.csv
      from the transcription, read at the commit above)
"""
from __future__ import annotations

import csv
import re
import sys
from pathlib import Path

from thermobear.contact.geometry import bearing_names, bearing_table

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
OUT = ROOT / "materials" / "minimum_load.toml"
ROWS = HERE / "data" / "minimum_load_skf2018.csv"
SOURCE = ("SKF Rolling bearings PUB BU/P1 17000/1 EN (October 2018), product tables 3.1 (single row angular contact "
          "ball bearings, A) and 5.1 (single direction thrust ball bearings, A), as transcribed in "
          "github.com/ArtemFilin1990/Mar 02_Термины_и_основы/Теория/типы подшипников/Rolling_bearings_1.md "
          "(commit 68b9707fc46f43fa4d0c070323c23237becbce8b)")
COLUMNS = ["table", "designation", "d_mm", "D_mm", "width_mm", "A", "row_lines", "A_line"]
NUMBER = re.compile(r"\d[\d ]*(,[\d ]+)?")
DESIGNATION = re.compile(r"▶?(\d{4,5} [A-Z][\w-]*)")
EMPTY = ("–", "-")                              # a cell without a designation (the transcription has both)
THRUST_DESIGNATION = re.compile(r"51[123]\d\d")
ANGULAR_HEADER = "3.1 Single row angular contact ball bearings"
ANGULAR_END = "3.2 Double row angular contact ball bearings"
FACTORS_HEADER = "Calculation factors"
THRUST_LINES = (94269, 95990)

#: SKF 2018 product tables 1.1, k_r of the deep groove series (read by hand at bores 10-60 mm; not extracted)
DEEP_GROOVE = [
    ("618", 0.015, "SKF 2018 product tables 1.1, k_r of the 618 rows (d 10-60 mm)"),
    ("619", 0.02, "SKF 2018 product tables 1.1, k_r of the 619 rows (d 10-60 mm)"),
    ("160", 0.02, "SKF 2018 product tables 1.1, k_r of the 160 rows (d 15-60 mm)"),
    ("60", 0.025, "SKF 2018 product tables 1.1, k_r of the 60 rows (d 10-60 mm)"),
    ("62", 0.025, "SKF 2018 product tables 1.1, k_r of the 62 rows (d 10-60 mm); worked example C.2 (6207)"),
    ("63", 0.03, "SKF 2018 product tables 1.1, k_r of the 63 rows (d 10-60 mm)"),
]

HEADER = """\
# SKF's requisite minimum load of ball bearings: the load below which the balls may skid (the rolling
# elements' and cage's inertia and the lubricant's drag exceed the traction the contacts can carry),
# with smearing damage to balls and raceways.  Read by thermobear.rating.minimum_load.
#
# Deep groove ball bearings (SKF 2018, p. 254):  F_rm = k_r (nu n / 1000)^(2/3) (d_m / 100)^2   [kN]
#   nu operating viscosity [mm2/s], n [r/min], d_m = (d + D)/2 [mm]; "If minimum load cannot be reached,
#   consider preloading."  k_r: minimum load factor of the product tables (one value per series, the same
#   at every bore of the series: read for bores 10-60 mm of the tables; SKF's worked example, the rope
#   sheave of section C.2, takes k_r = 0.025 for a 6207).
#
# Source: SKF (2018). Rolling bearings, PUB BU/P1 17000/1 EN, October 2018: "Requisite minimum load"
# (p. 106), deep groove ball bearings "Loads" (p. 254) and product tables 1.1 (k_r column, p. 260 ff.),
# read in the public transcription github.com/ArtemFilin1990/Mar (commit 68b9707f), file
# "02_Термины_и_основы/Теория/типы подшипников/Rolling_bearings_1.md": p. 254 at lines 30590-30700, the
# product tables' k_r columns at lines 31628-40400 (each series identified by its abutment diameter D_a).
# Series the tables list that thermobear's catalogue has not (617, 628, 637, 638, 639, 161, 622, 623, 630,
# 64) are left out: not read row by row.
#
# Single row angular contact ball bearings, single or in tandem (SKF 2018 "Loads", p. 398; lines 74856-74940)
# and single direction thrust ball bearings (p. 469; lines 94124-94160):
#   F_am = A (n / 1000)^2   [kN]    n [r/min]; A: minimum (axial) load factor of the product tables, one value
#   per bearing (it differs by cage and variant).  Angular contact pairs back-to-back or face-to-face take a
#   minimum radial load with k_r instead: not on file.
# [angular_contact.A]: the catalogue's 72B / 73B designations, SKF's "72xx BE" row with a polyamide (BECBP) or
# else steel (BEP) cage, from table 3.1 (lines 75528-83813; A on the "Calculation factors" page, matched by row
# position); [thrust.A]: the 511 / 512 / 513 designations, table 5.1 (lines 94269-95990).  Each row's d x D x B
# (H) equals the catalogue's.  Generated, with these two tables, by validation/minimum_load.py from
# validation/data/minimum_load_skf2018.csv (the extracted rows and their lines) — do not edit by hand.
"""


def _num(text: str) -> float:
    return float(text.replace(" ", "").replace(",", "."))


def _is_num(text: str) -> bool:
    return NUMBER.fullmatch(text) is not None


def _cells(lines: list, lo: int, hi: int) -> list:
    """(1-based line, text) of the non-empty lines lo..hi-1 (0-based indices)."""
    return [(i + 1, lines[i].strip()) for i in range(lo, hi) if lines[i].strip()]


def _first_page(cells: list, where: str) -> list:
    """The rows of a first page: dicts of d (None where it repeats), D, B, the designations and the lines."""
    i = next(k for k, (_, t) in enumerate(cells) if t == "kg")
    while not _is_num(cells[i][1]):
        i += 1
    rows = []
    while i < len(cells):
        j = i
        while j < len(cells) and _is_num(cells[j][1]):
            j += 1
        names = cells[j:j + 2]
        if j - i not in (8, 9) or len(names) < 2 or not all(t in EMPTY or DESIGNATION.fullmatch(t) for _, t in names):
            break
        vals = [_num(t) for _, t in cells[i:j]]
        d = vals.pop(0) if len(vals) == 9 else None
        rows.append({"d": d, "D": vals[0], "B": vals[1], "first": cells[i][0], "last": names[-1][0],
                     "names": [(ln, DESIGNATION.fullmatch(t).group(1)) for ln, t in names if t not in EMPTY]})
        i = j + 2
    if not rows:
        raise ValueError(f"{where}: no rows")
    return rows


def _factors_page(cells: list, rows: list, where: str) -> None:
    """Set A (and its line) of each first-page row from the second page, matched by position."""
    i = next(k for k, (_, t) in enumerate(cells) if t == "kr")
    while not _is_num(cells[i][1]):
        i += 1
    vals = []
    while i < len(cells) and (_is_num(cells[i][1]) or cells[i][1] == "–"):
        vals.append(cells[i])
        i += 1
    want = sum(16 if r["d"] is not None else 15 for r in rows)
    if len(vals) == want + 1 and vals[-1][1].isdigit() and i < len(cells) and cells[i][1] == "0.0":
        vals.pop()                                  # the printed page's number, then its footer "0.0", "3.1"
    if len(vals) != want:
        raise ValueError(f"{where}: {len(vals)} cells on the calculation factors page, the rows ask {want}")
    k = 0
    for r in rows:
        n = 16 if r["d"] is not None else 15
        cell = vals[k:k + n]
        if r["d"] is not None and _num(cell[0][1]) != r["d"]:
            raise ValueError(f"{where}: d {cell[0][1]} at line {cell[0][0]}, the first page's {r['d']:g}")
        kr = _num(cell[-1][1])
        if not 0.05 <= kr <= 0.2:
            raise ValueError(f"{where}: k_r {kr} at line {cell[-1][0]}: the columns are misread")
        r["A"], r["A_line"] = _num(cell[-2][1]), cell[-2][0]
        k += n


def angular_rows(lines: list) -> list:
    """The rows of table 3.1: (designation, d, D, B, A, row lines, A's line), one per designation cell."""
    heads = [i for i, t in enumerate(lines) if t.strip() == ANGULAR_HEADER]
    end = next(i for i, t in enumerate(lines) if t.strip() == ANGULAR_END)
    out = []
    for h, nxt in zip(heads, heads[1:] + [end]):
        f = next(i for i in range(h, nxt) if lines[i].strip() == FACTORS_HEADER)
        where = f"table 3.1 page at line {h + 1}"
        rows = _first_page(_cells(lines, h, f), where)
        _factors_page(_cells(lines, f, nxt), rows, where)
        d = None
        for r in rows:
            d = r["d"] if r["d"] is not None else d
            for _, name in r["names"]:
                out.append(["3.1", name, f"{d:g}", f"{r['D']:g}", f"{r['B']:g}", repr(r["A"]),
                            f"{r['first']}-{r['last']}", str(r["A_line"])])
    return out


def thrust_rows(lines: list) -> list:
    """The 511, 512, 513 rows of table 5.1: (designation, d, D, H, A, row lines, A's line)."""
    out, d = [], None
    for i in range(*THRUST_LINES):
        m = re.fullmatch(r"▶?(\S+)", lines[i].strip())
        if not m or not THRUST_DESIGNATION.fullmatch(m.group(1)):
            continue
        j = i
        while j > 0 and _is_num(lines[j - 1].strip()):
            j -= 1
        vals = [_num(v.strip()) for v in lines[j:i]]
        if len(vals) not in (9, 10) or (len(vals) == 9 and d is None):
            raise ValueError(f"table 5.1 line {i + 1}: {len(vals)} numbers above {m.group(1)}, not 9 or 10")
        first = len(vals) == 10
        if first:
            d = vals.pop(0)
        a_line = j + 1 + (6 if first else 5)
        out.append(["5.1", m.group(1), f"{d:g}", f"{vals[0]:g}", f"{vals[1]:g}", repr(vals[5]),
                    f"{j + 1}-{i + 1}", str(a_line)])
    return out


def extract(md: Path) -> None:
    """Write the rows of tables 3.1 and 5.1 (with their lines) to validation/data/minimum_load_skf2018.csv."""
    lines = Path(md).read_text(encoding="utf-8").split("\n")
    with open(ROWS, "w", newline="", encoding="utf-8") as f:
        f.write(f"# {SOURCE}; width_mm is B (3.1) or H (5.1); row_lines: the first page's row (3.1) or the row "
                "(5.1), d carried from the size's first row; extracted by validation/minimum_load.py --extract\n")
        csv.writer(f, lineterminator="\n").writerows([COLUMNS] + angular_rows(lines) + thrust_rows(lines))


def _read() -> list:
    with open(ROWS, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def _pick(name: str, rows: dict) -> dict | None:
    """SKF's row of a 72B / 73B catalogue designation: BECBP, else BEP, else the first open BE row of the size."""
    stem = name[:4]
    for suffix in ("BECBP", "BEP"):
        if f"{stem} {suffix}" in rows:
            return rows[f"{stem} {suffix}"]
    return next((r for d, r in rows.items() if re.fullmatch(rf"{stem} BE(?!-)\w*", d)), None)


def build() -> tuple[str, dict, list]:
    """(the data file's text, {section: {catalogue designation: entry}}, notes) from the extracted rows."""
    rows = {"3.1": {}, "5.1": {}}
    for r in _read():
        rows[r["table"]].setdefault(r["designation"], r)
    out, notes = {"angular_contact": {}, "thrust": {}}, []
    for name in bearing_names():
        t = bearing_table(name)
        series = t.get("series")
        if series in ("72B", "73B"):
            section, table, r = "angular_contact", "3.1", _pick(name, rows["3.1"])
        elif series in ("511", "512", "513"):
            section, table, r = "thrust", "5.1", rows["5.1"].get(name)
        else:
            continue
        if r is None:
            notes.append(f"{name}: no row in table {table}")
            continue
        dims = tuple(float(r[k]) for k in ("d_mm", "D_mm", "width_mm"))
        cat = (t["bore_mm"], t["outer_diameter_mm"], t["width_mm"])
        if dims != cat:
            notes.append(f"{name}: {r['designation']} (table {table}, lines {r['row_lines']}) d x D x "
                         f"{'B' if table == '3.1' else 'H'} {dims} differs from the catalogue's {cat}; not used")
            continue
        out[section][name] = {"value": float(r["A"]), "designation": r["designation"],
                              "source": (f"SKF 2018 table {table}, {r['designation']}: A at line {r['A_line']}, "
                                         f"row at lines {r['row_lines']}")}
    return write(out), out, notes


def write(entries: dict) -> str:
    body = ["", "[deep_groove.k_r]"]
    body += [f'"{s}" = {{ value = {v!r}, source = "{src}" }}' for s, v, src in DEEP_GROOVE]
    for section in ("angular_contact", "thrust"):
        body += ["", f"[{section}.A]"]
        body += [f'"{n}" = {{ value = {e["value"]!r}, designation = "{e["designation"]}", source = "{e["source"]}" }}'
                 for n, e in entries[section].items()]
    return HEADER + "\n".join(body) + "\n"


def main(argv) -> int:
    if argv[:1] == ["--extract"]:
        extract(Path(argv[1]))
        return 0
    text, entries, notes = build()
    OUT.write_text(text, encoding="utf-8")
    print(f"{OUT.relative_to(ROOT)}: A of {len(entries['angular_contact'])} angular contact and "
          f"{len(entries['thrust'])} thrust catalogue designations")
    for section, got in entries.items():
        picked = sorted({e["designation"].split(" ", 1)[-1] for e in got.values()}) if section != "thrust" else []
        print(f"  {section}: A {min(e['value'] for e in got.values()):g} … {max(e['value'] for e in got.values()):g}"
              + (f"; SKF rows {', '.join(picked)}" if picked else ""))
    for n in notes:
        print("note:", n)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

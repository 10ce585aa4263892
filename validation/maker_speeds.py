"""Makers' reference and limiting speeds of the catalogue bearings -> materials/maker_speeds.toml.

Sources (public transcriptions of SKF's product tables; their rows are kept in validation/data/ with the
line each came from, so that the data file can be written again without them):

* ``jraposo``: github.com/JRaposo-m/SKF-Bearing-Selection-Tool, skf_model/bearings/data/deep_groove_ball/
  deep_groove_ball.csv (SKF General Catalogue 10000 EN as transcribed there): deep groove ball bearings,
  open and capped (-2Z, -2RZ shields; -2RSL, -2RSH, -2RS1 contact seals), columns n_ref and n_limit [r/min];
  capped bearings with contact seals have no reference speed (blank), as in SKF's tables.
* ``bd_warehouse``: github.com/gumyr/bd_warehouse, src/bd_warehouse/data/
  single_row_deep_groove_ball_bearing_parameters.csv, single_row_capped_deep_groove_ball_bearing_parameters.csv
  and single_row_angular_contact_ball_bearing_parameters.csv (SKF values, columns Speed-reference and
  Speed-limit [r/min]): deep groove bores 3-10 mm, capped bores 3-8 mm, angular contact 7200-7203 B, 7302-7305 B.
* ``skf2018`` and ``skf2006`` (thrust ball bearings, validation/data/maker_speeds_skf_thrust.csv): two SKF
  catalogue editions as transcribed in github.com/ArtemFilin1990/Mar — SKF *Rolling bearings* PUB BU/P1
  17000/1 EN (October 2018), product table 5.1 "Single direction thrust ball bearings", in
  02_Термины_и_основы/Теория/типы подшипников/Rolling_bearings_1.md (commit 68b9707, one value a line: a row is
  its designation's line and the nine or ten lines above it, d left out where it repeats the row above), and
  the SKF General Catalogue, Russian edition (data as of early 2006, its preface), the same table in
  07_Бренды_и_каталоги/Бренды/каталоги/Общий_каталог_подшипников_SKF.md (commit b623d8e, a row a line, "9.500"
  = 9500 rpm): columns d, D, H, reference and limiting speed [r/min]; the 511, 512 and 513 rows of d 10-100 mm
  are extracted (the catalogue's thrust series; 51205-3ball is no SKF designation).  ISO 15312 and DIN 732
  exclude thrust ball bearings (ISO 15312's scope: "Thrust ball bearings are excluded ... as kinematic effects
  do not allow the thermal speed rating to be applied"; the 2006 catalogue's reference speeds follow ISO
  15312:2003 "за исключением упорных шарикоподшипников", except thrust ball bearings, its lines 6186-6188):
  SKF's reference speed of a thrust ball bearing is SKF's own rating (SKF 2018, 'Operating temperature and speed', p. 130: its reference speeds
  come from the SKF friction model at ISO 15312's reference conditions), not the standard's.  The editions' load ratings differ for some sizes
  (51208 C 44.2 kN in 2018, 46.8 kN in 2006); they are not read.

No source distinguishes grease from oil: SKF's limiting speed is one value per bearing (the kinematic limit of
the bearing, its cage or its seals), used for either lubrication here.

Rules (what the generator does, and why):

* a catalogue designation matches a source row of the same designation with its d x D x B (a thrust
  bearing's d x D x H); a row whose dimensions differ from the catalogue's is not used (named in the output: a
  transcription error of one of them);
* angular contact: the catalogue's 40° ``72xxB`` / ``73xxB`` (the seed's 7210 = 7210 B) take SKF's
  ``72xx BE...`` row of the source, whichever cage it lists (BECBP polyamide, BECBM brass, BECBPH PEEK: the
  one the source has; its designation is kept with the value);
* where both sources give a value they are compared: equal -> ``cross_check`` names the other row; unequal ->
  both recorded, the value of the row with the catalogue's dimensions and the newer catalogue transcription
  (jraposo, which lists every variant) is taken and the other kept in ``cross_check`` (none was found);
* thrust bearings: the 2018 edition's row (the newer catalogue) is taken and the 2006 edition's kept in
  ``cross_check`` (equal, or its values and the disagreement named: 51307, 3400 / 4800 rpm in 2018 against
  3200 / 4500 rpm in 2006); the 2006 row where the 2018 one is not used;
* duplicate rows of one designation in a source: identical values -> the first row, the duplicates named in
  ``note``; different values -> not used (none was found among the catalogue's designations).

Run:  python validation/maker_speeds.py                 (writes materials/maker_speeds.toml)
      python validation/maker_speeds.py --extract JR_CSV BDW_DATA_DIR   (rewrites validation/data/ from the
      sources' files; the generator then reads those)
      python validation/maker_speeds.py --extract-thrust ROLLING_BEARINGS_1_MD SKF_RU_MD   (rewrites
      validation/data/maker_speeds_skf_thrust.csv from the two transcriptions, read at the commits above)
"""
from __future__ import annotations

import csv
import re
import sys
from pathlib import Path

from thermobear.contact.geometry import bearing_names, bearing_table

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
OUT = ROOT / "materials" / "maker_speeds.toml"
JR_ROWS = HERE / "data" / "maker_speeds_jraposo.csv"
BDW_ROWS = HERE / "data" / "maker_speeds_bd_warehouse.csv"
THRUST_ROWS = HERE / "data" / "maker_speeds_skf_thrust.csv"

SOURCES = {
    "jraposo": ("SKF General Catalogue 10000 EN product tables as transcribed in github.com/JRaposo-m/"
                "SKF-Bearing-Selection-Tool skf_model/bearings/data/deep_groove_ball/deep_groove_ball.csv "
                "(commit df9a951, 2026-04-14)"),
    "bd_warehouse": ("SKF product table values as transcribed in github.com/gumyr/bd_warehouse "
                     "src/bd_warehouse/data/ (commit ea24664, 2024-03-27)"),
    "skf2018": ("SKF Rolling bearings PUB BU/P1 17000/1 EN (October 2018), product table 5.1 single direction thrust "
                "ball bearings, as transcribed in github.com/ArtemFilin1990/Mar 02_Термины_и_основы/Теория/"
                "типы подшипников/Rolling_bearings_1.md (commit 68b9707, 2026-01-17)"),
    "skf2006": ("SKF General Catalogue, Russian edition (data as of early 2006), single direction thrust ball "
                "bearings, as transcribed in github.com/ArtemFilin1990/Mar 07_Бренды_и_каталоги/Бренды/каталоги/"
                "Общий_каталог_подшипников_SKF.md (commit b623d8e, 2026-01-17)"),
}
#: thrust edition -> (its transcription's path in github.com/ArtemFilin1990/Mar, the commit it was read at)
THRUST_FILES = {
    "skf2018": ("02_Термины_и_основы/Теория/типы подшипников/Rolling_bearings_1.md",
                "68b9707fc46f43fa4d0c070323c23237becbce8b"),
    "skf2006": ("07_Бренды_и_каталоги/Бренды/каталоги/Общий_каталог_подшипников_SKF.md",
                "b623d8e17ca13788f4f01e3469621a974a5a9bd8"),
}
#: how two sources' values of one entry are combined: the sources' names, which is taken where they differ
RADIAL = ("jraposo", "bd_warehouse", "jraposo's row taken (every variant of the bearing from one transcription)")
THRUST = ("skf2018", "skf2006", "the 2018 edition's row taken (the newer catalogue)")
BDW_FILES = ("single_row_deep_groove_ball_bearing_parameters.csv",
             "single_row_capped_deep_groove_ball_bearing_parameters.csv",
             "single_row_angular_contact_ball_bearing_parameters.csv")
#: SKF closure suffix -> variant key of the data file
VARIANTS = {"": "open", "-2Z": "2Z", "-2RZ": "2RZ", "-2RSL": "2RSL", "-2RSH": "2RSH", "-2RS1": "2RS1"}
COLUMNS = ["source_line", "designation", "d_mm", "D_mm", "B_mm", "n_ref_rpm", "n_limit_rpm"]
THRUST_COLUMNS = ["edition", "file", "commit", "source_line", "designation", "d_mm", "D_mm", "H_mm", "n_ref_rpm",
                  "n_limit_rpm"]
#: the thrust series extracted (the catalogue's: 511, 512, 513 of bores 10-100 mm)
THRUST_DESIGNATION = re.compile(r"51[123]\d\d")
THRUST_MAX_BORE_MM = 100.0


def _number(text: str):
    t = text.strip().replace("\u2013", "").replace("-", "")
    return float(t) if t else None


def extract(jr_csv: Path, bdw_dir: Path) -> None:
    """Write the sources' rows the generator reads (the designation, d x D x B and the two speeds, with the
    line of the source file each came from) to validation/data/."""
    with open(jr_csv, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f, skipinitialspace=True))
    col = {h.strip(): i for i, h in enumerate(rows[0])}
    out = [COLUMNS]
    for line, r in enumerate(rows[1:], start=2):
        if len(r) < len(col):
            continue
        out.append([str(line), r[col["designation"]].strip(), r[col["d"]], r[col["D"]], r[col["B"]],
                    r[col["n_ref"]].strip(), r[col["n_limit"]].strip()])
    _write_rows(JR_ROWS, "jraposo", out)
    out = [["file"] + COLUMNS]
    for name in BDW_FILES:
        with open(bdw_dir / name, newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        col = {h.strip(): i for i, h in enumerate(rows[0])}
        speed = {h.strip().lower(): i for i, h in enumerate(rows[0]) if "speed" in h.lower()}
        for line, r in enumerate(rows[1:], start=2):
            des = r[col["SKT:Designation"]].strip().lstrip("* ").strip()
            if not des or des == "\u2013":
                continue
            out.append([name, str(line), des, r[col["SKT:d"]], r[col["SKT:D"]], r[col["SKT:B"]],
                        r[speed["skt:speed-reference"]], r[speed["skt:speed-limit"]]])
    _write_rows(BDW_ROWS, "bd_warehouse", out)


def _write_rows(path: Path, source: str, rows: list) -> None:
    with open(path, "w", newline="", encoding="utf-8") as f:
        f.write(f"# {SOURCES[source]}; extracted by validation/maker_speeds.py --extract\n")
        csv.writer(f, lineterminator="\n").writerows(rows)


def _thrust_2018(lines: list) -> list:
    """(first line, last line, designation, d, D, H, n_ref, n_limit) of the 2018 transcription: one value a line,
    a row its designation's line (``▶51208``: the popular-item mark) and the numbers on the lines just above
    it — D, H, C, C0, Pu, A, reference and limiting speed, mass, with d before them where it changes."""
    def num(t):
        return float(t.replace(" ", "").replace(",", "."))
    out, d = [], None
    for i, line in enumerate(lines):
        m = re.fullmatch(r"▶?(\S+)", line.strip())
        if not m or not THRUST_DESIGNATION.fullmatch(m.group(1)):
            continue
        j = i
        while j > 0 and re.fullmatch(r"\d[\d ]*(,[\d ]+)?", lines[j - 1].strip()):
            j -= 1
        vals = [num(v) for v in lines[j:i]]
        if len(vals) not in (9, 10) or (len(vals) == 9 and d is None):
            raise ValueError(f"2018 transcription line {i + 1}: {len(vals)} numbers above {m.group(1)}, not 9 or 10")
        if len(vals) == 10:
            d = vals.pop(0)
        out.append((j + 1, i + 1, m.group(1), d, vals[0], vals[1], vals[6], vals[7]))
    return out


def _thrust_2006(lines: list) -> list:
    """The same of the 2006 transcription: a row a line, its fields ended by ". " (d left out — "." — where it
    repeats the row above), a dot the thousands separator ("9.500" = 9500) and a comma the decimal one."""
    def num(t):
        return float(t.replace(".", "").replace(",", "."))
    out, d = [], None
    for i, line in enumerate(lines):
        f = re.split(r"\.\s+", line.strip())
        if len(f) != 11 or not THRUST_DESIGNATION.fullmatch(f[-1]):
            continue
        d = num(f[0]) if f[0] else d
        out.append((i + 1, i + 1, f[-1], d, num(f[1]), num(f[2]), num(f[7]), num(f[8])))
    return out


def extract_thrust(md_2018: Path, md_2006: Path) -> None:
    """Write the two SKF editions' thrust ball bearing rows (511, 512, 513 of d <= 100 mm; the line or lines of
    the transcription each came from) to validation/data/maker_speeds_skf_thrust.csv."""
    out = [THRUST_COLUMNS]
    for edition, path, parse in (("skf2018", md_2018, _thrust_2018), ("skf2006", md_2006, _thrust_2006)):
        lines = Path(path).read_text(encoding="utf-8").split("\n")
        file, commit = THRUST_FILES[edition]
        for first, last, des, d, D, H, ref, lim in parse(lines):
            if d <= THRUST_MAX_BORE_MM:
                out.append([edition, file, commit, str(first) if first == last else f"{first}-{last}", des,
                            f"{d:g}", f"{D:g}", f"{H:g}", f"{ref:.0f}", f"{lim:.0f}"])
    with open(THRUST_ROWS, "w", newline="", encoding="utf-8") as f:
        f.write(f"# {SOURCES['skf2018']}; {SOURCES['skf2006']}; extracted by validation/maker_speeds.py "
                "--extract-thrust\n")
        csv.writer(f, lineterminator="\n").writerows(out)


def _read(path: Path) -> list:
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def _split(designation: str):
    """(catalogue name, variant) of a source designation, or None: ``6208-2RSH`` -> ("6208", "2RSH");
    ``7205 BECBP`` -> ("7205B", "open"); other suffixes (M, MA, ETN9: other cages and designs) -> None."""
    m = re.fullmatch(r"(\d{4,5})(-2Z|-2RZ|-2RSL|-2RSH|-2RS1)?", designation)
    if m:
        return m.group(1), VARIANTS[m.group(2) or ""]
    m = re.fullmatch(r"(7[23]\d\d) BE\w*", designation)
    return (m.group(1) + "B", "open") if m else None


def _rows_by_key(rows: list, source: str, catalogue: dict, notes: list) -> dict:
    """(name, variant) -> the source's row for each catalogue designation whose dimensions agree."""
    out: dict = {}
    for r in rows:
        key = _split(r["designation"])
        if key is None or key[0] not in catalogue:
            continue
        key = (catalogue[key[0]][1], key[1])                   # an alias (7210B) -> its entry (7210)
        line = r["source_line"]
        where = (f"{source} {Path(r.get('file', 'deep_groove_ball.csv')).name} line{'s' if '-' in line else ''} "
                 f"{line}")
        width = "H" if "H_mm" in r else "B"                    # a thrust bearing's height
        dims = tuple(float(r[k]) for k in ("d_mm", "D_mm", f"{width}_mm"))
        if dims != catalogue[key[0]][0]:
            notes.append(f"{r['designation']} ({where}): d x D x {width} {dims} differs from the catalogue's "
                         f"{catalogue[key[0]][0]}; not used")
            continue
        row = {"designation": r["designation"], "reference_rpm": _number(r["n_ref_rpm"]),
               "limiting_rpm": _number(r["n_limit_rpm"]), "source": where}
        if key in out:
            first = out[key]
            same = (first["reference_rpm"], first["limiting_rpm"]) == (row["reference_rpm"], row["limiting_rpm"])
            first.setdefault("duplicates", []).append((where, same))
            continue
        out[key] = row
    return out


def merge(catalogue: dict) -> tuple[dict, list]:
    """The data file's entries ((name, variant) -> entry) and the notes of the cross-check."""
    notes: list = []
    jr = _rows_by_key(_read(JR_ROWS), "jraposo", catalogue, notes)
    bd = _rows_by_key(_read(BDW_ROWS), "bd_warehouse", catalogue, notes)
    new, old = (_rows_by_key(_thrust_rows(ed), ed, catalogue, notes) for ed in THRUST[:2])
    pairs = [(key, jr.get(key), bd.get(key), RADIAL) for key in set(jr) | set(bd)]
    pairs += [(key, new.get(key), old.get(key), THRUST) for key in set(new) | set(old)]
    out = {}
    for key, a, b, how in sorted(pairs, key=lambda p: p[0]):
        entry = _combine(key, a, b, how, notes)
        if entry is None:
            continue
        if b and b["designation"] != key[0] and key[0].endswith("B") and key[1] == "open":
            entry["note"] = (f"SKF's {b['designation']}, the 40° B design in the one cage the source lists; the "
                             "source's reference and limiting speeds are equal in all its angular contact rows")
        out[key] = entry
    order = {n: i for i, n in enumerate(bearing_names())}
    return dict(sorted(out.items(), key=lambda kv: (order.get(kv[0][0], -1), list(VARIANTS.values()).index(kv[0][1])))), \
        notes + overlap_notes()


def _combine(key: tuple, a, b, how: tuple, notes: list):
    """One entry from the rows of two sources (``how``: their names and the one taken where they differ): the
    first source's row where it has one, the other's in ``cross_check``; None (named in ``notes``) where a source
    has duplicate rows of it with different values."""
    entry = dict(a or b)
    dups = entry.pop("duplicates", [])
    if any(not same for _, same in dups):
        notes.append(f"{key}: duplicate rows with different values ({dups}); not used")
        return None
    if dups:
        entry["note"] = "duplicate rows with the same values: " + ", ".join(w for w, _ in dups)
    if a and b:
        va, vb = (a["reference_rpm"], a["limiting_rpm"]), (b["reference_rpm"], b["limiting_rpm"])
        if va == vb:
            entry["cross_check"] = f"equal in {b['source']} ({b['designation']})"
        else:
            entry["cross_check"] = (f"{b['source']} ({b['designation']}) gives reference {vb[0]}, limiting "
                                    f"{vb[1]} rpm; {how[2]}")
            notes.append(f"{key}: {how[0]} {va} against {how[1]} {vb}")
    return entry


def _thrust_rows(edition: str) -> list:
    """One edition's rows of validation/data/maker_speeds_skf_thrust.csv."""
    return [r for r in _read(THRUST_ROWS) if r["edition"] == edition]


def overlap_notes() -> list:
    """The two sources compared on every designation both list (all sizes, not only the catalogue's): the radial
    transcriptions, and the thrust editions."""
    return [_overlap(_read(JR_ROWS), _read(BDW_ROWS), "B", "the sources compared on the {} designations both list "
                     "(any size)", "jraposo / bd_warehouse"),
            _overlap(_thrust_rows("skf2018"), _thrust_rows("skf2006"), "H", "the SKF editions compared on the {} "
                     "thrust designations both list (511, 512, 513 of d 10-100 mm)", "2018 / 2006")]


def _overlap(rows_a: list, rows_b: list, width: str, what: str, names: str) -> str:
    a = {r["designation"]: r for r in rows_a}
    keys = ("d_mm", "D_mm", f"{width}_mm", "n_ref_rpm", "n_limit_rpm")
    both, differ = 0, []
    for r in rows_b:
        j = a.get(r["designation"])
        if j is None:
            continue
        both += 1
        diff = [f"{k} {j[k] or '–'} / {r[k] or '–'}" for k in keys if _number(j[k]) != _number(r[k])]
        if diff:
            differ.append(f"{r['designation']}: " + ", ".join(diff))
    return (what.format(both) + f": {both - len(differ)} agree in d, D, {width} and both speeds; differ ({names}): "
            + ("; ".join(differ) or "none"))


def _fmt(v) -> str:
    return f"{v:.1f}" if isinstance(v, float) else f'"{v}"'


def write(entries: dict, notes: list) -> str:
    head = ["# Makers' reference and limiting speeds [rpm] of the catalogue bearings, by designation and variant",
            "# (open; shields 2Z, 2RZ; contact seals 2RSL, 2RSH, 2RS1). Generated by validation/maker_speeds.py — do not",
            "# edit by hand; rerun the script.  Reference speed: SKF's thermal speed rating (ISO 15312 conditions);",
            "# limiting speed: SKF's kinematic limit of the bearing, its cage or its seals (one value, grease or oil:",
            "# the sources do not distinguish).  A capped bearing with contact seals has no reference speed.",
            "# Thrust ball bearings (511, 512, 513; open): SKF's 2018 and 2006 catalogue editions.  ISO 15312 and DIN 732",
            "# exclude thrust ball bearings (ISO 15312 scope: \"Thrust ball bearings are excluded ... as kinematic effects",
            "# do not allow the thermal speed rating to be applied\"): SKF's reference speed of a thrust ball bearing is",
            "# SKF's own rating (SKF 2018, 'Operating temperature and speed', p. 130: the SKF friction model at ISO 15312's reference conditions), not the standard's.",
            "# A bearing or variant not listed has no maker's speed on file (no source lists it).",
            "# Sources:"] + [f"#   {k}: {v}" for k, v in SOURCES.items()]
    head += ["# Cross-check notes:"] + [f"#   {n}" for n in notes] if notes else ["# Cross-check notes: none"]
    body = []
    for (name, variant), e in entries.items():
        body += ["", f'["{name}"."{variant}"]']
        for k in ("designation", "reference_rpm", "limiting_rpm", "source", "cross_check", "note"):
            if e.get(k) is not None:
                body.append(f"{k} = {_fmt(e[k])}")
    return "\n".join(head + body) + "\n"


def build() -> tuple[str, dict, list]:
    """(the data file's text, its entries, the cross-check notes) from validation/data/ and the catalogue."""
    catalogue = {}
    for name in bearing_names():
        t = bearing_table(name)
        if "bore_mm" in t and "outer_diameter_mm" in t and "width_mm" in t:
            catalogue[name] = ((t["bore_mm"], t["outer_diameter_mm"], t["width_mm"]), name)
            for alias in t.get("aliases", ()):
                catalogue[alias] = catalogue[name]
    entries, notes = merge(catalogue)
    return write(entries, notes), entries, notes


def main(argv) -> int:
    if argv[:1] == ["--extract"]:
        extract(Path(argv[1]), Path(argv[2]))
        return 0
    if argv[:1] == ["--extract-thrust"]:
        extract_thrust(Path(argv[1]), Path(argv[2]))
        return 0
    text, entries, notes = build()
    OUT.write_text(text, encoding="utf-8")
    names = {n for n, _ in entries}
    print(f"{OUT.relative_to(ROOT)}: {len(entries)} entries, {len(names)} catalogue designations of "
          f"{len(bearing_names())}")
    for n in notes:
        print("note:", n)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

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

Neither source has thrust ball bearings: the 511, 512, 513 series (51208, the seeds' 51107 and 51205) have
no maker's speed on file.  Neither distinguishes grease from oil: SKF's limiting speed is one value per
bearing (the kinematic limit of the bearing, its cage or its seals), used for either lubrication here.

Rules (what the generator does, and why):

* a catalogue designation matches a source row of the same designation with its d x D x B; a row whose
  dimensions differ from the catalogue's is not used (named in the output: a transcription error of one of
  them);
* angular contact: the catalogue's 40° ``72xxB`` / ``73xxB`` (the seed's 7210 = 7210 B) take SKF's
  ``72xx BE...`` row of the source, whichever cage it lists (BECBP polyamide, BECBM brass, BECBPH PEEK: the
  one the source has; its designation is kept with the value);
* where both sources give a value they are compared: equal -> ``cross_check`` names the other row; unequal ->
  both recorded, the value of the row with the catalogue's dimensions and the newer catalogue transcription
  (jraposo, which lists every variant) is taken and the other kept in ``cross_check`` (none was found);
* duplicate rows of one designation in a source: identical values -> the first row, the duplicates named in
  ``note``; different values -> not used (none was found among the catalogue's designations).

Run:  python validation/maker_speeds.py                 (writes materials/maker_speeds.toml)
      python validation/maker_speeds.py --extract JR_CSV BDW_DATA_DIR   (rewrites validation/data/ from the
      sources' files; the generator then reads those)
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

SOURCES = {
    "jraposo": ("SKF General Catalogue 10000 EN product tables as transcribed in github.com/JRaposo-m/"
                "SKF-Bearing-Selection-Tool skf_model/bearings/data/deep_groove_ball/deep_groove_ball.csv "
                "(commit df9a951, 2026-04-14)"),
    "bd_warehouse": ("SKF product table values as transcribed in github.com/gumyr/bd_warehouse "
                     "src/bd_warehouse/data/ (commit ea24664, 2024-03-27)"),
}
BDW_FILES = ("single_row_deep_groove_ball_bearing_parameters.csv",
             "single_row_capped_deep_groove_ball_bearing_parameters.csv",
             "single_row_angular_contact_ball_bearing_parameters.csv")
#: SKF closure suffix -> variant key of the data file
VARIANTS = {"": "open", "-2Z": "2Z", "-2RZ": "2RZ", "-2RSL": "2RSL", "-2RSH": "2RSH", "-2RS1": "2RS1"}
COLUMNS = ["source_line", "designation", "d_mm", "D_mm", "B_mm", "n_ref_rpm", "n_limit_rpm"]


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
        where = f"{source} {r.get('file', 'deep_groove_ball.csv')} line {r['source_line']}"
        dims = tuple(float(r[k]) for k in ("d_mm", "D_mm", "B_mm"))
        if dims != catalogue[key[0]][0]:
            notes.append(f"{r['designation']} ({where}): d x D x B {dims} differs from the catalogue's "
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
    out = {}
    for key in sorted(set(jr) | set(bd)):
        a, b = jr.get(key), bd.get(key)
        entry = dict(a or b)
        dups = entry.pop("duplicates", [])
        if any(not same for _, same in dups):
            notes.append(f"{key}: duplicate rows with different values ({dups}); not used")
            continue
        if dups:
            entry["note"] = "duplicate rows with the same values: " + ", ".join(w for w, _ in dups)
        if a and b:
            va, vb = (a["reference_rpm"], a["limiting_rpm"]), (b["reference_rpm"], b["limiting_rpm"])
            if va == vb:
                entry["cross_check"] = f"equal in {b['source']} ({b['designation']})"
            else:
                entry["cross_check"] = (f"{b['source']} ({b['designation']}) gives reference {vb[0]}, limiting "
                                        f"{vb[1]} rpm; jraposo's row taken (every variant of the bearing from one "
                                        "transcription)")
                notes.append(f"{key}: jraposo {va} against bd_warehouse {vb}")
        if b and b["designation"] != key[0] and key[0].endswith("B") and key[1] == "open":
            entry["note"] = (f"SKF's {b['designation']}, the 40° B design in the one cage the source lists; the "
                             "source's reference and limiting speeds are equal in all its angular contact rows")
        out[key] = entry
    order = {n: i for i, n in enumerate(bearing_names())}
    return dict(sorted(out.items(), key=lambda kv: (order.get(kv[0][0], -1), list(VARIANTS.values()).index(kv[0][1])))), \
        notes + overlap_notes()


def overlap_notes() -> list:
    """The two sources compared on every designation both list (all sizes, not only the catalogue's)."""
    jr = {r["designation"]: r for r in _read(JR_ROWS)}
    keys = ("d_mm", "D_mm", "B_mm", "n_ref_rpm", "n_limit_rpm")
    both, differ = 0, []
    for r in _read(BDW_ROWS):
        j = jr.get(r["designation"])
        if j is None:
            continue
        both += 1
        diff = [f"{k} {j[k] or '–'} / {r[k] or '–'}" for k in keys if _number(j[k]) != _number(r[k])]
        if diff:
            differ.append(f"{r['designation']}: " + ", ".join(diff))
    return [f"the sources compared on the {both} designations both list (any size): {both - len(differ)} agree in "
            f"d, D, B and both speeds; differ (jraposo / bd_warehouse): " + "; ".join(differ)]


def _fmt(v) -> str:
    return f"{v:.1f}" if isinstance(v, float) else f'"{v}"'


def write(entries: dict, notes: list) -> str:
    head = ["# Makers' reference and limiting speeds [rpm] of the catalogue bearings, by designation and variant",
            "# (open; shields 2Z, 2RZ; contact seals 2RSL, 2RSH, 2RS1). Generated by validation/maker_speeds.py — do not",
            "# edit by hand; rerun the script.  Reference speed: SKF's thermal speed rating (ISO 15312 conditions);",
            "# limiting speed: SKF's kinematic limit of the bearing, its cage or its seals (one value, grease or oil:",
            "# the sources do not distinguish).  A capped bearing with contact seals has no reference speed.",
            "# A bearing or variant not listed has no maker's speed on file (thrust bearings: no source).",
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

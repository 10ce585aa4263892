"""Makers' reference and limiting speeds (thermobear.rating.maker_speeds, materials/maker_speeds.toml): the values
are the source rows, the seals select the variant, a speed above the limiting speed is named on the answer (and
only above it), a bearing without a value has none, and ``thermobear speed`` shows the limit beside the thermal
speeds."""
import csv
import importlib.util
import json
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import thermobear as tb
from thermobear.app.cli import main
from thermobear.contact.geometry import bearing_names
from thermobear.coupled.limits import past_maker_limit, point_warnings
from thermobear.errors import InputError
from thermobear.rating import maker_speeds as ms

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "validation" / "data"


def _source_rows(name: str) -> dict:
    """designation -> (n_ref, n_limit) of a source's extracted rows (validation/data/maker_speeds_<name>.csv)."""
    with open(DATA / f"maker_speeds_{name}.csv", encoding="utf-8") as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        return {r["designation"]: (float(r["n_ref_rpm"]) if r["n_ref_rpm"].strip() not in ("", "\u2013") else None,
                                   float(r["n_limit_rpm"]) if r["n_limit_rpm"].strip() not in ("", "\u2013") else None)
                for r in rows}


@pytest.mark.parametrize("bearing, seals, designation, source", [
    ("6208", "none", "6208", "jraposo"), ("6208", "shield", "6208-2Z", "jraposo"),
    ("6208", "RSH", "6208-2RSH", "jraposo"), ("6305", "none", "6305", "jraposo"),
    ("6204", "RSL", "6204-2RSL", "jraposo"), ("61800", "RS1", "61800-2RS1", "jraposo"),
    ("6210", "none", "6210", "jraposo"), ("7200 B", "none", "7200 BECBP", "bd_warehouse"),
    ("7305B", "none", "7305 BECBPH", "bd_warehouse"),
])
def test_looked_up_values_are_the_source_rows(bearing, seals, designation, source):
    """6208: 18000 / 11000 rpm open, 9000 shielded, 5600 with RSH seals (no reference speed), as the rows."""
    m = ms.maker_speeds(bearing, seals)
    assert m.designation == designation and (m.reference_rpm, m.limiting_rpm) == _source_rows(source)[designation]
    assert m.limiting == pytest.approx(m.limiting_rpm * np.pi / 30.0, rel=1e-15)      # SI inside
    assert source in m.source and not m.note


def test_the_6208_by_hand():
    """The SKF values of the 6208 as the transcription lists them (its lines 297-300)."""
    t = ms.maker_speeds_table()["6208"]
    assert (t["open"]["reference_rpm"], t["open"]["limiting_rpm"]) == (18000.0, 11000.0)
    assert (t["2Z"]["limiting_rpm"], t["2RZ"]["limiting_rpm"], t["2RSH"]["limiting_rpm"]) == (9000.0, 9000.0, 5600.0)
    assert "reference_rpm" not in t["2RSH"]           # SKF gives contact-sealed bearings no reference speed


def test_both_sources_agree_where_both_list_a_catalogue_bearing():
    jr, bd = _source_rows("jraposo"), _source_rows("bd_warehouse")
    both = [d for d in ("6000", "6200", "6300", "61800", "61900") if d in jr and d in bd]
    assert len(both) == 5 and all(jr[d] == bd[d] for d in both)
    assert all("equal in bd_warehouse" in ms.maker_speeds_table()[d]["open"]["cross_check"] for d in both)


def test_seals_select_the_contact_seal_limit():
    """Contact seals run slower than shields, shields slower than the open bearing; an RS1 6208 (listed as 2RSH
    only) takes the lowest contact-sealed row, named; an RSL 6204 its own, higher, row."""
    lim = {s: ms.maker_speeds("6208", s).limiting_rpm for s in ("none", "shield", "RS1", "RSH", "RSL")}
    assert lim["RS1"] == lim["RSH"] == lim["RSL"] == 5600.0 < lim["shield"] == 9000.0 < lim["none"] == 11000.0
    rs1 = ms.maker_speeds("6208", "RS1")
    assert rs1.variant == "2RSH" and "no 2RS1 row on file" in rs1.note
    assert ms.maker_speeds("6204", "RSL").limiting_rpm == 17000.0
    assert ms.maker_speeds("6204", "RS1").limiting_rpm == 10000.0        # the 2RSH row: lower than 2RSL's
    capped = ms.maker_speeds("7200B", "RS1")                             # no capped angular contact row
    assert capped.variant == "open" and "upper bound" in capped.note


@pytest.mark.parametrize("name", ["51205-3ball", "7210", "7205B", "7014C", "iso-dgbb", "16001"])
def test_a_bearing_without_a_sourced_value_has_none(name):
    assert ms.maker_speeds(name) is None and ms.maker_speeds(name, "RS1") is None
    assert ms.limiting_speed_text(name).startswith(f"no maker's limiting speed on file for {name}")


def test_no_warning_without_a_value_on_file():
    s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")).with_(n_rpm=50000.0)
    assert past_maker_limit(s) is None
    assert not [w for w in point_warnings(s, None, [50.0, 50.0, 50.0]) if w.quantity == "maker_limiting_speed"]


def _maker_warnings(ws):
    return [w for w in ws if w.quantity == "maker_limiting_speed"]


def test_steady_state_warns_just_above_the_limit_and_not_below():
    """The 6208-2RS1 block (limit 5600 rpm, the 2RSH row): 5599.9 and 5600 rpm say nothing, 5600.1 rpm is named,
    and the answer itself does not step at the threshold."""
    s = tb.load_scene(tb.example_path("block_6208_grease.toml"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st = tb.steady_states([s.with_(n_rpm=n) for n in (5599.9, 5600.0, 5600.1)])
    assert [len(_maker_warnings(x.warnings)) for x in st] == [0, 0, 1]
    w = _maker_warnings(st[2].warnings)[0]
    assert (w.field, w.value, w.limit) == ("operation.n_rpm", 5600.1, "<= 5600 rpm")
    assert "6208-2RSH" in str(w) and "maker_speeds.toml" in w.source
    assert st[2].P_W == pytest.approx(st[0].P_W, rel=1e-4)


def test_run_sweep_and_heat_up_name_it_too():
    """7000 rpm in the 6208-2RS1 block: run (Python and --json), a sweep row and a heat-up carry the warning."""
    s = tb.load_scene(tb.example_path("block_6208_grease.toml")).with_(n_rpm=7000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        run = tb.solve(s)
        tr = tb.transient(s, 20.0)
        rows = tb.run_sweep(tb.load_scene(tb.example_path("block_6208_grease.toml")), {"n_rpm": [5000.0, 7000.0]})
    assert len(_maker_warnings(run.warnings)) == 1 and len(_maker_warnings(tr.warnings)) == 1
    msgs = [[m for m in r["warnings"] if "maker's limiting speed" in m] for r in rows]
    assert [len(m) for m in msgs] == [0, 1]


def test_cli_run_json_names_it(capsys):
    assert main(["run", tb.example_path("block_6208_grease.toml"), "--set", "n_rpm=7000", "--json"]) == 0
    out = capsys.readouterr()
    d = json.loads(out.out)
    w = [w for w in d["warnings"] if w["quantity"] == "maker_limiting_speed"]
    assert len(w) == 1 and w[0]["value"] == 7000.0 and w[0]["limit"] == "<= 5600 rpm"
    assert "maker's limiting speed 5600 rpm" in out.err


def test_cli_speed_shows_the_limit_and_says_it_governs(capsys):
    """The 6208 oil-jet block: thermally safe 17 714 rpm (model), above SKF's 11 000 rpm limiting speed: the
    thermal number is kept, flagged, and the limiting speed governs."""
    path = tb.example_path("block_6208_oil_jet.toml")
    assert main(["speed", path, "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    m = d["maker"]
    assert (m["limiting_rpm"], m["reference_rpm"], m["designation"]) == (11000.0, 18000.0, "6208")
    assert d["model"]["n_rpm"] > 11000.0 and d["model"]["above_limiting_speed"] is True
    assert (m["governing_rpm"], m["governed_by"]) == (11000.0, "maker's limiting speed")
    assert main(["speed", path]) == 0
    text = capsys.readouterr().out
    assert "maker's limiting speed (6208, kinematic)" in text and "11000 rpm" in text
    assert "maker's reference speed (6208, ISO 15312)" in text and "the limiting speed governs" in text


def test_cli_speed_of_a_sealed_bearing_below_the_limit_and_of_one_without_a_value(capsys):
    assert main(["speed", tb.example_path("block_6208_grease.toml"), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["maker"]["limiting_rpm"] == 5600.0 and d["maker"]["designation"] == "6208-2RSH"
    assert d["model"]["above_limiting_speed"] is False and d["maker"]["governed_by"] == "thermally safe speed (model)"
    assert main(["speed", tb.example_path("seed004_oil_jet_7210.toml")]) == 0
    text = capsys.readouterr().out
    assert "no maker's limiting speed on file for 7210" in text and "governs" not in text
    assert main(["speed", tb.example_path("seed004_oil_jet_7210.toml"), "--json"]) == 0
    m = json.loads(capsys.readouterr().out)["maker"]
    assert m["limiting_rpm"] is None and m["governed_by"].endswith("no maker's limiting speed on file")


@pytest.mark.parametrize("text, field", [
    ('["6208".open]\ndesignation = "6208"\nlimiting_rpm = 11000.0\nsource = "x"\nspeed_rpm = 1.0\n',
     "maker_speeds.toml: 6208.open.speed_rpm"),
    ('["6208".sealed]\ndesignation = "6208"\nlimiting_rpm = 11000.0\nsource = "x"\n', "maker_speeds.toml: 6208.sealed"),
    ('["6208".open]\ndesignation = "6208"\nlimiting_rpm = "fast"\nsource = "x"\n', "maker_speeds.toml: 6208.open.limiting_rpm"),
    ('["6208".open]\ndesignation = "6208"\nsource = "x"\n', "maker_speeds.toml: 6208.open.limiting_rpm"),
])
def test_malformed_entries_are_refused_by_name(tmp_path, monkeypatch, text, field):
    (tmp_path / "maker_speeds.toml").write_text(text, encoding="utf-8")
    monkeypatch.setattr(ms, "data_dir", lambda kind: tmp_path)
    with pytest.raises(InputError) as e:
        ms.maker_speeds("6208")
    assert e.value.field == field


def _generator():
    """validation/maker_speeds.py as a module."""
    path = ROOT / "validation" / "maker_speeds.py"
    sys.path.insert(0, str(path.parent))
    try:
        spec = importlib.util.spec_from_file_location("maker_speeds_script", path)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
    finally:
        sys.path.remove(str(path.parent))
    return mod


def test_data_file_is_what_the_generator_writes_now():
    """materials/maker_speeds.toml is the output of validation/maker_speeds.py on the extracted source rows."""
    text, entries, notes = _generator().build()
    assert (ROOT / "materials" / "maker_speeds.toml").read_text(encoding="utf-8") == text
    names = {n for n, _ in entries}
    assert len(names) == 186 and {"6208", "6305", "6210", "7200B", "7305B"} <= names
    thrust = {n for n in bearing_names() if tb.bearing(n).kind == "thrust"}
    assert {n for n in names if n.startswith("51")} == thrust - {"51205-3ball"}    # every SKF thrust designation
    assert len(thrust) == 56 and {(n, "open") for n in thrust - {"51205-3ball"}} <= set(entries)
    assert [n for n in notes if n.startswith("('51307'")] == [
        "('51307', 'open'): skf2018 (3400.0, 4800.0) against skf2006 (3200.0, 4500.0)"]


# -- thrust ball bearings: SKF's 2018 and 2006 catalogue editions (validation/data/maker_speeds_skf_thrust.csv)

def _thrust_rows() -> dict:
    """(edition, designation) -> the row of validation/data/maker_speeds_skf_thrust.csv."""
    with open(DATA / "maker_speeds_skf_thrust.csv", encoding="utf-8") as f:
        return {(r["edition"], r["designation"]): r
                for r in csv.DictReader(line for line in f if not line.startswith("#"))}


@pytest.mark.parametrize("name, dims, ref, lim, lines_2018, line_2006", [
    # SKF Rolling bearings 17000/1 EN (2018) table 5.1 and SKF General Catalogue (RU, 2006 data): both the same
    ("51208", ("40", "68", "19"), 3800.0, 5300.0, "94953-94962", "44053"),
    ("51107", ("35", "52", "12"), 5600.0, 7500.0, "94592-94602", "44047"),
    ("51205", ("25", "47", "15"), 5300.0, 7500.0, "94514-94523", "43958"),
    ("51200", ("10", "26", "11"), 8000.0, 11000.0, "94399-94408", "43943"),
    ("51210", ("50", "78", "22"), 3400.0, 4500.0, "95043-95052", "44063"),
])
def test_thrust_rows_are_skfs_published_values(name, dims, ref, lim, lines_2018, line_2006):
    """The published d x D x H and reference / limiting speeds, the transcriptions' lines of each edition, and the
    data file's entry (the 2018 edition's, the 2006 one equal in cross_check) as looked up."""
    rows = _thrust_rows()
    for edition, lines in (("skf2018", lines_2018), ("skf2006", line_2006)):
        r = rows[(edition, name)]
        assert (r["d_mm"], r["D_mm"], r["H_mm"], float(r["n_ref_rpm"]), float(r["n_limit_rpm"])) == dims + (ref, lim)
        assert r["source_line"] == lines
    assert rows[("skf2018", name)]["commit"] == "68b9707fc46f43fa4d0c070323c23237becbce8b"
    assert rows[("skf2006", name)]["commit"] == "b623d8e17ca13788f4f01e3469621a974a5a9bd8"
    m = ms.maker_speeds(name)
    assert (m.designation, m.variant, m.reference_rpm, m.limiting_rpm) == (name, "open", ref, lim)
    assert m.source == f"skf2018 Rolling_bearings_1.md lines {lines_2018}"
    entry = ms.maker_speeds_table()[name]["open"]
    assert entry["cross_check"] == f"equal in skf2006 Общий_каталог_подшипников_SKF.md line {line_2006} ({name})"


def test_the_editions_disagree_on_the_51307_only_and_the_newer_is_taken():
    """51307: 3400 / 4800 rpm in 2018, 3200 / 4500 rpm in 2006 — the 2018 row taken, the 2006 one named."""
    rows = _thrust_rows()
    both = {d for e, d in rows if e == "skf2018"} & {d for e, d in rows if e == "skf2006"}
    keys = ("d_mm", "D_mm", "H_mm", "n_ref_rpm", "n_limit_rpm")
    differ = {d for d in both if any(rows[("skf2018", d)][k] != rows[("skf2006", d)][k] for k in keys)}
    assert len(both) == 55 and differ == {"51307"}
    m = ms.maker_speeds("51307")
    assert (m.reference_rpm, m.limiting_rpm) == (3400.0, 4800.0)
    cc = ms.maker_speeds_table()["51307"]["open"]["cross_check"]
    assert "gives reference 3200.0, limiting 4500.0 rpm" in cc and "2018 edition's row taken" in cc


def test_the_thrust_extraction_reads_both_layouts():
    """The transcriptions' layouts, as they print the 51107 / 51207 rows: 2018 one value a line (d left out where it
    repeats, "7 500" with a space), 2006 a row a line ("." for a repeated d, "7.500" with a dot)."""
    gen = _generator()
    lines_2018 = ["", "35", "52", "12", "19,9", "51", "1,86", "0,013", "5 600", "7 500", "0,08", "▶51107", "",
                  "62", "18", "35,1", "73,5", "2,7", "0,028", "4 000", "5 600", "0,22", "▶51207"]
    assert gen._thrust_2018(lines_2018) == [(2, 12, "51107", 35.0, 52.0, 12.0, 5600.0, 7500.0),
                                            (14, 23, "51207", 35.0, 62.0, 18.0, 4000.0, 5600.0)]
    lines_2006 = ["35. \t52. \t12. \t19,9. \t51. \t1,86. \t0,013. \t5.600. \t7.500. \t0,080. \t51107",
                  ". \t62. \t18. \t35,1. \t73,5. \t2,7. \t0,028. \t4.000. \t5.600. \t0,22. \t51207"]
    assert gen._thrust_2006(lines_2006) == [(1, 1, "51107", 35.0, 52.0, 12.0, 5600.0, 7500.0),
                                            (2, 2, "51207", 35.0, 62.0, 18.0, 4000.0, 5600.0)]


def test_a_thrust_scene_past_its_limiting_speed_is_named():
    """Seed 002's 51107 (SKF: 7500 rpm): 7500 rpm says nothing, 7500.1 rpm is named on the steady state."""
    s = tb.load_scene(tb.example_path("seed002_grease_thrust_51107.toml"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st = tb.steady_states([s.with_(n_rpm=n) for n in (7500.0, 7500.1)])
    assert [len(_maker_warnings(x.warnings)) for x in st] == [0, 1]
    w = _maker_warnings(st[1].warnings)[0]
    assert (w.field, w.value, w.limit) == ("operation.n_rpm", 7500.1, "<= 7500 rpm")
    assert "51107" in str(w) and "skf2018" in w.source


def test_cli_run_names_it_for_an_init_made_thrust_scene(tmp_path, capsys):
    """`thermobear init 51208 --lubrication grease`, run at 6000 rpm: above SKF's 5300 rpm, named."""
    path = tmp_path / "x.toml"
    assert main(["init", "51208", "--lubrication", "grease", "--out", str(path)]) == 0
    capsys.readouterr()
    assert main(["run", str(path), "--set", "n_rpm=6000", "--json"]) == 0
    out = capsys.readouterr()
    w = [w for w in json.loads(out.out)["warnings"] if w["quantity"] == "maker_limiting_speed"]
    assert len(w) == 1 and (w[0]["value"], w[0]["limit"]) == (6000.0, "<= 5300 rpm")
    assert "maker's limiting speed 5300 rpm of the 51208" in out.err


def test_cli_speed_of_a_thrust_bearing_says_iso_15312_excludes_it(capsys):
    """Seed 002's 51107: the ISO 15312 row and SKF's reference speed say that ISO 15312 excludes thrust ball
    bearings; the limiting speed 7500 rpm is above the model's thermally safe speed, which governs."""
    path = tb.example_path("seed002_grease_thrust_51107.toml")
    assert main(["speed", path, "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    m = d["maker"]
    assert (m["limiting_rpm"], m["reference_rpm"], m["designation"]) == (7500.0, 5600.0, "51107")
    assert "ISO 15312 excludes thrust ball bearings" in m["reference_basis"]
    assert d["model"]["above_limiting_speed"] is False and m["governed_by"] == "thermally safe speed (model)"
    assert main(["speed", path]) == 0
    text = capsys.readouterr().out
    iso = next(line for line in text.splitlines() if "ISO 15312 thermal reference speed" in line)
    assert iso.endswith("ISO 15312 excludes thrust ball bearings: a model comparison")
    ref = next(line for line in text.splitlines() if "maker's reference speed" in line)
    assert "(51107, SKF)" in ref and "5600 rpm" in ref and "ISO 15312 excludes thrust ball bearings" in ref


def test_readme_counts_the_bearings_with_makers_speeds():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    row = next(line for line in readme.splitlines() if line.startswith("| makers' speeds |"))
    assert f"of {len(ms.maker_speeds_table())} catalogue bearings" in row

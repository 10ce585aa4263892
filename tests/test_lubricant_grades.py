"""ISO VG mineral and PAO oil grades and generic greases (materials/lubricants/iso-vg-*, grease-*),
written by validation/lubricant_grades.py: the files load, reproduce their grade and viscosity index
(ASTM D2270), their viscosity falls with temperature and α_p is physical."""
import importlib.util
from pathlib import Path

import numpy as np
import pytest

import thermobear as tb
from thermobear.lubrication.viscosity_index import viscosity_index

SCRIPT = Path(__file__).resolve().parents[1] / "validation" / "lubricant_grades.py"


@pytest.fixture(scope="module")
def gen():
    spec = importlib.util.spec_from_file_location("lubricant_grades_script", SCRIPT)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


GRADES = (10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460)
OILS = [f"iso-vg-{g}-{f}" for f in ("mineral", "pao") for g in GRADES]
GREASES = ["grease-lithium-mineral-vg100-nlgi2", "grease-lithium-complex-mineral-vg150-nlgi2",
           "grease-polyurea-mineral-vg100-nlgi2", "grease-lithium-pao-vg22-nlgi2"]


def test_d2270_inversion_reproduces_the_projects_earlier_estimates(gen):
    """materials/lubricants: mol-liton-00 (nu40 40 -> nu100 6.185 at VI 100), seed001-oil-a (46.5 -> 6.81),
    seed001-oil-b (30.7 -> 5.23): the same route gives the same numbers."""
    assert gen.nu100_from_vi(40.0, 100.0) == pytest.approx(6.185, abs=0.002)
    assert gen.nu100_from_vi(tb.lubricant("seed001-oil-a").nu40_cSt, 100.0) == pytest.approx(6.81, abs=0.01)
    assert gen.nu100_from_vi(tb.lubricant("seed001-oil-b").nu40_cSt, 100.0) == pytest.approx(5.23, abs=0.01)


@pytest.mark.parametrize("name", OILS + GREASES)
def test_grade_files_load_and_reproduce_grade_and_vi(name, gen):
    lub = tb.lubricant(name)
    grade = int(name.split("vg-")[-1].split("-")[0]) if name.startswith("iso") else int(name.split("-vg")[1].split("-")[0])
    family = "pao" if "pao" in name else "mineral"
    assert lub.nu(40.0) == pytest.approx(grade, rel=1e-9)
    assert viscosity_index(lub.nu40_cSt, lub.nu100_cSt) == pytest.approx(gen.VI[family], abs=0.2)   # nu100 stored to 0.001
    assert lub.kind == ("grease" if name.startswith("grease") else "oil")
    T = np.linspace(-10.0, 140.0, 31)
    nu = lub.nu(T)
    assert np.all(np.diff(nu) < 0) and np.all(np.diff(lub.eta(T)) < 0)      # thinner when hotter
    a40 = lub.alpha_p_at(40.0)
    assert 5e-9 < a40 < 35e-9                                                 # 5-35 1/GPa: oils at 40 °C
    assert lub.alpha_p_at(100.0) < a40                                        # Gold: falls with viscosity
    assert 800.0 < lub.rho(15.0) < 950.0 and 0.1 < lub.k_th(40.0) < 0.2 and 1700 < lub.cp(40.0) < 2400


def test_grades_are_ordered_and_pao_thins_less_with_temperature():
    for fam in ("mineral", "pao"):
        nu100 = [tb.lubricant(f"iso-vg-{g}-{fam}").nu(100.0) for g in GRADES]
        assert np.all(np.diff(nu100) > 0)
    for g in GRADES:
        m, p = tb.lubricant(f"iso-vg-{g}-mineral"), tb.lubricant(f"iso-vg-{g}-pao")
        assert p.nu(100.0) > m.nu(100.0) and p.nu(0.0) < m.nu(0.0)            # higher VI: flatter curve
        assert p.alpha_p_at(40.0) < m.alpha_p_at(40.0)                         # Gold: PAO lower than mineral


def test_files_are_what_the_script_writes(gen, tmp_path, monkeypatch):
    """materials/lubricants/iso-vg-* and grease-* are the current output of validation/lubricant_grades.py."""
    monkeypatch.setattr(gen, "OUT", tmp_path)
    gen.main()
    here = SCRIPT.parents[1] / "materials" / "lubricants"
    for f in tmp_path.glob("*.toml"):
        assert f.read_text(encoding="utf-8") == (here / f.name).read_text(encoding="utf-8"), f.name
    assert len(list(tmp_path.glob("*.toml"))) == len(OILS) + len(GREASES)

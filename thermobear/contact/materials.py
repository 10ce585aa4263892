"""Solid materials of rings and balls, and the reduced (contact) modulus.

Data live in ``materials/solids/*.toml`` (one file per material, each value
with its unit in the key and its source in a comment; the keys of :data:`FIELDS`, estimated values
listed in ``estimated`` with their range in ``uncertainty``, :func:`thermobear.schema.check_uncertainty`).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from thermobear.files import data_dir, lookup, names_in
from thermobear.errors import InputError
from thermobear.schema import Field, check_table, check_uncertainty

__all__ = ["Material", "material", "material_names", "reduced_modulus", "FIELDS", "PROPERTIES"]

#: The keys of a material file, with their kinds and units.
FIELDS = {
    "name": Field.text("label"), "description": Field.text(), "source": Field.text(),
    "E_Pa": Field.number("Pa", 0.0, None, lo_open=True, doc="Young's modulus", required=True),
    "nu": Field.number("-", -1.0, 0.5, lo_open=True, hi_open=True, doc="Poisson's ratio", required=True),
    "rho_kg_m3": Field.number("kg/m^3", 0.0, None, lo_open=True, doc="density", required=True),
    "k_W_mK": Field.number("W/(m K)", 0.0, None, lo_open=True, doc="thermal conductivity"),
    "cp_J_kgK": Field.number("J/(kg K)", 0.0, None, lo_open=True, doc="specific heat"),
    "alpha_th_1_K": Field.number("1/K", 0.0, None, doc="thermal expansion coefficient"),
    "estimated": Field.names("keys whose values are estimates"),
    "uncertainty": Field.table("ranges of estimated values (thermobear.schema.check_uncertainty)"),
}
#: File key → :class:`Material` attribute of the properties a thermal network reads.
PROPERTIES = {"k_W_mK": "k", "cp_J_kgK": "cp", "rho_kg_m3": "rho"}


@dataclass(frozen=True)
class Material:
    """An isotropic elastic solid.

    Parameters
    ----------
    E : float       Young's modulus [Pa]
    nu : float      Poisson's ratio [-]
    rho : float     density [kg/m^3]
    k : float       thermal conductivity [W/(m K)] (optional; needed by thermal networks)
    cp : float      specific heat [J/(kg K)] (optional; needed by transients)
    name : str      label
    uncertainty : dict  file key → :class:`~thermobear.schema.Uncertainty` of its estimated values

    >>> steel = Material(E=2.1e11, nu=0.3, rho=7850.0)
    >>> round(reduced_modulus(steel, steel) / 1e9, 1)
    230.8
    """

    E: float
    nu: float
    rho: float = 7830.0
    k: float | None = None
    cp: float | None = None
    name: str = "custom"
    uncertainty: dict = field(default_factory=dict, compare=False, hash=False, repr=False)

    def __post_init__(self):
        if not (np.isfinite(self.E) and self.E > 0):
            raise InputError(f"material[{self.name}].E", self.E, "Young's modulus must be > 0 [Pa]")
        if not (-1.0 < self.nu < 0.5):
            raise InputError(f"material[{self.name}].nu", self.nu, "Poisson's ratio must lie in (-1, 0.5)")
        if not (np.isfinite(self.rho) and self.rho > 0):
            raise InputError(f"material[{self.name}].rho", self.rho, "density must be > 0 [kg/m^3]")
        for fld in ("k", "cp"):
            v = getattr(self, fld)
            if v is not None and not (np.isfinite(v) and v > 0):
                raise InputError(f"material[{self.name}].{fld}", v, "must be > 0")


def material_names() -> list[str]:
    """Names of the bundled materials (the folder listed on each call, ≈ 30 µs).

    >>> "aisi-52100" in material_names()
    True
    """
    return names_in(data_dir("materials") / "solids")


def material(name: str) -> Material:
    """Bundled material by name (``aisi-52100``, ``m50``, ``si3n4``), built from its file as
    :func:`thermobear.files.read_toml` reads it (a changed file is read again).

    >>> material("aisi-52100").E
    210000000000.0
    """
    if isinstance(name, Material):
        return name
    name = str(name)
    d = lookup("materials", "solids", name, "material")
    where = f"materials/solids/{name}.toml"
    t = check_table(d, FIELDS, where)
    unc = check_uncertainty(t.get("uncertainty", {}), {k: FIELDS[k] for k in t if FIELDS[k].kind == "number"}, where)
    return Material(E=t["E_Pa"], nu=t["nu"], rho=t["rho_kg_m3"], k=t.get("k_W_mK"), cp=t.get("cp_J_kgK"),
                    name=t.get("name", name), uncertainty=unc)


def reduced_modulus(m1: Material, m2: Material) -> float:
    r"""Reduced (contact) modulus E' of two bodies [Pa].

    Notes
    -----
    2/E' = (1-ν1²)/E1 + (1-ν2²)/E2  (Hamrock & Dowson 1981; seed 004 nomenclature;
    the seeds' E* in 000/001 is this E').  Steel on steel (210 GPa, 0.3): 230.8 GPa.

    >>> s = Material(E=210e9, nu=0.3)
    >>> round(reduced_modulus(s, s) / 1e9, 3)
    230.769
    """
    return 2.0 / ((1.0 - m1.nu**2) / m1.E + (1.0 - m2.nu**2) / m2.E)

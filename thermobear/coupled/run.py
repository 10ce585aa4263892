"""``thermobear run``: a scene with the least model it needs, and what it reports."""
from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from thermobear.coupled.blend import blend_losses
from thermobear.coupled.limits import emit, point_warnings
from thermobear.coupled.sources import scene_losses
from thermobear.coupled.steady import SteadyState, steady_state
from thermobear.errors import OutsideValidity
from thermobear.models import plan_many
from thermobear.scene import Scene

__all__ = ["RunResult", "solve"]


@dataclass
class RunResult:
    """What ``thermobear run`` reports.

    Attributes
    ----------
    scene : Scene
    P_W : float                power loss [W]
    torque_Nm : float          friction torque on the rotating ring [N m]
    breakdown_W : dict         loss family → W
    T_C : dict                 node → °C (prescribed: the contacts' temperature)
    models_used : dict         model → (choice, reason)
    losses : LossResult        the loss result (per contact)
    steady : SteadyState       the coupled solution (None when the temperature is prescribed)
    warnings : list            OutsideValidity warnings of the answer
    """

    scene: Scene
    P_W: float
    torque_Nm: float
    breakdown_W: dict
    T_C: dict
    models_used: dict
    losses: object
    steady: SteadyState | None = None
    warnings: list = None

    def as_dict(self) -> dict:
        r = self.losses
        d = {"scene": self.scene.name, "bearing": self.scene.bearing.name, "n_rpm": self.scene.n_rpm,
             "Fa_N": self.scene.Fa, "Fr_N": self.scene.Fr, "T_C": self.T_C, "P_W": self.P_W,
             "torque_Nm": self.torque_Nm, "breakdown_W": self.breakdown_W,
             "models_used": {k: {"choice": v[0], "reason": v[1]} for k, v in self.models_used.items()},
             "warnings": [w.as_dict() for w in self.warnings or []]}
        if getattr(r, "contacts", None):
            d["balls"] = {"Q_inner_N": r.contacts["inner"]["Q"], "Q_outer_N": r.contacts["outer"]["Q"],
                          "alpha_deg": np.rad2deg(r.contacts["inner"]["alpha"]),
                          "regime_inner": r.contacts["inner"]["regime"], "regime_outer": r.contacts["outer"]["regime"]}
        if self.steady is not None:
            d["solver"] = {"iterations": self.steady.iterations, "residual_K": self.steady.residual_K,
                           "energy_balance_W": self.steady.energy_balance_W}
            d["heat_flows_W"] = self.steady.heat_flows_W
        return d

    def summary(self) -> str:
        s = self.scene
        lines = [f"thermobear — {s.name}: {s.bearing.name}, {s.n_rpm:g} rpm, Fa {s.Fa:g} N, Fr {s.Fr:g} N, "
                 f"{s.lubricant.name} ({s.supply})", "", "Temperatures [°C]"]
        for k, v in self.T_C.items():
            lines.append(f"  {k:18s} {v:8.2f}" + ("   imposed (thermal.fixed_C)" if k in s.T_fixed_C else ""))
        lines += ["", f"Power loss {self.P_W:.3f} W   (friction torque {self.torque_Nm * 1e3:.2f} N mm)"]
        for k, v in self.breakdown_W.items():
            share = 100 * v / self.P_W if self.P_W > 0 else 0.0
            lines.append(f"  {k:12s} {v:10.4f} W  {share:5.1f} %")
        lines += ["", "Models used"]
        for k, v in self.models_used.items():
            if k == "node_roles":
                continue
            lines.append(f"  {k:18s} {str(v[0]):40s} {v[1]}")
        if self.steady is not None:
            lines += ["", f"Fixed point: {self.steady.iterations} iterations, residual {self.steady.residual_K:.1e} K, "
                          f"energy balance {self.steady.energy_balance_W:.1e} W"]
        return "\n".join(lines)


def solve(scene: Scene) -> RunResult:
    """Run a scene with the least model it needs (a thermal network only when the temperature is not
    prescribed).

    >>> import thermobear as tb
    >>> r = solve(tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")))
    >>> r.P_W > 0, r.steady.iterations < 10
    (True, True)
    """
    if scene.T_C is not None:
        alts = plan_many([scene])[0]
        if isinstance(alts, Exception):
            raise alts
        with warnings.catch_warnings():        # the answer's validity: point_warnings below
            warnings.simplefilter("ignore", OutsideValidity)
            # the model choice's dry loads are the loads (solved once); across a switch, the blend
            r = blend_losses([(a.weight, scene_losses(scene, models=a.models, dry=None if a.dry is None else a.dry.load()))
                              for a in alts])
        T = float(scene.T_C)
        ws = point_warnings(scene, r, [T, T, T])
        emit(ws)
        return RunResult(scene=scene, P_W=float(r.P_W), torque_Nm=float(r.torque_Nm),
                         breakdown_W={k: float(v) for k, v in r.breakdown_W.items()},
                         T_C={"contacts (prescribed)": T}, models_used=r.models_used, losses=r,
                         warnings=ws)
    st = steady_state(scene)
    return RunResult(scene=scene, P_W=st.P_W, torque_Nm=st.torque_Nm, breakdown_W=dict(st.breakdown_W), T_C=st.T_C,
                     models_used=st.models_used, losses=st.losses, steady=st, warnings=st.warnings)

r"""Calibration: fit uncertain parameters of a scene to a rig log (:mod:`thermobear.app.rig`).

:func:`calibrate` fits named parameters by :func:`scipy.optimize.least_squares`
and reports each with its standard uncertainty from the Jacobian, covariance =
s² (JᵀJ)⁻¹ with s² = Σ r²/(m − p) (m residuals, p parameters; Bates & Watts
1988, §2.3).  Residuals are weighted so that 1 unit ≈ 1 K for a temperature
channel and 1 % of the mean measured torque for the torque channel.  The log is
simulated as :func:`thermobear.app.rig.simulate_log` does (logged boundaries
included).

References
----------
.. [1] Bates, D. M., Watts, D. G., 1988, *Nonlinear Regression Analysis and Its
   Applications*, Wiley, §2.3.
"""
from __future__ import annotations

import dataclasses
import warnings
import math
from dataclasses import dataclass, field

import numpy as np

from thermobear.app.rig import Comparison, RigLog, compare, simulate_log, special_target
from thermobear.coupled.uncertainty import uncertain_inputs
from thermobear.errors import InputError, NoConvergence, OutsideValidity
from thermobear.lazy import lazy_module
from thermobear.losses.skf import skf_constants
from thermobear.model_inputs import unread_inputs
from thermobear.models import replenishment_constant
from thermobear.scene import Scene
from thermobear.scene.scene import FILE_KEYS, SECTIONS
from thermobear.scene.network import network_spec
from thermobear.thermal.builders import Machine, build_network, estimates

optimize = lazy_module("scipy.optimize")    # least_squares: loaded by its first use

__all__ = ["calibrate", "Calibration", "parameter_names"]

_SCENE_SCALARS = ("T_ambient_C", "T_oil_in_C", "oil_flow_L_h", "mu_boundary", "mu_full_film", "K_rs")
_SKF = ("skf_R1", "skf_S1", "skf_mu_EHL")
#: a scene scalar's address in the scene file (``unread_inputs`` names them so)
_ADDRESS = {k: a for a, k in FILE_KEYS.items() if k in _SCENE_SCALARS}
_BUILDER = "builder."


def _network_numeric_parameters(scene: Scene) -> dict:
    """``"<element or node>.<parameter>"`` → numeric value, for every number in the scene's network."""
    if not scene.network:
        return {}
    spec = network_spec(scene.network, scene.path, parameters=scene.network_parameters, fixed_C=scene.T_fixed_C)
    out = {}
    tables = [(e.get("name"), e) for e in spec.get("elements", [])] + list(spec.get("nodes", {}).items())
    for name, tbl in tables:
        if not name or not isinstance(tbl, dict):
            continue
        for k, v in tbl.items():
            if isinstance(v, (int, float)) and not isinstance(v, bool):
                out[f"{name}.{k}"] = float(v)
    return out


def _builder_keys(scene: Scene) -> list:
    """``builder.<key>`` of the estimates a network built from the scene's machine reads (none for a network file)."""
    if not isinstance(scene.network, Machine):
        return []
    return [_BUILDER + k for k in estimates.sampled_keys(scene.network)]


def parameter_names(scene: Scene) -> list:
    """Parameters :func:`calibrate` can fit for this scene.

    For a network built from the scene's ``[shaft]`` / ``[housing]``, first the builders' estimates it reads
    (``builder.R_mount_m2K_W``, ``builder.emissivity``, ``builder.k_air_still_W_mK``, …: the machine's own
    unknowns, ``materials/network_builders.toml``, the network built again with the value); then network
    parameters (``[thermal.parameters]`` keys and every numeric ``<element or node>.<parameter>`` of the
    network), the scene scalars T_ambient_C, T_oil_in_C, oil_flow_L_h, and mu_boundary, mu_full_film, K_rs (the
    starvation factor's replenishment constant, started at SKF's) where the scene's models read them
    (:func:`~thermobear.model_inputs.unread_inputs`: not mu_full_film under the Eyring traction, neither on the SKF model;
    not K_rs without starvation), and — for scenes on the SKF global model (``[models] losses = "skf"``) — skf_R1,
    skf_S1, skf_mu_EHL.
    """
    names = _builder_keys(scene) + list(scene.network_parameters)
    names += [k for k in _network_numeric_parameters(scene) if k not in names]
    unread = unread_inputs(scene)
    names += [k for k in _SCENE_SCALARS if _ADDRESS[k] not in unread]
    if scene.models.get("losses") == "skf":
        names += list(_SKF)
    return names


def _parse_param(scene: Scene, spec: str):
    name, _, start = spec.partition("=")
    name = name.strip()
    if name in _SKF and scene.models.get("losses") != "skf":
        raise InputError("--param", name, 'SKF constants need a scene on the SKF model: [models] losses = "skf"')
    why = unread_inputs(scene).get(_ADDRESS[name]) if name in _SCENE_SCALARS else None
    if why:
        raise InputError("--param", name, f"the scene's models do not read it, so the log cannot fit it: {why}")
    known = parameter_names(scene)
    if name not in known:
        raise InputError("--param", name, f"unknown parameter; this scene offers: {', '.join(known)}")
    if start.strip():
        try:
            x0 = float(start)
        except ValueError:
            raise InputError(f"--param {name}", start, "start value must be a number") from None
    elif name.startswith(_BUILDER):
        x0 = estimates.machine_value(scene.network, name[len(_BUILDER):])
    elif name in scene.network_parameters:
        x0 = scene.network_parameters[name]
    elif "." in name:
        x0 = _network_numeric_parameters(scene)[name]
    elif name in _SKF:
        x0 = scene.models.get(name)
        if x0 is None:
            x0 = 0.05 if name == "skf_mu_EHL" else _skf_table(scene)[name.split("_")[1]]
    elif name == "oil_flow_L_h":
        x0 = scene.oil_flow * 3.6e6
    elif name == "K_rs":
        x0 = replenishment_constant(scene)
    else:
        x0 = getattr(scene, name)
    if x0 is None or isinstance(x0, bool) or not isinstance(x0, (int, float)) or not math.isfinite(x0):
        raise InputError(f"--param {name}", x0, "needs a finite numeric start value (give NAME=START)")
    if x0 == 0.0 and name in _ADDRESS and name != "K_rs":  # a start of 0 of a quantity that cannot go negative
        sec, key = _ADDRESS[name].split(".", 1)
        fld = SECTIONS[sec][key]
        if fld.lo is not None and fld.lo >= 0.0:
            raise InputError(f"--param {name}", x0, f"a start of 0 cannot be fitted: {name} stays >= {fld.lo:g}, "
                             "so it is fitted as a positive value in logarithms; give NAME=START > 0")
    hi = SECTIONS["lubricant"]["K_rs"].hi               # the scene file's bound, one place
    if name == "K_rs" and not 0.0 < x0 < hi:
        raise InputError(f"--param {name}", x0, f"start must lie in (0, {hi:g}): K_rs is fitted in logarithms (0 is no "
                         f"starvation: start at e.g. 1e-9), and the fit's steps need room below the scene's bound {hi:g}")
    return name, float(x0)


def _skf_table(scene):
    b = scene.bearing
    return skf_constants(b.kind, b.series)


def _apply(scene: Scene, values: dict, cells: dict | None = None) -> Scene:
    built = {k[len(_BUILDER):]: v for k, v in values.items() if k.startswith(_BUILDER)}
    net = {k: v for k, v in values.items()
           if (k in scene.network_parameters or "." in k) and not k.startswith(_BUILDER)}
    sc = scene.with_(network_parameters=net) if net else scene
    if built:                    # the machine with the values, cut into the nominal's cells (its nodes kept)
        sc = dataclasses.replace(sc, network=estimates.drawn(sc.network, built, cells))
    skf = {k: v for k, v in values.items() if k in _SKF}
    if skf:
        sc = sc.with_(models=skf)
    w = {k: v for k, v in values.items() if k in ("T_ambient_C", "T_oil_in_C", "oil_flow_L_h")}
    if w:
        sc = sc.with_(**w)
    rep = {k: v for k, v in values.items() if k in ("mu_boundary", "mu_full_film")}
    for k, v in rep.items():
        if not 0.0 <= v <= 1.0:
            raise InputError(k, v, "friction coefficient must lie in [0, 1]")
    if rep:
        sc = dataclasses.replace(sc, **rep)
    if "K_rs" in values:
        sc = sc.with_(K_rs=values["K_rs"])                   # checked as the scene file's key (>= 0)
    return sc


@dataclass
class Calibration:
    """Fitted parameters with standard uncertainties.

    Attributes
    ----------
    values : dict          name → fitted value
    std : dict             name → standard uncertainty (None if the data do not determine it)
    start : dict           name → start value
    cov : ndarray          covariance of the parameters (in the order of ``values``)
    rms_residual : float   RMS weighted residual (≈ K for temperatures) at the optimum
    dof : int              residuals − parameters
    nfev : int             model evaluations
    comparison : Comparison  the log against the calibrated scene
    scene : Scene          the calibrated scene
    """

    values: dict
    std: dict
    start: dict
    cov: np.ndarray
    rms_residual: float
    dof: int
    nfev: int
    comparison: Comparison | None = None
    scene: Scene | None = field(default=None, repr=False)
    message: str = ""

    def as_dict(self) -> dict:
        return {"values": self.values, "std": self.std, "start": self.start, "cov": self.cov,
                "rms_residual": self.rms_residual, "dof": self.dof, "nfev": self.nfev, "message": self.message,
                "metrics": self.comparison.metrics if self.comparison else None,
                "mode": self.comparison.mode if self.comparison else None}

    def summary(self) -> str:
        w = max([18] + [len(k) for k in self.values])
        lines = [f"calibration: {self.nfev} model evaluations, RMS residual {self.rms_residual:.4g} "
                 f"(K, or % of torque), {self.dof} degrees of freedom", "",
                 f"{'parameter':{w}s} {'start':>12s} {'fitted':>12s} {'std':>12s}"]
        for k, v in self.values.items():
            s = self.std[k]
            lines.append(f"{k:{w}s} {self.start[k]:12.5g} {v:12.5g} " + (f"{s:12.3g}" if s is not None else f"{'n/a':>12s}"))
        if self.message:
            lines += ["", self.message]
        if self.comparison is not None:
            lines += ["", self.comparison.summary()]
        return "\n".join(lines)


#: The Jacobian at the fit is checked by central differences this many times the fit's step wider
_WIDE = 10.0


def _central(resid, x, h):
    """Central-difference Jacobian of ``resid`` at ``x`` with the step ``h`` (absolute: u is scaled to 1)."""
    cols = []
    for i in range(x.size):
        e = np.zeros_like(x)
        e[i] = h
        cols.append((resid(x + e) - resid(x - e)) / (2.0 * h))
    return np.column_stack(cols)


def _forward(resid, h):
    """The forward-difference Jacobian of ``resid`` with the absolute step ``h`` in u, for least_squares (scipy's
    relative step shrinks with |u| and degenerates where an iterate passes u = 0: a step of 1e-9 under the heat-up's
    tolerance noise); the residual at x is the last one ``resid`` returned there (``resid.last``)."""
    def jac(x):
        lx, f0 = resid.last
        f0 = f0 if np.array_equal(lx, x) else resid(x)
        cols = []
        for i in range(x.size):
            e = np.zeros_like(x)
            e[i] = h
            cols.append((resid(x + e) - f0) / h)
        return np.column_stack(cols)
    return jac


def _fit(resid, xs0, diff_step, max_nfev):
    """(least-squares result, its Jacobian, note): the fit from ``xs0`` with forward differences of step ``diff_step``,
    then its Jacobian checked by central differences :data:`_WIDE` times wider.  A residual that is not smooth at
    ``diff_step`` (a heat-up's integrator tolerance and film cells) turns a forward difference into noise: a false
    minimum and an uncertainty orders of magnitude too small.  Where the two Jacobians differ by more than a quarter
    of the wider one's norm, the fit goes on from there with the wider step, and its uncertainty comes from the wider
    central Jacobian (the note says so)."""
    fit = (lambda x0, h: optimize.least_squares(resid, x0, jac=_forward(resid, h), method="trf", max_nfev=max_nfev,
                                                x_scale=1.0))
    res = fit(xs0, diff_step)
    if res.status <= 0:
        return res, res.jac, ""
    wide = _WIDE * diff_step
    J = _central(resid, res.x, wide)
    if np.linalg.norm(res.jac - J) <= 0.25 * np.linalg.norm(J):
        return res, res.jac, ""
    res = fit(res.x, wide)
    return res, _central(resid, res.x, wide), (
        f"the residuals are not smooth at the step {diff_step:g} (the simulation's tolerance): fitted on with "
        f"{wide:g}, the uncertainty from central differences at that step")


def calibrate(scene: Scene, log: RigLog, params: list, mapping: dict, *, T0_C=None, max_nfev: int = 60,
              diff_step: float = 1e-3) -> Calibration:
    r"""Fit named parameters of a scene to a rig log (nonlinear least squares).

    Parameters
    ----------
    scene : Scene
    log : RigLog
    params : list[str]     names (``NAME`` or ``NAME=START``, see :func:`parameter_names`): network
                           parameters (``"bearing_to_ambient.G_W_K"``, ``"oil_stream.beta"``, or a
                           ``[thermal.parameters]`` key), T_ambient_C, T_oil_in_C, oil_flow_L_h,
                           mu_boundary, mu_full_film, or on an SKF scene skf_R1, skf_S1, skf_mu_EHL
                           (seed 002 re-calibrates R1, S1 for the 51107 this way)
    mapping : dict         channel → node (:func:`channel_map`)
    T0_C : float           start temperature of transient logs [°C] (default ambient)
    max_nfev : int         iterations of each least-squares pass (its function evaluations; the forward Jacobian's
                           p evaluations per iteration, the central check's 2p and a second pass where the
                           residuals are not smooth come on top)
    diff_step : float      finite-difference step of the Jacobian, relative to the start value (absolute in u)
                           (a step in ln p for positive parameters, diff_step·|p0| — or diff_step
                           when p0 = 0 — for the others)

    Returns
    -------
    Calibration

    Notes
    -----
    Positive parameters are fitted as ln p (p stays positive; the standard
    uncertainty is σ_p = p σ_ln p).  Covariance = s² (JᵀJ)⁻¹, s² = Σ r²/(m − p);
    with m = p (no degrees of freedom) the uncertainty is not determined (None).
    The optimiser sees every parameter as u = 1 at its start value (ln p = ln p0 + u − 1,
    or p = p0 + (u − 1)·|p0|), and its forward differences take the absolute step ``diff_step`` in u:
    a relative step of ``diff_step`` in p (or of |p0|) whatever the value (scipy's own step is relative to
    |u| and degenerates where an iterate passes u = 0, to a step the integrator's tolerance noise swamps).
    The Jacobian at the answer is checked by central differences ten times wider; where the residuals are not
    smooth at ``diff_step``, the fit goes on with the wider step and says so (``message``).
    """
    if not params:
        raise InputError("--param", None, "name at least one parameter to fit")
    specs = [_parse_param(scene, p) for p in params]
    names = [n for n, _ in specs]
    if len(set(names)) != len(names):
        raise InputError("--param", ", ".join(names), "each parameter once")
    x0 = np.array([v for _, v in specs])
    logsp = np.array([v > 0 and not n.endswith("_C") for n, v in specs])
    lin = np.where(x0 != 0.0, np.abs(x0), 1.0)          # scale of a parameter fitted as itself

    def values_of(u):
        u = np.asarray(u, float) - 1.0
        return {n: float(p0 * np.exp(ui) if lg else p0 + ui * sc)
                for n, p0, ui, lg, sc in zip(names, x0, u, logsp, lin)}

    weights = {}
    if "torque_Nm" in log.columns:
        tq = log["torque_Nm"]
        if np.any(~np.isnan(tq)):
            mean = float(np.nanmean(np.abs(tq)))
            if not mean > 0:
                raise InputError("torque_Nm", 0.0, "a torque to fit must not be zero in every row (its residuals "
                                 "are weighed in % of its mean)")
            weights["torque_Nm"] = 100.0 / mean
    fit_channels = [c for c, n in mapping.items() if not special_target(n)]
    nfev = [0]
    cells = ({k: g.n for k, g in build_network(scene.network).segments.items()}
             if any(n.startswith(_BUILDER) for n in names) else None)

    def resid(x):
        nfev[0] += 1
        sim = simulate_log(_apply(scene, values_of(x), cells), log, mapping, T0_C=T0_C)
        chans = fit_channels + (["torque_Nm"] if "torque_Nm" in weights else [])
        r = []
        for c in chans:
            y = log[c]
            ok = ~np.isnan(y)
            r.append((sim[c][ok] - y[ok]) * weights.get(c, 1.0))
        resid.last = (np.array(x, float), np.concatenate(r) if r else np.zeros(0))
        return resid.last[1]
    resid.last = (None, None)

    xs0 = np.ones(len(names))
    with warnings.catch_warnings():
        # the trial values' warnings (a trial far from the answer may run hot): the answer's are the comparison's
        warnings.simplefilter("ignore", OutsideValidity)
        warnings.simplefilter("ignore", RuntimeWarning)
        r0 = resid(xs0)
        m, p = r0.size, len(names)
        if m < p:
            raise InputError("--param", ", ".join(names), f"{p} parameters but only {m} measured values")
        res, J, msg = _fit(resid, xs0, diff_step, max_nfev)
    rms = float(np.sqrt(np.mean(res.fun**2))) if m else 0.0
    if res.status <= 0:
        raise NoConvergence(f"calibration did not converge: {res.message}", iterations=int(res.nfev),
                            residual=rms, last=values_of(res.x))
    dof = m - p
    JTJ = J.T @ J
    vals = values_of(res.x)
    std = {n: None for n in names}
    cov = np.full((p, p), np.nan)
    if np.linalg.cond(JTJ) > 1e14:
        msg = "; ".join(filter(None, [msg, "the data do not determine these parameters independently (singular "
                                           "Jacobian): no uncertainty"]))
    elif dof == 0:
        msg = "; ".join(filter(None, [msg, "as many parameters as measured values: exact fit, uncertainty not "
                                           "determined"]))
    else:
        s2 = float(res.fun @ res.fun) / dof
        cov_x = s2 * np.linalg.inv(JTJ)
        scale = np.array([vals[n] if lg else sc for n, lg, sc in zip(names, logsp, lin)])
        cov = cov_x * np.outer(scale, scale)
        std = {n: float(np.sqrt(cov[i, i])) for i, n in enumerate(names)}
    msg = "; ".join(filter(None, [msg, *_fit_notes(scene, names, vals, std, x0, logsp)]))
    cal_scene = _apply(scene, vals, cells)
    comp = compare(cal_scene, log, mapping, T0_C=T0_C)
    return Calibration(values=vals, std=std, start=dict(zip(names, x0.tolist())), cov=cov, rms_residual=rms,
                       dof=dof, nfev=nfev[0], comparison=comp, scene=cal_scene, message=msg)


def _fit_notes(scene: Scene, names, vals: dict, std: dict, x0, logsp) -> list:
    """What the fitted values say beyond their numbers: a parameter that runs towards 0 (the log needs none of it),
    a positive one the log does not determine (its standard uncertainty as large as its value; not said of a
    temperature, whose zero is arbitrary: its stated range speaks for it), one fitted outside the range
    the scene states for it (its uncertainty's 5–95 % or support: :func:`~thermobear.coupled.uncertainty.uncertain_inputs`)."""
    stated = {i.address: i.uncertainty for i in uncertain_inputs(scene)}
    notes = []
    for i, n in enumerate(names):
        v, s = vals[n], std[n]
        if logsp[i] and s is not None and v < 0.1 * x0[i] and s > v:
            notes.append(f"{n} runs towards 0 ({v:.3g} ± {s:.2g} from the start {x0[i]:.3g}): the log does not "
                         "determine it and needs none of it")
        elif logsp[i] and s is not None and s >= v:        # (ratio-scale parameters: a temperature's 0 is arbitrary)
            notes.append(f"{n} is not determined by the log ({v:.3g} ± {s:.2g}: the uncertainty as large as the value)")
        u = stated.get(n if n.startswith(_BUILDER) else _ADDRESS.get(n))
        if u is not None:
            nominal = _parse_param(scene, n)[1]                 # the scene's own value (a given start aside)
            lo, hi = sorted(float(u.apply(nominal, d)) for d in (u.lo, u.hi))
            if not lo <= v <= hi:
                span = "support" if u.distribution == "uniform" else "5–95 %"
                notes.append(f"{n} = {v:.3g} lies outside the range the scene states for it, {lo:.3g} … {hi:.3g} "
                             f"({span}; {u.source or 'no source given'}): the log pulls it where the scene holds it "
                             "unlikely — check the log's channel map, and what else the model may miss")
    return notes

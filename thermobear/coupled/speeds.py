r"""Speeds found on the model: ISO 15312's thermal reference speed from thermobear's own losses, the
thermally safe speed of a scene's own cooling (root finding on the coupled steady state), and DIN
732's thermally safe speed of the scene by the standard's method, for comparison.

* :func:`thermal_reference_speed` — the speed at which the local loss model, at ISO 15312's
  reference conditions (bearing at 70 °C, reference load and oil, oil bath up to the middle of the
  lowest ball), dissipates the reference heat flow q_r A_r (:mod:`thermobear.rating.speeds`).
* :func:`thermally_safe_speed` — the speed at which the hotter race (the node of the inner or outer
  contact role: ``inner_race`` / ``outer_race``, the rings' raceway layers, where the network has them;
  :func:`hottest_race`) or a chosen node of the scene's coupled steady state reaches a limit
  temperature: DIN 732's question answered with the full model.
* :func:`runaway_speed` — the speed at which the coupled model's equilibria end: a thermal runaway, a preloaded
  pair's preload running away, or another end (:data:`ENDS`), bracketed by bisection in log speed.
* :func:`din732_safe_speed` — DIN 732's answer: n_θ = f_n n_θr with n_θr by ISO 15312's own
  (Palmgren-form) equations and the heat the seating surfaces and the circulating oil carry away.

Each search brackets its root on a ladder of speeds evaluated in one batched call (losses over a
speed array; :func:`~thermobear.coupled.steady.steady_states` for the coupled model), within the
speed the validity limits accept (n·d_m ≤ 4e6 mm/min, :data:`thermobear.validity.LIMITS`), takes
the first crossing (the lowest speed that meets the condition: the conservative one when the
ladder is not monotonic, which the result reports) and refines it with Brent's method
(:func:`scipy.optimize.brentq`).  No crossing raises :class:`~thermobear.errors.NoSpeedRoot` naming
why ("… at no speed up to …", "… already at …").  The coupled search also ends its range at the speed
where the scene's contacts can no longer carry its loads (:class:`~thermobear.errors.ContactLimit`: in
an angular contact bearing the balls' centrifugal force turns the inner contacts towards the groove's
edge until the ellipse passes it); with no crossing below it, that speed is found by bisection and
named in the NoSpeedRoot.
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np

from thermobear.contact.geometry import BallBearing
from thermobear.coupled.sources import prepare, prepared_for
from thermobear.coupled.steady import SteadyState, steady_state, steady_states
from thermobear.errors import (ContactLimit, InputError, NoConvergence, NoSpeedRoot, OutsideValidity, SolverError,
                               ThermalPreloadRunaway, ThermalRunaway)
from thermobear.lazy import lazy_module
from thermobear.losses import bearing_losses
from thermobear.lubrication.lubricant import Lubricant, lubricant
from thermobear.rating.iso76 import static_equivalent_load
from thermobear.rating.life import stated_ratings
from thermobear.rating.speeds import (din732_balance_ratio, din732_heat_flow, din732_parameters, din732_speed_ratio,
                                      palmgren_coefficients, palmgren_load, palmgren_moments, reference_conditions,
                                      reference_heat_flow_density, reference_surface, standard_reference_speed)
from thermobear.scene import Scene
from thermobear.validity import LIMITS, collect

optimize = lazy_module("scipy.optimize")    # brentq: loaded by its first use

__all__ = ["ReferenceSpeed", "SafeSpeed", "RunawaySpeed", "Din732Speed", "runaway_speed", "reference_lubricant", "reference_loads", "thermal_reference_speed",
           "thermally_safe_speed", "din732_safe_speed", "hottest_ring_C", "hottest_race", "check_node",
           "HOTTER_RACE"]

_N_DM_REFUSE = LIMITS["n_dm"].refuse[1]          #: mm/min
#: Fa / (Fr tan α) of a single angular contact bearing loaded over half its balls (load zone ε = 0.5,
#: Sjövall's integrals J_a/J_r for ball bearings; Harris & Kotzalas 2007, "Distribution of internal
#: loading"): the axial reaction ISO 15312's radial reference load needs on such a bearing.
AXIAL_REACTION = 1.25
#: What a speed search limits when no node is named: the hotter of the inner and outer race nodes
#: (:func:`hottest_race`)
HOTTER_RACE = "hotter race"


def _ceiling_rpm(brg: BallBearing, n_max_rpm=None) -> float:
    top = _N_DM_REFUSE / (brg.dm * 1e3) * (1.0 - 1e-9)
    return top if n_max_rpm is None else min(float(n_max_rpm), top)


def reference_lubricant(kind: str) -> Lubricant:
    """ISO 15312's reference oil: a mineral oil without EP additives of ν_r at 70 °C (12 mm²/s radial,
    24 mm²/s thrust), with the base-oil properties of the bundled ISO VG 32 (radial) or ISO VG 68
    (thrust) mineral oil, the grades the standard names (as quoted by SKF).

    >>> round(reference_lubricant("deep_groove").nu(70.0), 9), round(reference_lubricant("thrust").nu(70.0), 9)
    (12.0, 24.0)
    """
    ref = reference_conditions(kind)
    base = lubricant("iso-vg-32-mineral" if ref.load == "Fr" else "iso-vg-68-mineral")
    return Lubricant.from_single_point(ref.nu_cSt * 1e-6 * float(base.rho(ref.T_C)), ref.T_C, base.rho15,
                                       walther_B=base.walther_B, gold_s=base.gold_s, gold_t=base.gold_t,
                                       name=f"iso15312-reference-{ref.nu_cSt:g}cSt", base_oil="mineral",
                                       description=f"ISO 15312 reference oil, {ref.nu_cSt:g} mm²/s at 70 °C "
                                                   f"(base oil of {base.name})")


@dataclass
class ReferenceSpeed:
    """The model's ISO 15312 thermal reference speed.

    Attributes
    ----------
    bearing : str
    n_rpm : float           speed at which the model's friction power equals q_r A_r [rpm]
    P_W : float             the model's friction power there [W]
    Phi_r_W : float         reference heat flow q_r A_r [W]
    q_r_W_m2, A_r_m2 : float
    load_N : float          reference load (radial 0.05 C0, thrust axial 0.02 C0) [N]
    lubricant : str
    residual_W : float      P_W − Phi_r_W [W]
    iterations : int        Brent iterations
    monotonic : bool        the friction power grew with speed over the bracket ladder
    warnings : list         OutsideValidity warnings of the answer (scope, speed)
    """

    bearing: str
    n_rpm: float
    P_W: float
    Phi_r_W: float
    q_r_W_m2: float
    A_r_m2: float
    load_N: float
    lubricant: str
    residual_W: float
    iterations: int
    monotonic: bool = True
    warnings: list = field(default_factory=list)


def _first_crossing(n, g):
    """Index i of the first ladder point with g >= 0 (None: none); g[i-1] < 0 when i > 0."""
    hit = np.flatnonzero(np.asarray(g) >= 0.0)
    return None if hit.size == 0 else int(hit[0])


def reference_loads(brg: BallBearing) -> dict:
    """ISO 15312's reference load of ``brg`` as scene loads {"Fa": N, "Fr": N}: the fraction of C0 (as the data
    state it, else ISO 76's from the geometry: :func:`~thermobear.rating.life.stated_ratings`) of
    :func:`~thermobear.rating.speeds.reference_conditions`, and for an angular contact bearing the axial
    reaction of a half load zone (:data:`AXIAL_REACTION`).

    >>> import thermobear as tb
    >>> {k: round(v) for k, v in reference_loads(tb.bearing("6208")).items()}
    {'Fr': 994}
    """
    ref = reference_conditions(brg.kind)
    loads = {ref.load: ref.load_fraction * stated_ratings(brg)[1]}
    if brg.kind == "angular_contact":                 # the axial reaction of a half load zone (ε = 0.5)
        loads["Fa"] = AXIAL_REACTION * loads["Fr"] * float(np.tan(brg.alpha0))
    return loads


def thermal_reference_speed(brg: BallBearing, *, lubricant: Lubricant | None = None, n_max_rpm=None,
                            xtol_rpm: float = 0.01, points: int = 25) -> ReferenceSpeed:
    """ISO 15312 thermal reference speed of ``brg`` from thermobear's local loss model.

    The friction power of :func:`~thermobear.losses.bearing_losses` with the whole bearing at 70 °C,
    the reference load (angular contact bearings: with the axial reaction of a half load zone,
    :data:`AXIAL_REACTION`) and oil (:func:`reference_lubricant`), oil-bath supply with the level at the
    middle of the lowest ball (SKF's H = D/2; thrust bearings: no churning term, the bath of a
    vertical shaft is not modelled) equals the reference heat flow q_r A_r.

    Raises
    ------
    NoSpeedRoot    the reference heat flow is reached at no speed up to the n·d_m limit (or already at 1 rpm)

    >>> import thermobear as tb
    >>> r = thermal_reference_speed(tb.bearing("6208"))
    >>> 5000 < r.n_rpm < 20000, abs(r.residual_W) < 1e-6 * r.Phi_r_W
    (True, True)
    """
    ref = reference_conditions(brg.kind)
    oil = reference_lubricant(brg.kind) if lubricant is None else lubricant
    A_r = float(reference_surface(brg.bore, brg.outer_diameter, brg.width, brg.kind))
    q_r = float(reference_heat_flow_density(A_r, brg.kind))
    loads = reference_loads(brg)
    Phi, load = q_r * A_r, loads[ref.load]
    level = brg.D / 2.0 if ref.load == "Fr" else None

    def power(n):
        return bearing_losses(brg, oil, n_rpm=n, T_C=ref.T_C, supply="oil_bath", oil_level_m=level, **loads).P_W

    top = _ceiling_rpm(brg, n_max_rpm)
    ladder = np.geomspace(1.0, top, points)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OutsideValidity)     # the answer's validity is checked below
        P = np.asarray(power(ladder), float)
        i = _first_crossing(ladder, P - Phi)
        if i is None:
            raise NoSpeedRoot(f"{brg.name}: the reference heat flow q_r A_r = {Phi:.4g} W is reached at no speed up to "
                              f"{top:.6g} rpm (n·dm limit; model friction there {P[-1]:.4g} W)", residual=P[-1] - Phi)
        if i == 0:
            raise NoSpeedRoot(f"{brg.name}: the reference heat flow q_r A_r = {Phi:.4g} W is exceeded already at "
                              f"{ladder[0]:g} rpm ({P[0]:.4g} W)", residual=P[0] - Phi)
        n, r = optimize.brentq(lambda x: float(power(x)) - Phi, ladder[i - 1], ladder[i], xtol=xtol_rpm, full_output=True)
    if not r.converged:
        raise NoConvergence(f"{brg.name}: Brent did not converge ({r.flag})", iterations=r.iterations)
    with collect(replay=False) as ws:
        P_n = float(power(n))
    if not ref.in_scope:
        ws.append(OutsideValidity(f"{brg.name}: ISO 15312 excludes thrust ball bearings (kinematic effects); the "
                                  "thrust reference conditions are applied as a model comparison only",
                                  quantity="iso15312_scope", field="bearing.kind", value=brg.kind,
                                  source="ISO 15312:2018 scope"))
    return ReferenceSpeed(bearing=brg.name, n_rpm=float(n), P_W=P_n, Phi_r_W=Phi, q_r_W_m2=q_r, A_r_m2=A_r,
                          load_N=float(load), lubricant=oil.name, residual_W=P_n - Phi, iterations=int(r.iterations),
                          monotonic=bool(np.all(np.diff(P) > 0.0)), warnings=list(ws))


def hottest_race(st: SteadyState, node: str | None = None) -> tuple[str, float]:
    """(node, temperature [°C]) of ``node`` in a steady state, or of the hotter race when ``node`` is None: the
    node of the inner or the outer contact role (:data:`thermobear.thermal.network.ROLES`: ``inner_race`` /
    ``outer_race`` where the network has them — the rings' raceway layers, not the ring bodies ``inner_ring``
    / ``outer_ring`` — else the washers, the rings or the one bearing node)."""
    if node is not None:
        if node not in st.T_C:
            raise InputError("node", node, f"a node of the scene's network: {', '.join(st.T_C)}")
        return node, float(st.T_C[node])
    inner, outer = st.roles["inner"], st.roles["outer"]
    return (inner, float(st.T_C[inner])) if st.T_C[inner] > st.T_C[outer] else (outer, float(st.T_C[outer]))


def hottest_ring_C(st: SteadyState, node: str | None = None) -> float:
    """Temperature [°C] of ``node`` in a steady state, or of the hotter race (:func:`hottest_race`) when ``node``
    is None."""
    return hottest_race(st, node)[1]


def check_node(scene: Scene, node: str | None, *, field: str = "node", prepared=None) -> None:
    """InputError naming ``field`` unless ``node`` (None: the hotter race) is a free node of the scene's network,
    one whose temperature is solved: a fixed-temperature node (a boundary, or imposed by ``thermal.fixed_C``)
    does not follow the speed, and a speed search on it would answer nothing."""
    if node is None:
        return
    tpl = prepared_for(scene, prepared).template
    if node not in tpl.free_nodes:
        what = ("a fixed-temperature (boundary) node: its temperature does not follow the speed" if node in
                tpl.fixed_nodes else "no such node")
        raise InputError(field, node, f"{what}; a free node of the scene's network: {', '.join(tpl.free_nodes)}")


@dataclass
class SafeSpeed:
    """The thermally safe speed of a scene's own cooling (the coupled model).

    Attributes
    ----------
    scene : str
    n_rpm : float         speed at which the node reaches the limit [rpm]
    limit_C : float       limit temperature [°C]
    node : str            the node limited (:data:`HOTTER_RACE` when none was named)
    T_C : float           its temperature at n_rpm [°C]
    T_node : str          the node whose temperature T_C is (the hotter race: ``inner_race`` or ``outer_race``)
    residual_K : float    T_C − limit_C [K]
    iterations : int      Brent iterations
    bracket_rpm : tuple   the ladder speeds around the root [rpm]
    monotonic : bool      the node temperature grew with speed over the ladder from its coolest point to the
                          bracket (a dip at low speed, where the churned bath carries away heat the machine
                          brings in faster than friction grows, is allowed)
    steady : SteadyState  the coupled steady state at n_rpm
    warnings : list       OutsideValidity warnings of that steady state
    """

    scene: str
    n_rpm: float
    limit_C: float
    node: str
    T_C: float
    residual_K: float
    iterations: int
    bracket_rpm: tuple
    monotonic: bool
    steady: SteadyState = field(repr=False, default=None)
    warnings: list = field(default_factory=list)
    T_node: str = ""
    ladder: tuple = field(repr=False, default=())   # ((speed [rpm], None or the exception that stopped it), ...)


#: the errors of a point without an equilibrium: a thermal runaway, or a preload's (a radial one, a pair's)
_RUNAWAYS = (ThermalRunaway, ThermalPreloadRunaway)


def _beyond(exc) -> bool:
    """An error that means no equilibrium below the lubricant's temperature limit (above any limit)."""
    return isinstance(exc, _RUNAWAYS) or (isinstance(exc, InputError) and "lubricant temperature" in str(exc))


def _one(scene, prepared):
    try:
        return steady_state(scene, prepared=prepared)
    except (*_RUNAWAYS, InputError, NoConvergence) as exc:
        return exc


def _ladder_T(scenes, node, prepared, limit_C) -> tuple:
    """(node temperatures of the ladder's steady states, index of the first rung whose contacts cannot carry
    the loads or None, the steady states or exceptions): a point without an equilibrium below the lubricant's limit is inf; the rungs from a
    :class:`~thermobear.errors.ContactLimit` on are cut off (it is raised at the first rung); another error
    at or below the first crossing is raised."""
    T, errors = [], {}
    results = _ladder_results(scenes, prepared)
    stop = next((k for k, r in enumerate(results) if isinstance(r, ContactLimit)), None)
    if stop == 0:
        raise results[0]
    for k, r in enumerate(results[:stop]):
        if isinstance(r, Exception):
            T.append(np.inf)
            if not _beyond(r):
                errors[k] = r
        else:
            T.append(hottest_ring_C(r, node))
    T = np.asarray(T)
    i = _first_crossing(None, T - limit_C)
    for k, e in errors.items():
        if i is None or k <= i:
            raise e
    return T, stop, results


def _ladder_results(scenes, prepared) -> list:
    """The steady states of a ladder's scenes in one batched call, or each one's exception (one by one where a
    point past the lubricant's limit stops the batch)."""
    try:
        return steady_states(scenes, prepared=prepared)
    except InputError as exc:
        if not _beyond(exc):
            raise
        return [_one(sc, prepared) for sc in scenes]


def _contact_limit(scene, prepared, lo, hi, node, rtol=2e-3) -> tuple:
    """(speed [rpm], ``node``'s temperature there [°C], the ContactLimit just above it): bisection in log speed
    between ``lo`` (its contacts carry the loads) and ``hi`` (they do not) to ``rtol`` relative."""
    exc, T_lo = None, None
    while hi / lo > 1.0 + rtol:
        mid = float(np.sqrt(lo * hi))
        try:
            T_lo, lo = hottest_ring_C(steady_state(scene.with_(n_rpm=mid), prepared=prepared), node), mid
        except ContactLimit as e:
            hi, exc = mid, e
        except (*_RUNAWAYS, InputError) as e:
            if not _beyond(e):
                raise
            T_lo, lo = np.inf, mid                    # beyond the lubricant's limit, but the contacts carry it
    if T_lo is None:
        T_lo = hottest_ring_C(steady_state(scene.with_(n_rpm=lo), prepared=prepared), node)
    if exc is None:
        try:
            steady_state(scene.with_(n_rpm=float(hi)), prepared=prepared)
        except ContactLimit as e:
            exc = e
    return lo, T_lo, exc


def _contact_no_root(scene, limit_C, what, n_c, T_c, exc) -> NoSpeedRoot:
    """The NoSpeedRoot of a search that meets the contacts' limit ``n_c`` [rpm] below the temperature limit."""
    why = exc.expected if exc is not None else "contacts cannot carry the loads"
    out = NoSpeedRoot(f"{scene.name}: the limit {limit_C:g} °C on {what} is reached at no speed up to {n_c:.6g} rpm, "
                      f"the highest speed at which the contacts carry the loads ({T_c:.2f} °C there); above it the "
                      f"{why}", residual=T_c - limit_C)
    out.contact_limit_rpm, out.T_C = n_c, T_c          # the numbers, for a report
    return out


def thermally_safe_speed(scene: Scene, *, limit_C: float = 70.0, node: str | None = None, n_min_rpm=None,
                         n_max_rpm=None, points: int = 9, xtol_rpm: float = 1.0) -> SafeSpeed:
    """Speed at which the scene's hotter race (:func:`hottest_race`; or ``node``) reaches ``limit_C`` in the coupled
    steady state.

    Parameters
    ----------
    scene : Scene          the machine (its load, lubrication and cooling); its own speed is replaced
    limit_C : float        limit temperature [°C]
    node : str             a network node instead of the hotter race
    n_min_rpm, n_max_rpm   search range [rpm] (default: 1 % of the scene's speed, at least 1 rpm, up to the
                           n·d_m limit of thermobear.validity)
    points : int           ladder points (one batched steady-state call)
    xtol_rpm : float       tolerance of the speed [rpm]

    Raises
    ------
    NoSpeedRoot   the limit is reached at no speed up to the top of the range, or exceeded already at its bottom
    InputError    a bad limit, node (not a free node of the network: :func:`check_node`) or range

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("block_6208_oil_bath.toml"))
    >>> r = thermally_safe_speed(s, limit_C=60.0, xtol_rpm=10.0)
    >>> abs(r.T_C - 60.0) < 0.5, r.n_rpm > s.n_rpm
    (True, True)
    """
    if not isinstance(scene, Scene):
        raise InputError("scene", type(scene).__name__, "a thermobear Scene")
    if not np.isfinite(limit_C) or limit_C <= -40.0:
        raise InputError("limit_C", limit_C, "a finite temperature above -40 °C")
    top = _ceiling_rpm(scene.bearing, n_max_rpm)
    bottom = max(1.0, 0.01 * scene.n_rpm) if n_min_rpm is None else float(n_min_rpm)
    if not 0.0 < bottom < top:
        raise InputError("n_min_rpm", n_min_rpm, f"a speed in (0, {top:.6g}) rpm below n_max_rpm")
    prep = prepare(scene)
    check_node(scene, node, prepared=prep)
    what = "the hotter race (inner or outer race node)" if node is None else f"node {node}"
    ladder = np.geomspace(bottom, top, points)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OutsideValidity)         # the answer's own warnings are kept
        T, stop, res = _ladder_T([scene.with_(n_rpm=float(n)) for n in ladder], node, prep, limit_C)
        i = _first_crossing(ladder, T - limit_C)
        lo, hi = (float(ladder[i - 1]), float(ladder[i])) if i else (None, None)
        if i is None and stop is not None:
            n_c, T_c, exc = _contact_limit(scene, prep, float(ladder[stop - 1]), float(ladder[stop]), node)
            if not T_c >= limit_C:
                raise _contact_no_root(scene, limit_C, what, n_c, T_c, exc)
            i, lo, hi = stop, float(ladder[stop - 1]), n_c      # the crossing lies below the contacts' limit
        if i is None:
            raise NoSpeedRoot(f"{scene.name}: the limit {limit_C:g} °C on {what} is reached at no speed up to "
                              f"{top:.6g} rpm (n·dm limit of the models; {T[-1]:.2f} °C there)",
                              residual=T[-1] - limit_C)
        if i == 0:
            raise NoSpeedRoot(f"{scene.name}: the limit {limit_C:g} °C on {what} is exceeded already at "
                              f"{bottom:.6g} rpm ({T[0]:.2f} °C)", residual=T[0] - limit_C)

        seen, refused, edge = {}, [], not np.isfinite(T[i]) if i < T.size else False

        def excess(n):
            try:
                seen[n] = steady_state(scene.with_(n_rpm=float(n)), prepared=prep)
                return hottest_ring_C(seen[n], node) - limit_C
            except (*_RUNAWAYS, InputError, NoConvergence) as e:
                refused.append(float(n))
                # below a runaway rung the search closes on the fold where the equilibria end: there the heating
                # path's loop gain nears 1 and it may not settle — as undecided as a runaway for the root
                if not (_beyond(e) or (edge and isinstance(e, NoConvergence))):
                    raise
                return 1e3                                      # no equilibrium: beyond any limit
        try:
            n, r = optimize.brentq(excess, lo, hi, xtol=xtol_rpm, full_output=True)
        except ContactLimit:          # between the rungs (the top one ran away first): the search ends there
            n_c, T_c, exc = _contact_limit(scene, prep, lo, refused[-1], node)
            if not T_c >= limit_C:
                raise _contact_no_root(scene, limit_C, what, n_c, T_c, exc) from None
            hi = n_c
            n, r = optimize.brentq(excess, lo, hi, xtol=xtol_rpm, full_output=True)
    if not r.converged:
        raise NoConvergence(f"{scene.name}: Brent did not converge ({r.flag})", iterations=r.iterations)
    st = seen[n] if n in seen else steady_state(scene.with_(n_rpm=float(n)), prepared=prep)
    at, Tn = hottest_race(st, node)
    rise = T[int(np.argmin(T[:i + 1])):i + 1]       # from the coolest ladder point up to the crossing
    return SafeSpeed(scene=scene.name, n_rpm=float(n), limit_C=float(limit_C), node=node or HOTTER_RACE, T_C=Tn,
                     residual_K=Tn - limit_C, iterations=int(r.iterations), bracket_rpm=(lo, hi),
                     monotonic=bool(np.all(np.diff(rise) > 0.0)), steady=st, warnings=list(st.warnings), T_node=at,
                     ladder=tuple((float(n), r if isinstance(r, Exception) else None) for n, r in zip(ladder, res)))


#: what ends the equilibria at a speed: the error's class → its name in the answer
ENDS = {ThermalPreloadRunaway: "preload runaway", ThermalRunaway: "thermal runaway", NoConvergence: "no converged "
        "equilibrium", ContactLimit: "the contacts cannot carry the loads", InputError: "past the lubricant's limit"}


def _ends(exc) -> str | None:
    """The name of what ends the equilibria (:data:`ENDS`), or None for another error."""
    if isinstance(exc, ContactLimit):              # (an InputError: before the lubricant's)
        return ENDS[ContactLimit]
    if isinstance(exc, InputError) and not _beyond(exc):
        return None
    return next((v for k, v in ENDS.items() if isinstance(exc, k)), None)


@dataclass
class RunawaySpeed:
    """The lowest speed at which a scene's coupled model has no equilibrium, and the highest below it that has one.

    Attributes
    ----------
    scene : str
    n_rpm : float          the lowest speed found without an equilibrium [rpm]
    settled_rpm : float    the highest speed found with one, within ``rtol`` below n_rpm [rpm]
    kind : str             what ends the equilibria there (:data:`ENDS`: a thermal runaway, a preload's, …)
    why : str              the error at n_rpm, one line
    T_C, T_node : float, str  the hotter race's temperature at settled_rpm [°C] and its node
    P_W : float            the power loss at settled_rpm [W]
    preload_warm_N : float | None  a preloaded pair's warm preload at settled_rpm [N] (None: no pair)
    steady : SteadyState   the coupled steady state at settled_rpm
    iterations : int       bisection steps
    again_rpm : tuple      ladder speeds above n_rpm that have an equilibrium again (the ladder not monotonic: the
                           first end is the answer, these say it is not the last) [rpm]
    """

    scene: str
    n_rpm: float
    settled_rpm: float
    kind: str
    why: str
    T_C: float
    T_node: str
    P_W: float
    preload_warm_N: float | None = None
    steady: SteadyState = field(repr=False, default=None)
    iterations: int = 0
    again_rpm: tuple = ()


def runaway_speed(scene: Scene, *, n_min_rpm=None, n_max_rpm=None, points: int = 9, rtol: float = 0.01,
                  ladder=None) -> RunawaySpeed:
    """The speed at which the coupled model of a scene's machine stops having an equilibrium: a thermal runaway
    (the losses grow with temperature faster than the cooling), a preloaded pair's preload running away (the warm
    inner ring and balls adding preload, the preload adding heat), or another end of the equilibria (:data:`ENDS`).
    A ladder of speeds (one batched call; or ``ladder``, a :class:`SafeSpeed`'s) finds the first rung without an
    equilibrium, and bisection in log speed narrows it with the rung below to ``rtol`` relative.

    Parameters
    ----------
    scene : Scene          the machine; its own speed is replaced
    n_min_rpm, n_max_rpm   search range [rpm] (as :func:`thermally_safe_speed`)
    points : int           ladder points
    rtol : float           relative width of the final bracket [-]
    ladder : tuple         ``((speed [rpm], None or the exception there), ...)`` already solved, ascending (then
                           ``n_min_rpm``, ``n_max_rpm`` and ``points`` are not used)

    Returns
    -------
    RunawaySpeed           the bracket, what ends the equilibria, the state below it, the bisection's steps and the
                           ladder's speeds above it that have an equilibrium again

    Raises
    ------
    NoSpeedRoot   an equilibrium at every rung up to the top of the range, or none already at its bottom
    InputError    bad range; SolverError / InputError of another kind at a rung below the first without equilibrium

    >>> import thermobear as tb
    >>> s = tb.load_scene(tb.example_path("seed004_oil_jet_7210.toml")).with_(arrangement="back_to_back",
    ...                                                                    preload_N=450.0, Fa=0.0, Fr=650.0)
    >>> r = runaway_speed(s, n_min_rpm=3200.0, n_max_rpm=6500.0, points=2, rtol=0.05)
    >>> r.kind, 3200.0 < r.settled_rpm < r.n_rpm <= 1.05 * r.settled_rpm
    ('preload runaway', True)
    """
    if not isinstance(scene, Scene):
        raise InputError("scene", type(scene).__name__, "a thermobear Scene")
    if not (np.isfinite(rtol) and 0.0 < rtol < 1.0):
        raise InputError("rtol", rtol, "a relative bracket width in (0, 1)")
    prep = prepare(scene)
    if ladder is None:
        top = _ceiling_rpm(scene.bearing, n_max_rpm)
        bottom = max(1.0, 0.01 * scene.n_rpm) if n_min_rpm is None else float(n_min_rpm)
        if not 0.0 < bottom < top:
            raise InputError("n_min_rpm", n_min_rpm, f"a speed in (0, {top:.6g}) rpm below n_max_rpm")
        rungs = np.geomspace(bottom, top, max(int(points), 2))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", OutsideValidity)
            res = _ladder_results([scene.with_(n_rpm=float(n)) for n in rungs], prep)
        ladder = tuple((float(n), r if isinstance(r, Exception) else None) for n, r in zip(rungs, res))
    k = next((k for k, (_, e) in enumerate(ladder) if e is not None), None)
    if k is not None and _ends(ladder[k][1]) is None:
        raise ladder[k][1]
    if k is None:
        raise NoSpeedRoot(f"{scene.name}: an equilibrium at every speed up to {ladder[-1][0]:.6g} rpm (the top of "
                          "the search: the n·dm limit of the models or n_max_rpm)", residual=0.0)
    if k == 0:
        raise NoSpeedRoot(f"{scene.name}: no equilibrium already at {ladder[0][0]:.6g} rpm ({_ends(ladder[0][1])})",
                          residual=0.0)
    (lo, _), (hi, why) = ladder[k - 1], ladder[k]
    again = tuple(n for n, e in ladder[k + 1:] if e is None)
    st, its = None, 0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", OutsideValidity)
        while hi / lo > 1.0 + rtol:
            mid, its = float(np.sqrt(lo * hi)), its + 1
            try:
                st, lo = steady_state(scene.with_(n_rpm=mid), prepared=prep), mid
            except (SolverError, InputError) as e:
                if _ends(e) is None:
                    raise
                hi, why = mid, e
        st = st if st is not None else steady_state(scene.with_(n_rpm=lo), prepared=prep)
    at, T = hottest_race(st, None)
    pre = getattr(st, "preload", None)
    return RunawaySpeed(scene=scene.name, n_rpm=float(hi), settled_rpm=float(lo), kind=_ends(why),
                        why=f"{type(why).__name__}: " + " ".join(str(why).split()), T_C=T, T_node=at, P_W=float(st.P_W),
                        preload_warm_N=float(pre["warm_N"]) if pre else None, steady=st, iterations=its,
                        again_rpm=again)


@dataclass
class Din732Speed:
    """DIN 732's thermally safe operating speed of a scene (the standard's method; see
    :mod:`thermobear.rating.speeds` for what is unconfirmed).

    Attributes
    ----------
    n_rpm : float            n_θ = f_n n_θr [rpm]
    f_n : float              speed ratio [-]
    K_L, K_P : float         lubricant (M0's) and load (M1's) parameters [-]
    n_theta_r_rpm : float    thermal reference speed by ISO 15312's equations [rpm]
    Phi_W : float            heat dissipated at the limit temperature (seating surfaces + oil) [W]
    limit_C : float          the bearing temperature of the balance [°C]
    nu_cSt : float           operating viscosity at limit_C [mm²/s]
    P1_N : float             load of the friction moment [N]
    f0, f1 : float           friction coefficients (operating lubrication and load)
    f_n_balance : float      the root of the heat balance K_L f^(5/3) + K_P f = 1 that DIN 732's f_n
                             approximates (within 5.7 % for 0.01 ≤ K_L, K_P ≤ 10) [-]
    """

    n_rpm: float
    f_n: float
    K_L: float
    K_P: float
    n_theta_r_rpm: float
    Phi_W: float
    limit_C: float
    nu_cSt: float
    P1_N: float
    f0: float
    f1: float
    f_n_balance: float = float("nan")   #: the root of the balance f_n approximates (rating.speeds.din732_balance_ratio)


_SUPPLIES = {"oil_bath": "oil_bath", "oil_jet": "oil_jet", "oil_air": "oil_air", "grease": "grease"}


def din732_safe_speed(scene: Scene, *, limit_C: float = 70.0) -> Din732Speed:
    """DIN 732 thermally safe operating speed of a scene's bearing, by the standard's method.

    n_θr from ISO 15312's heat balance with Palmgren's oil-bath coefficients at the reference load
    (:func:`~thermobear.rating.speeds.standard_reference_speed`); the heat dissipated at ``limit_C``:
    seating surfaces k_q A_s (limit − ambient) plus, with an oil jet, the oil flow heated from its
    inlet temperature to the limit; the friction moments at the scene's load and at the viscosity at
    ``limit_C``; f_n by DIN 732's approximation.

    Raises
    ------
    InputError    thrust ball bearings (outside DIN 732), a preloaded pair (its loads are the coupled state's),
                  dry-film supply, a limit not above the ambient

    >>> import thermobear as tb
    >>> d = din732_safe_speed(tb.load_scene(tb.example_path("block_6208_oil_bath.toml")))
    >>> 1000 < d.n_rpm < 30000, round(d.f_n * d.n_theta_r_rpm - d.n_rpm, 6)
    (True, 0.0)
    """
    brg = scene.bearing
    if brg.kind == "thrust":
        raise InputError("bearing.kind", brg.kind, "DIN 732 gives no thermally safe speed for thrust ball bearings")
    if getattr(scene, "arrangement", None) is not None:
        raise InputError("bearing.arrangement", scene.arrangement, "DIN 732 rates one bearing under its own loads; a "
                         "pair's loaded bearing carries the warm preload the coupled state solves (thermobear run): "
                         "give that bearing's loads without arrangement for DIN 732's row")
    if scene.supply not in _SUPPLIES:
        raise InputError("lubricant.supply", scene.supply, f"DIN 732 here: one of {', '.join(_SUPPLIES)}")
    dT_A = limit_C - scene.T_ambient_C
    if not np.isfinite(dT_A) or dT_A <= 0.0:
        raise InputError("limit_C", limit_C, f"must be above the ambient {scene.T_ambient_C:g} °C (at or below it no heat "
                         "leaves the bearing)")
    ref = reference_conditions(brg.kind)
    C0 = stated_ratings(brg)[1]                       # the data's, else ISO 76's from the geometry
    A_s = float(reference_surface(brg.bore, brg.outer_diameter, brg.width, brg.kind))
    f0r, f1r = palmgren_coefficients(brg.kind, "oil_bath", ref.load_fraction * C0, C0)
    n_r, _, _ = standard_reference_speed(A_s, brg.dm, ref.load_fraction * C0, f0r, float(f1r), ref.nu_cSt,
                                         n_max_rpm=_ceiling_rpm(brg))
    oil_L_min, dT_oil = 0.0, 0.0
    if scene.supply == "oil_jet" and scene.T_oil_in_C is not None:
        oil_L_min, dT_oil = scene.oil_flow * 6e4, max(limit_C - scene.T_oil_in_C, 0.0)
    Phi = float(din732_heat_flow(A_s, dT_A, oil_flow_L_min=oil_L_min, dT_oil=dT_oil))
    P0 = static_equivalent_load(scene.Fr, scene.Fa, brg.alpha0, brg.kind)
    f0, f1 = palmgren_coefficients(brg.kind, _SUPPLIES[scene.supply], P0, C0)
    P1 = float(palmgren_load(brg.kind, scene.Fa, scene.Fr, brg.alpha0))
    nu = float(scene.lubricant.nu(limit_C))
    M0, M1 = palmgren_moments(n_r, nu, P1, brg.dm, f0, f1)
    K_L, K_P = din732_parameters(n_r, M0, M1, Phi)
    f_n = float(din732_speed_ratio(K_L, K_P))
    return Din732Speed(n_rpm=f_n * n_r, f_n=f_n, f_n_balance=float(din732_balance_ratio(K_L, K_P)), K_L=float(K_L),
                       K_P=float(K_P), n_theta_r_rpm=n_r, Phi_W=Phi,
                       limit_C=float(limit_C), nu_cSt=nu, P1_N=P1, f0=float(f0), f1=float(f1))

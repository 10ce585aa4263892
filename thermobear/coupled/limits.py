"""The validity of an answer: the limits of :mod:`thermobear.validity` checked at a solved point.

The solvers call :func:`contact_pressure` as soon as the loads are known (a load the contacts
cannot carry is refused before anything else runs) and :func:`point_warnings` on each answer (what
lies outside the validated range becomes a warning of that point's result).
"""
from __future__ import annotations

import warnings

import numpy as np

from thermobear.errors import ContactLimit, ExtrapolationWarning, InputError, OutsideValidity, ThermalRunaway, UnreadInput
from thermobear.arrays import take
from thermobear.loads.api import check_contacts, groove_angle, loads_text
from thermobear.losses.seals import CONTACT_SEALS, seal_material
from thermobear.model_inputs import unread_settings
from thermobear.rating.life import stated_ratings
from thermobear.rating.maker_speeds import maker_speeds
from thermobear.units import rpm_to_rad_s
from thermobear.validity import LIMITS, P_MAX_REFUSE_PA, T_LUBRICANT_REFUSE_C, check, collect

__all__ = ["p_max_Pa", "contact_pressure", "overloads", "point_warnings", "family_warnings", "grease_limit", "emit",
           "past_maker_limit", "runaway_at", "runaway_in", "film_preload_warnings", "film_load_preload_warnings",
           "FILM_PRELOAD_RATIO", "FILM_PRELOAD_C0"]


def p_max_Pa(Q, a, b):
    r"""Maximum Hertz contact pressure [Pa] of contacts with load Q [N] and semi-axes a, b [m].

    .. math:: p_{max} = \frac{3 Q}{2 \pi a b}

    (Harris 2001 eq 6.47); 0 where a contact is unloaded.

    >>> round(float(p_max_Pa(1000.0, 1e-3, 2e-4)) / 1e6, 1)
    2387.3
    """
    Q, a, b = (np.asarray(v, float) for v in (Q, a, b))
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where((Q > 0) & (a > 0) & (b > 0), 1.5 * Q / (np.pi * a * b), 0.0)


def contact_pressure(contacts, field: str = "operation (Fa_N, Fr_N, M_Nm)", warn: bool = False) -> list:
    """Refuse (InputError) loads whose maximum contact pressure exceeds the accepted limit, per
    contact of a prepared contact set (``contacts.sides[side]`` with Q, a, b); returns the warnings
    (with ``warn``)."""
    out = []
    for side in ("inner", "outer"):
        sd = contacts.sides[side] if hasattr(contacts, "sides") else contacts[side]
        out += check("p_max", p_max_Pa(sd["Q"], sd["a"], sd["b"]), field, what=f"{side} contacts", warn=warn)
    return out


def overloads(scenes, contacts) -> dict:
    """Points whose loads the contacts cannot carry: index → ContactLimit (an InputError) naming the loads,
    for a contact set over the points of ``scenes``: the maximum contact pressure beyond
    :data:`thermobear.validity.P_MAX_REFUSE_PA` (twice the ISO 76 static rating load) or a contact ellipse
    past its groove's equator (:func:`thermobear.loads.check_contacts`, the messages made only for the
    points outside)."""
    B, brg = len(scenes), scenes[0].bearing
    sides = {s: contacts.sides[s] for s in ("inner", "outer")}
    p = np.stack([np.asarray(p_max_Pa(sides[s]["Q"], sides[s]["a"], sides[s]["b"]), float).reshape(B, -1).max(axis=1)
                  for s in sides])
    theta = np.stack([np.reshape(np.where(np.asarray(sides[s]["Q"]) > 0,
                                          groove_angle(brg, sides[s]["alpha"], sides[s]["a"], f), 0.0), (B, -1)).max(axis=1)
                      for s, f in (("inner", brg.fi), ("outer", brg.fo))])
    out = {}
    for b in np.flatnonzero((p.max(axis=0) > P_MAX_REFUSE_PA) | (theta.max(axis=0) > LIMITS["contact_angle"].refuse[1])):
        sc = scenes[b]
        one = {s: {k: np.reshape(sides[s][k], (B, -1))[b] for k in ("Q", "alpha", "a", "b")} for s in sides}
        try:
            check_contacts(sc.bearing, one, "operation (Fa_N, Fr_N, M_Nm)",
                           given=loads_text(sc.Fa, sc.Fr, sc.M, sc.Fz, sc.My)
                           + (f" at {sc.n_rpm:.6g} rpm" if sc.n_rpm > 0 else "") + f" ({sc.bearing.name})")
        except ContactLimit as exc:
            out[int(b)] = exc
    return out


def grease_limit(scene) -> float | None:
    """The upper operating temperature [°C] of a scene's grease as its data state it (``grease_T_max_C``: the
    maker's, or a class's estimate with its range), None for an oil or a grease without one."""
    lub = scene.lubricant
    if lub.kind != "grease":
        return None
    T = lub.table.get("grease_T_max_C")
    return None if T is None or np.ndim(T) else float(T)


def _grease_warning(scene, x_C) -> list:
    """An OutsideValidity warning when the bearing's contacts or cavity run above the grease's upper operating
    temperature (:func:`grease_limit`): the thickener softens, the base oil bleeds and oxidises (SKF Group 2018,
    *Rolling bearings*, relubrication: intervals halve every 15 K above 70 °C), and the grease models here are
    those of a grease within its range."""
    T_max = grease_limit(scene)
    T = float(np.max(x_C))
    if T_max is None or not T > T_max:
        return []
    lub = scene.lubricant
    return [OutsideValidity(
        f"lubricant {lub.name}: contact / cavity temperature {T:.1f} °C above the grease's upper operating "
        f"temperature {T_max:g} °C (data: grease_T_max_C) — beyond it the thickener softens and the base oil bleeds "
        "and oxidises (SKF 2018: relubrication intervals halve every 15 K above 70 °C); the grease's life, not only "
        "its friction, is at stake",
        quantity="grease_T", value=T, limit=f"<= {T_max:g} °C", source=f"materials/lubricants/{lub.name}.toml",
        field="lubricant.name")]


def _seal_T(x_C, T_seal_C=None) -> tuple:
    """(temperature [°C], what it is) the seal check reads: the network's seal node where it has one, else the
    hottest contact / cavity temperature."""
    if T_seal_C is not None and np.isfinite(T_seal_C):
        return float(T_seal_C), "seal node"
    return float(np.max(x_C)), "contact / cavity temperature"


def _seal_hot(scene, x_C, T_seal_C=None, T_max_C=None) -> bool:
    """Contact seals above their material's upper operating temperature (:func:`_seal_T`; ``T_max_C`` the
    material's, read once by a caller checking many points)."""
    if scene.seals not in CONTACT_SEALS:
        return False
    return _seal_T(x_C, T_seal_C)[0] > (seal_material()["T_max_C"] if T_max_C is None else T_max_C)


def _seal_warning(scene, x_C, T_seal_C=None) -> list:
    """An OutsideValidity warning where a bearing with contact seals runs its seal lips (the network's seal node;
    without one, the contacts or cavity) above the seal material's upper operating temperature
    (:func:`thermobear.losses.seals.seal_material`: NBR 100 °C, 120 °C briefly): the lips harden and wear, and
    SKF's seal friction model is that of a lip within its range."""
    if not _seal_hot(scene, x_C, T_seal_C):
        return []
    m, (T, what) = seal_material(), _seal_T(x_C, T_seal_C)
    return [OutsideValidity(
        f"bearing.seals = {scene.seals}: {what} {T:.1f} °C above the {m['name']} seal lips' upper "
        f"operating temperature {m['T_max_C']:g} °C ({m['T_brief_C']:g} °C for brief periods) — the lips harden and "
        "wear; the seal friction is that of a lip within its range", quantity="seal_T", value=T,
        limit=f"<= {m['T_max_C']:g} °C", source=m["source"], field="bearing.seals")]


def past_maker_limit(scene):
    """The scene's maker's speeds (:func:`thermobear.rating.maker_speeds.maker_speeds`, by its bearing and seals)
    where its speed lies above their limiting speed, else None (at or below it, or no value on file)."""
    if not scene.n_rpm > 0:
        return None
    m = maker_speeds(scene.bearing, scene.seals)
    return m if _above(scene.n_rpm, m) else None


def _above(n_rpm, m) -> bool:
    """A speed [rpm] above the limiting speed of maker's speeds ``m`` (None: no value on file)."""
    return m is not None and n_rpm > 0 and rpm_to_rad_s(n_rpm) > m.limiting


def _past_maker_limits(scenes) -> np.ndarray:
    """Per point (B,): above the maker's limiting speed (:func:`past_maker_limit`), the data read once per bearing
    and seals of the family."""
    found: dict = {}
    out = np.zeros(len(scenes), bool)
    for b, s in enumerate(scenes):
        key = (s.bearing.name, s.seals)
        if key not in found:
            found[key] = maker_speeds(s.bearing, s.seals)
        out[b] = _above(s.n_rpm, found[key])
    return out


def _maker_speed_warning(scene) -> list:
    """An OutsideValidity warning where the scene runs above its bearing's maker's limiting speed (SKF's kinematic
    limit of the bearing, its cage or its seals' lips, for grease and oil alike): whatever the cooling, the maker
    does not rate the bearing for that speed, and the models here know nothing of the cage's or the lips' limit."""
    m = past_maker_limit(scene)
    if m is None:
        return []
    what = m.designation + (f" for seals = {scene.seals}" if scene.seals != "none" else "")
    return [OutsideValidity(
        f"operation.n_rpm = {scene.n_rpm:g} rpm above the maker's limiting speed {m.limiting_rpm:g} rpm of the "
        f"{what} (SKF's kinematic limit of the bearing, its cage or its seals, for grease and oil; {m.source}"
        + (f"; {m.note}" if m.note else "") + ") — the maker does not rate the bearing for this speed, whatever "
        "the cooling; the models' losses and temperatures know no cage or seal-lip speed limit",
        quantity="maker_limiting_speed", value=float(scene.n_rpm), limit=f"<= {m.limiting_rpm:g} rpm",
        source=f"materials/maker_speeds.toml [{m.bearing}.{m.variant}]: {m.source}", field="operation.n_rpm")]


def _unloaded(scene) -> bool:
    """At speed without any load (Fa, Fr, Fz, M, My all 0) and without a radial preload (a negative clearance
    holds the rings centred, every ball loaded: :func:`~thermobear.contact.fits.clearance_preload`)."""
    return (scene.n_rpm > 0 and not any(getattr(scene, k) for k in ("Fa", "Fr", "Fz", "M", "My"))
            and scene.bearing.Pd >= 0)


def _unloaded_warning(scene) -> list:
    """An OutsideValidity warning for a bearing at speed without any load: its rings are held centred, a state
    that is not the limit of a small load — the smallest load seats the rings one way or the other (an axial one
    turns the contact angles, a radial one moves the ring across the clearance), and the losses follow (seed 004's
    7210 at 40 °C: 19 W unloaded, 45 W under 1 µN axial; the 6208 oil bath 32.6 W, 33.1 W under 1 µN axial, 41.5 W
    under 1 µN radial)."""
    if not _unloaded(scene):
        return []
    return [OutsideValidity(
        "unloaded at speed: the rings held centred, a state the smallest load changes (an axial one turns the contact "
        "angles, a radial one moves a ring across the clearance) — the losses here are not those of a lightly loaded "
        "bearing; give the load it carries (a preload, the rotor's weight)", quantity="unloaded", value=0.0,
        limit="a load > 0", source="thermobear.coupled.limits", field="operation (Fa_N, Fr_N)")]


def _oil_as_grease(scene) -> bool:
    """An oil's data under ``supply = "grease"``."""
    return scene.supply == "grease" and getattr(scene.lubricant, "kind", "oil") != "grease"


def _oil_as_grease_warning(scene) -> list:
    """An OutsideValidity warning for an oil's data under a grease supply: the grease models use it as the base oil,
    and no grease upper operating temperature (``grease_T_max_C``, :func:`grease_limit`) is checked."""
    if not _oil_as_grease(scene):
        return []
    name = scene.lubricant.name
    return [OutsideValidity(
        f"lubricant {name} is an oil, supply = grease: taken as the grease's base oil, and no grease operating "
        "temperature limit is checked (its data has no grease_T_max_C); a grease of the list (thermobear list "
        "lubricants) states its own", quantity="lubricant kind", value="oil", limit="a grease",
        source=f"materials/lubricants/{name}.toml", field="lubricant.name")]


#: The film load model's Σ Q over the dry solution's above which the films preload the bearing (a warning), where
#: the films also add more than FILM_PRELOAD_C0 C0 (ISO 15312's light reference load, 0.05 C0): at light loads the
#: films of the balls outside the load zone legitimately double a small Σ Q (a 6208 oil bath under Fr 50 N: ×2–3.7)
FILM_PRELOAD_RATIO = 2.0
FILM_PRELOAD_C0 = 0.05


def _dry_sum(dry) -> float:
    """Σ Q of the inner contacts [N] of a point's dry load distribution (a DryRow, a LoadDistribution; None: NaN)."""
    if dry is None:
        return np.nan
    if hasattr(dry, "batch"):                  # a row of a batched solution: its Q_i alone, not the whole row
        return float(np.sum(np.reshape(np.asarray(dry.batch.Q_i, float), (dry.B, -1))[dry.row]))
    return float(np.sum(dry.Q_i))


def _film_ratio(scenes, losses, dry) -> np.ndarray:
    """Per point (B,): Σ Q of the inner contacts of ``losses`` (mean ball load × Z: one model alternative's — a
    blend's are its dominant one's, :func:`film_preload_warnings` checks each) over that of the point's dry load
    distribution (``dry``: one per point, None: no check → NaN); NaN too where the
    films add less than :data:`FILM_PRELOAD_C0` C0."""
    B = len(scenes)
    c = getattr(losses, "contacts", None)
    if not c or dry is None:
        return np.full(B, np.nan)
    Q = np.reshape(np.asarray(c["inner"]["Q"], float), (B, -1)).mean(axis=1) * np.array([s.bearing.Z for s in scenes])
    Q_dry = np.array([_dry_sum(d) for d in dry])
    with np.errstate(all="ignore"):
        ratio = Q / Q_dry
    for b in np.flatnonzero(ratio > FILM_PRELOAD_RATIO):          # the bearing's C0 only where it is asked
        if not Q[b] - Q_dry[b] > FILM_PRELOAD_C0 * stated_ratings(scenes[b].bearing)[1]:
            ratio[b] = np.nan
    return ratio


def film_load_preload_warnings(scene, rows) -> list:
    """The film-preload warning (:data:`FILM_PRELOAD_RATIO`) of film load distributions ``[(T_film [°C],
    LoadDistribution, dry)]`` of one scene (a heat-up's loads at the film temperatures it passed): named once, at
    the film temperature of the largest preload."""
    worst = (np.nan, None, None)
    for T, ld, dry in rows:
        Q_dry = _dry_sum(dry)
        r = float(np.sum(ld.Q_i)) / Q_dry if Q_dry > 0 else np.nan
        if r > FILM_PRELOAD_RATIO and np.sum(ld.Q_i) - Q_dry > FILM_PRELOAD_C0 * stated_ratings(scene.bearing)[1] and \
                not r <= worst[0]:
            worst = (r, T, dry)
    return _film_preload_warning(scene, worst[0], worst[2], f" at {worst[1]:.3g} °C film temperature in the heat-up"
                                 if worst[1] is not None else "")


def _film_preload_warning(scene, ratio: float, dry, where: str = "", phi_rs=None) -> list:
    """An OutsideValidity warning where the film load model's ball loads exceed the dry solution's by more than
    :data:`FILM_PRELOAD_RATIO` (and by more than :data:`FILM_PRELOAD_C0` C0): the fully flooded films on both races
    of each ball (Hamrock–Dowson thicknesses, which a starved inlet would thin) take up more than the clearance and
    preload every ball; the hysteresis and sliding losses follow those loads."""
    if not ratio > FILM_PRELOAD_RATIO:
        return []
    Q_dry = _dry_sum(dry)
    starved = ("" if phi_rs is None or not phi_rs < 0.5 else
               f"; the same contacts' rolling force takes the track as starved (SKF's Φ_rs down to {phi_rs:.3g}) while "
               "the film load law takes it as flooded: no source links the two, so the answer lies between this one and "
               "the dry loads'")
    return [OutsideValidity(
        f"film-induced preload{where}: with the films in the contact laws the balls carry Σ Q = {ratio * Q_dry / 1e3:.3g} kN "
        f"on the inner race, {ratio:.3g} × the {Q_dry / 1e3:.3g} kN of the dry solution — the fully flooded films "
        "(Hamrock–Dowson, no starvation) are thicker than the clearance leaves them, and the hysteresis and sliding "
        "losses follow these loads; a starved inlet (cold, viscous oil) makes thinner films, so this is an upper "
        f"bound (models.load_model = jones_harris gives the dry loads){starved}", quantity="film preload", value=float(ratio),
        limit=f"<= {FILM_PRELOAD_RATIO:g} × the dry loads", source="thermobear.coupled.limits",
        field="models.load_model")]


def _least_phi_rs(losses):
    """The smallest replenishment factor Φ_rs of a loss result's contacts (None: no per-contact factor)."""
    c = getattr(losses, "contacts", None)
    vals = [np.asarray(c[k]["phi_rs"], float) for k in ("inner", "outer") if c and k in c and "phi_rs" in c[k]]
    return float(min(v.min() for v in vals)) if vals and all(v.size for v in vals) else None


def film_preload_warnings(scene, alternatives) -> list:
    """The film-preload warnings (:data:`FILM_PRELOAD_RATIO`) of a point's model alternatives ``[(losses, dry)]``,
    each checked with its own dry load distribution (a blend keeps one alternative's contacts: the film
    alternative's preload is named even where it does not dominate the weights)."""
    out = []
    for losses, dry in alternatives:
        if dry is not None:
            out += [w for w in _film_preload_warning(scene, float(_film_ratio([scene], losses, [dry])[0]), dry,
                                                     phi_rs=_least_phi_rs(losses))
                    if str(w) not in map(str, out)]
    return out


def _unread_warnings(scene) -> list:
    """An :class:`~thermobear.errors.UnreadInput` warning for each input the scene sets that its models do not
    read (:func:`thermobear.model_inputs.unread_settings`): the value would change nothing, never silently."""
    return [UnreadInput(f"{fld} = {v if isinstance(v, str) else format(v, 'g')} is not read by the chosen models: "
                        f"{why} — it changes nothing here",
                        quantity=fld, value=v, limit=why, source="thermobear.model_inputs.unread_inputs",
                        field=fld) for fld, v, why in unread_settings(scene)]


def point_warnings(scene, losses, x_C, dry=None, T_seal_C=None) -> list:
    """The OutsideValidity warnings of one solved operating point: speed (n·d_m; the maker's limiting speed),
    contact pressure, contact and oil temperatures (the lubricant's validated range; a grease's upper operating
    temperature; contact seals' lip material; an oil's data under a grease supply), the SKF model's Φ_bl, a bearing
    at speed without load, a scene input the models do not read (:class:`~thermobear.errors.UnreadInput`); with
    ``dry`` (the point's dry load distribution, where the film load model gave ``losses``' loads) a preload by the
    films; ``T_seal_C``: the network's seal node [°C], where it has one."""
    grease = (_grease_warning(scene, x_C) + _seal_warning(scene, x_C, T_seal_C) + _oil_as_grease_warning(scene)
              + _unloaded_warning(scene) + _unread_warnings(scene) + _maker_speed_warning(scene))
    grease += film_preload_warnings(scene, [(losses, dry)])
    with collect(replay=False) as got:
        check("n_dm", scene.n_rpm * scene.bearing.dm * 1e3, "operation.n_rpm", warn=True)
        check("lubricant_T", np.asarray(x_C, float), "contact / oil temperature", category=ExtrapolationWarning)
        if getattr(losses, "contacts", None):
            contact_pressure(losses.contacts, warn=True)
        skf = getattr(losses, "skf", None)
        if skf is not None:
            check("skf_phi_bl", np.asarray(skf.phi_bl, float), "models.losses = skf")
    return list(got) + grease


def _outside_warn(name, v) -> np.ndarray:
    """Per point (rows of ``v``): anything outside the validated range of limit ``name``."""
    lo, hi = LIMITS[name].warn
    v = np.asarray(v, float).reshape(np.shape(v)[0], -1)
    out = np.zeros(v.shape[0], bool)
    if lo is not None:
        out |= (v < lo).any(axis=1)
    if hi is not None:
        out |= (v > hi).any(axis=1)
    return out


def family_warnings(scenes, losses, x_C, answered=None, dry=None, T_seal_C=None) -> list:
    """:func:`point_warnings` of the B points of a family (batched ``losses``, ``x_C`` (B, 3)): the
    ranges checked for all points at once, the messages made only for the points outside (and
    ``answered``: a mask of the points that have an answer); ``dry``: per point its dry load distribution, where the
    film load model gave the loads (a preload by the films is named); ``T_seal_C``: (B,) the network's seal node [°C]
    where it has one."""
    B = len(scenes)
    n_dm = np.array([s.n_rpm * s.bearing.dm * 1e3 for s in scenes])
    flag = _outside_warn("n_dm", n_dm[:, None]) | _outside_warn("lubricant_T", x_C)
    T_max = np.array([np.inf if grease_limit(s) is None else grease_limit(s) for s in scenes])
    flag |= np.asarray(x_C, float).reshape(B, -1).max(axis=1) > T_max
    T_seal = np.full(B, np.nan) if T_seal_C is None else np.broadcast_to(np.asarray(T_seal_C, float), (B,))
    if any(s.seals in CONTACT_SEALS for s in scenes):
        T_lip = seal_material()["T_max_C"]
        flag |= np.array([_seal_hot(s, x, t, T_lip) for s, x, t in zip(scenes, np.asarray(x_C, float).reshape(B, -1),
                                                                         T_seal)])
    flag |= np.array([_unloaded(s) or _oil_as_grease(s) or bool(unread_settings(s)) for s in scenes])
    flag |= _past_maker_limits(scenes)
    flag |= _film_ratio(scenes, losses, dry) > FILM_PRELOAD_RATIO
    c = getattr(losses, "contacts", None)
    if c:
        p = np.concatenate([np.reshape(p_max_Pa(c[s]["Q"], c[s]["a"], c[s]["b"]), (B, -1)) for s in ("inner", "outer")], 1)
        flag |= _outside_warn("p_max", p)
    if getattr(losses, "skf", None) is not None:
        flag |= _outside_warn("skf_phi_bl", np.reshape(np.asarray(losses.skf.phi_bl, float), (B, -1)))
    out = [[] for _ in range(B)]
    if answered is not None:
        flag &= np.asarray(answered, bool)
    for b in np.flatnonzero(flag):
        out[b] = point_warnings(scenes[b], take(losses, b, B), x_C[b], None if dry is None else dry[b], T_seal[b])
    return out


def emit(ws, stacklevel: int = 3):
    """Issue an answer's warnings to the caller (Python warnings; the command line prints each once)."""
    for w in ws:
        warnings.warn(w, stacklevel=stacklevel)


def runaway_at(T_state: dict, t_s: float) -> None:
    """ThermalRunaway where a heat-up's node temperatures (``T_state``: node → °C at a piece's end ``t_s`` [s])
    pass the lubricant's limit (:data:`thermobear.validity.T_LUBRICANT_REFUSE_C`)."""
    hot = {n: v for n, v in T_state.items() if v > T_LUBRICANT_REFUSE_C[1]}
    if hot:
        node = max(hot, key=hot.get)
        raise ThermalRunaway(f"the heat-up passes the lubricant's limit {T_LUBRICANT_REFUSE_C[1]:g} °C ({node} at "
                             f"{hot[node]:.4g} °C by t = {t_s:g} s): no equilibrium the bearing could run at",
                             iterations=0, last=T_state)


def runaway_in(x_C, t_s) -> None:
    """ThermalRunaway where a heat-up's contact or oil temperatures (``x_C``: three series [°C] over the output
    times ``t_s`` [s]) pass the lubricant's limit between two pieces' ends (a start near it that passes it and
    comes back), as :func:`runaway_at` names one at a piece's end."""
    x = np.asarray(x_C, float)
    hi = T_LUBRICANT_REFUSE_C[1]
    if x.size and x.max() > hi:
        k = int(np.argmax((x > hi).any(axis=0)))
        raise ThermalRunaway(f"the heat-up passes the lubricant's limit {hi:g} °C (contact / oil temperature "
                             f"{x[:, k].max():.4g} °C at t = {t_s[k]:g} s)", iterations=0)

r"""High-speed quasi-static load distribution of a ball bearing (Jones 1960; Harris 2001 ch. 8).

At speed each ball carries a centrifugal force F_c and a gyroscopic moment M_g,
so the inner and outer contacts no longer share one line of action: α_o falls,
α_i rises and Q_o > Q_i.  Rigid rings, outer ring fixed, inner ring rotating at
n [rpm] and displaced by (δa, δr, θ, δz, θ_y) exactly as in :mod:`thermobear.loads.static`
(ISO/TS 16281 convention: δa measured from the centred position).

Geometry of ball j (Jones 1960 [1]; Harris 2001 [2] §8.2).  x axial (the direction in which F_a
pushes the inner ring), r radial outward through the ball centre; O_o and O_i
the outer and inner groove curvature centres, C the ball centre:

    O_i − O_o = (A1_j, A2_j) = (δa + ℜ (θ cos ψ_j + θ_y sin ψ_j),  A_r0 + δr cos ψ_j + δz sin ψ_j)
    C − O_o   = (X1_j, X2_j) = ((f_o − ½)D + δo_j)(sin αo_j, cos αo_j)
    O_i − C   = (A1_j − X1_j, A2_j − X2_j) = ((f_i − ½)D + δi_j)(sin αi_j, cos αi_j)

The two distance equations of Jones (1960) are explicit in δi, δo,

    δo = |C − O_o| − (f_o − ½)D,     δi = |O_i − C| − (f_i − ½)D,

so they are satisfied identically and the unknowns left per ball are X1, X2;
α_i, α_o are the directions of those two vectors.  Q_i = K_i δi^1.5,
Q_o = K_o δo^1.5.  A_r0 = A − P_d/2 is the radial distance of the groove centres with the rings centred (A cos α0
with a clearance; with a negative one, a radial preload, every ball is compressed between centred rings:
:attr:`~thermobear.contact.geometry.BallBearing.A_r0`, :mod:`thermobear.loads.rings`).

Free-body diagram of the ball (re-derived here; unit normal n = (sin α, cos α)
pointing from the inner towards the outer contact, tangent e = (cos α, −sin α),
cage frame x̂, r̂, t̂ = x̂ × r̂ of :mod:`thermobear.contact.kinematics`):

* inner ring on ball: +Q_i n_i (pushes outward/forward), outer ring: −Q_o n_o;
* centrifugal force +F_c r̂, F_c = ½ m dm ω_c² (Harris 2001 eq 8.9);
* gyroscopic moment.  The ball spins at ω_b = ω_R (cos β x̂ + sin β r̂) in a frame
  turning at ω_c x̂, so dH/dt = ω_c x̂ × J ω_b = J ω_R ω_c sin β t̂: the contacts must
  apply the couple M_g t̂ with M_g = J ω_R ω_c sin β, J = m D²/10, in the β and
  ω_R convention of :func:`thermobear.contact.kinematics.ball_kinematics` (β = −β_Harris,
  hence M_g = −M_g,Harris).  A tangential friction force T e at the outer contact
  point C + (D/2) n_o gives the couple −(D/2) T t̂, at the inner contact point
  C − (D/2) n_i it gives +(D/2) T t̂.  With the share λ_i + λ_o = 2 (outer-raceway
  control λ_o = 2, λ_i = 0) the friction forces on the ball are
  +λ_i (M_g/D) e_i at the inner and −λ_o (M_g/D) e_o at the outer contact.

Ball equilibrium (axial, radial):

    Q_i sin αi − Q_o sin αo + (M_g/D)(λ_i cos αi − λ_o cos αo)      = 0
    Q_i cos αi − Q_o cos αo − (M_g/D)(λ_i sin αi − λ_o sin αo) + F_c = 0

Harris (2001) §8.2 ball equations written with M_g,Harris = −M_g (the signs re-derived here
from the friction couple; tests/test_loads_highspeed.py checks them against dH/dt of the ball).
Inner-ring equilibrium (the inner ring receives −(Q_i n_i + λ_i (M_g/D) e_i) from
each ball; the friction force acts at the contact point, a distance f_i D from
O_i, hence the couple term):

    F_a   = Σ (Q_i sin αi + λ_i (M_g/D) cos αi)
    F_r   = Σ (Q_i cos αi − λ_i (M_g/D) sin αi) cos ψ,        F_z = the same with sin ψ
    M     = Σ [(Q_i sin αi + λ_i (M_g/D) cos αi) ℜ − λ_i f_i M_g] cos ψ,   M_y = the same with sin ψ

(ℜ the tilt arm, ℜ_i by default, :mod:`thermobear.loads.rings`; Harris 2001 §8.2; Harris & Kotzalas 2007 [3] ch. 3; global equations with M_g,Harris = −M_g).  With
outer-raceway control every M_g term leaves the global equations.

Kinematics: one rigid cage.  Every ball orbits at the cage speed ω_c, the Q_i-weighted mean of
the balls' own no-slip orbital speeds (:func:`thermobear.contact.kinematics.ball_kinematics` at each
ball's current α_i, α_o; :func:`thermobear.contact.kinematics.common_cage_speed`), and spins at the
load-weighted least-squares ω_R of :func:`thermobear.contact.kinematics.caged_ball_kinematics`.  Harris's
model lets each ball orbit at its own speed; under combined load at speed those differ by 50 %
and more, and a ball outside the load zone would orbit at the speed its gap's "contact angle"
implies (with a centrifugal force to match).  Every residual is evaluated with the kinematics
recomputed at the iterate, so a converged residual is the fixed point of the coupled problem.

Solver: Newton on the 2Z + ndof unknowns (X per ball; δa, δr, θ, and δz, θ_y when a load leaves the x–y
plane: ndof = 3 or 5) — the 4Z + ndof of Harris with
δi, δo eliminated exactly — vectorised over the balls and a batch of load cases.  The
Jacobian is exact and analytic: contact stiffness matrices, and the derivatives of β, the
balls' own orbital speeds, ω_R, F_c and M_g with respect to α_i, α_o, Q_i, Q_o and the cage
speed (:meth:`thermobear.loads.highspeed_model._HSProblem.direction`); the cage speed, a load-weighted mean over all balls, enters
as one more global unknown whose residual is zero at every iterate, so the per-ball 2×2 blocks
are eliminated in closed form (Schur complement) and one (ndof + 1)² system is solved per case.
Convergence is quadratic.  The iteration is the shared damped Newton of
:mod:`thermobear.loads.newton`; this form's safeguards: a ball's step follows the polar path about the outer
groove centre (a ball resting on the outer race rolls along it instead of being pushed into
it); a ball's step that would close an open contact is shortened to the approach carrying its
own force scale; steps are capped at 0.1 A; a backtracking line search asks for a decrease
against the largest of the last 5 residuals (non-monotone: a light ball changing between
resting, wedged and floating may raise the residual for one step); a light ball whose residual
stalls the line search is re-placed (:func:`thermobear.loads.highspeed_start.relax`).  Start
(:func:`thermobear.loads.highspeed_start.start`): the static solution of
:func:`thermobear.loads.static.load_distribution_static`, loaded balls pushed out by their F_c,
light and out-of-zone balls placed in equilibrium under their F_c and gyroscopic friction with
the rings held (on the outer race or wedged between both races with loads ~F_c).  Past the
tolerance up to two more Newton steps are taken towards tol·10⁻³ (quadratic convergence makes
them cheap; they fix the ill-conditioned positions of balls carrying ~F_c).  A case
that fails is re-solved by continuation in speed; if equilibria exist up to some speed
and not beyond (the branch ends: e.g. outer-raceway control in a thrust bearing, where the
cage speed runs away as α_i passes 90°), NoEquilibrium says so.  For a thrust bearing δr is
held at 0 (the shaft locates the shaft washer radially).  α_o may fall to ≤ 0 at light
load and high speed (contact at the groove bottom) and is returned as such; only a loaded
inner contact at α_i ≤ 0 of an angular contact bearing is refused (NoEquilibrium).  A ball out of contact gets a
vanishing linear "tension" stiffness ε K √A (ε = 1e-12) so that its position stays
defined at n = 0; its contact force is reported as 0 (the force it could carry,
< 1e-9 of the applied load, is below every tolerance).

Cost: a load case is a few hundred numpy calls on Z-element arrays (the call overhead, not the
arithmetic, sets it); a batch of cases costs little more than one.

Film contact law (optional, ``film=dict(eta=..., alpha_p=...)``; prototype, as
:mod:`thermobear.loads.film` is for the low-speed form).  The dry law opens a contact whose
groove-centre distance exceeds the unloaded one; a lubricated contact still carries the
hydrodynamic load of a film as thick as the gap (seed 004, Darul et al. 2024, §5.3.5, §6,
Figs 13, 18, 19: low-loaded balls stay in IVR with a finite rolling force;
validation/report/seed004_film_whatif.md).  With the film each contact c ∈ {i, o} obeys

    δ_c = δ_el,c(Q_c) − h_c(Q_c, α_c),    δ_el,c = (Q_c / K_c)^(2/3),

δ_c = dl_c the signed approach of that contact above (δi, δo; negative: a gap bridged by the
film) [m], K_c the Hertz constant (Harris 2001 eq 7.3 form), h_c the Nijenbanning–Venner–Moes
(1994) central film (:func:`thermobear.lubrication.film.film_thickness_nvm`) at R_x,c(α_c) = (D/2)(1 ∓ D cos α_c
/ d_m), R_y,c, the mean entrainment speed of the caged kinematics u_i = |ω − ω_cage| (d_m/2)(1 −
γ' cos α_i), u_o = ω_cage (d_m/2)(1 + γ' cos α_o) (:func:`thermobear.contact.kinematics.caged_ball_kinematics`,
outer ring fixed), one viscosity η and one α_p (one temperature) per load case, E' of the bearing.
The law is inverted per contact for Q_c > 0 (every contact, every δ_c: no open contacts and no
tension stiffness) by the vectorised bracketed Newton iteration in ln Q of
:func:`thermobear.loads.filmlaw._invert`, warm-started from the loads of the frozen iterate carried to
first order; dQ/dδ = 1/(dδ_el/dQ − dh/dQ) > 0, the film derivative analytic (chain rule through the
NVM blend, :class:`thermobear.loads.filmlaw._NVMFixed`).  In the Jacobian the contact law also carries
∂Q/∂α = −(∂G/∂α) dQ/dδ (G the right-hand side; through R_x and u of the film, analytic; the
α-dependence of K_c with ``stiffness="per_ball"`` is left out, as in the dry law), entering the
contact stiffness matrices, dM_g/dx and dω_cage/dx.  The cage speed in the entrainment speeds is
frozen per Newton step (taken from the iterate, the iterate re-evaluated with it unless the lag is
below 5 % of the iterate's residual; the Jacobian omits ∂h/∂ω_cage), so the converged point is a
fixed point of both, and its lag is reported (``HighSpeedExtras.film_cage_lag``, ~1e-16 at
convergence).  Convergence from the dry solution:
quadratic until the lag dominates, then linear with a factor ~1e-3 (6–12 steps, seed 004 cases).
Start: the dry high-speed solution (open contacts at a load of 1e-9 of the force scale, which the
inversion's bracket expands from); failures are retried by continuation in viscosity.  At small n
(F_c, M_g → 0) the ball equilibrium forces Q_i = Q_o on one line, δ_i + δ_o = s, and the law
becomes that of :mod:`thermobear.loads.film` (δ_el,i + δ_el,o = (Q/K_n)^(2/3)).
Approximations: one temperature for all films, fully flooded inlets, the central NVM film carries
the load (fitted for films thin against R_x), no thermal or starvation reduction.

References
----------
.. [1] Jones, A. B. (1960). A general theory for elastically constrained ball and radial roller
   bearings under arbitrary load and speed conditions. *J. Basic Eng.* 82(2):309–320.
.. [2] Harris, T. A. (2001). *Rolling Bearing Analysis*, 4th ed., Wiley, ch. 8 (§8.2 ball
   equilibrium; eq 8.9 centrifugal force, eq 8.34 gyroscopic moment, eqs 8.60–8.66).
.. [3] Harris, T. A. & Kotzalas, M. N. (2007). *Advanced Concepts of Bearing Technology* (Rolling
   Bearing Analysis, 5th ed.), CRC Press, ch. 3 (high-speed ball bearings).
.. [4] Darul, Ł. et al. (2024). *Lubricants* 12:14 (seed 004), §5.3.5, §6.
.. [5] Nijenbanning, G., Venner, C. H. & Moes, H. (1994). *Wear* 176(2):217–229.
"""
from __future__ import annotations

from dataclasses import dataclass, fields, replace

import numpy as np

from thermobear.contact.geometry import BallBearing
from thermobear.errors import InputError, NoConvergence, NoEquilibrium
from thermobear.loads.filmlaw import FilmInputs, _FilmLaw, film_inputs
from thermobear.loads.highspeed_model import _HSProblem
from thermobear.loads.highspeed_start import start as _start
from thermobear.loads.highspeed_start import static_start
from thermobear.loads.newton import NewtonOptions, continuation, newton
from thermobear.loads.rings import (LoadDistribution, arm_length, azimuths, check_stiffness, force_scale, ring_loads,
                                    unbatch)
from thermobear.loads.static import load_distribution_static

__all__ = ["HighSpeedExtras", "FilmInputs", "load_distribution_high_speed", "load_distribution_high_speed_full",
           "HS_CONTROLS"]

#: raceway-control hypotheses: name -> (λ_i, λ_o, control passed to ball_kinematics for β)
HS_CONTROLS = {"outer": (0.0, 2.0, "outer"), "inner": (2.0, 0.0, "inner"), "both": (1.0, 1.0, "outer")}
_ALIASES = {"none": "both"}
_MAXIT = 100
_STEP_CAP = 0.1         # largest Newton move of a ball centre or ring per step, in units of A
_POLISH = 2             # Newton steps allowed after the tolerance is met, towards tol·1e-3
_NONMONOTONE = 5        # line search: sufficient decrease against the largest of the last 5 norms
_SPEED_STEPS = np.linspace(0.0, 1.0, 11)[1:]   # continuation in speed (fractions of n)
_ETA_STEPS = (1e-6, 1e-4, 1e-2, 1e-1, 1.0)    # continuation in viscosity of the film stage (fractions of η)
_CHUNK = 512            # cases solved together (a larger batch goes a chunk at a time: its results are the same)


@dataclass(frozen=True)
class HighSpeedExtras:
    """Per-ball quantities of the high-speed solution (leading batch axis as the loads, last axis Z).

    Attributes
    ----------
    Fc : ball centrifugal force ½ m dm ω_c² [N]
    Mg : gyroscopic moment J ω_R ω_c sin β [N m] (β, ω_R in the kinematics convention; = −M_g,Harris)
    omega_c : cage (orbital) speed [rad/s]
    omega_R : ball spin speed relative to the cage [rad/s] (signed)
    beta : pitch angle of the ball axis [rad] (β = −β_Harris)
    X1, X2 : axial / radial position of the ball centre from the outer groove curvature centre [m]
    delta_i, delta_o : elastic approach at the inner / outer contact [m]; negative = gap
    lambda_i, lambda_o : share of the gyroscopic moment taken by each raceway [-]
    control : raceway-control hypothesis ("outer", "inner" or "both")
    n_rpm : inner-ring speed [rpm]

    With the film contact law (``film=...``; ``None`` otherwise):

    h_i, h_o : NVM central film of the inner / outer contact at the solution [m]
    delta_el_i, delta_el_o : elastic (Hertz) approach (Q/K)^(2/3) of each contact [m]
        (``delta_i`` = ``delta_el_i`` − ``h_i``: the signed approach, negative across a film-bridged gap)
    u_i, u_o : mean entrainment speeds at which the films were evaluated [m/s]
    film_law_residual : max |δ_el − h − δ| / (δ_el + h) over the contacts [-]
    film_cage_lag : |ω_cage − ω_cage,frozen| / ω between the cage speed of the solution and the one the
        entrainment speeds were frozen at in the last Newton step [-]
    """

    Fc: np.ndarray
    Mg: np.ndarray
    omega_c: np.ndarray
    omega_R: np.ndarray
    beta: np.ndarray
    X1: np.ndarray
    X2: np.ndarray
    delta_i: np.ndarray
    delta_o: np.ndarray
    lambda_i: float
    lambda_o: float
    control: str
    n_rpm: np.ndarray
    h_i: np.ndarray = None
    h_o: np.ndarray = None
    delta_el_i: np.ndarray = None
    delta_el_o: np.ndarray = None
    u_i: np.ndarray = None
    u_o: np.ndarray = None
    film_law_residual: float = None
    film_cage_lag: float = None


def _check_options(control, stiffness, tol, maxiter):
    if not isinstance(control, str) or _ALIASES.get(control, control) not in HS_CONTROLS:
        raise InputError("control", control, f"must be one of {', '.join(HS_CONTROLS)} (or 'none' = 'both')")
    check_stiffness(stiffness)
    if not (isinstance(tol, (int, float)) and 0.0 < tol < 1e-3):
        raise InputError("tol", tol, "relative residual tolerance must lie in (0, 1e-3)")
    if not (isinstance(maxiter, (int, np.integer)) and maxiter >= 1):
        raise InputError("maxiter", maxiter, "must be an integer >= 1")


def load_distribution_high_speed_full(brg: BallBearing, Fa=0.0, Fr=0.0, M=None, n_rpm=0.0, *, Fz=0.0, My=None,
                                      control: str = "outer", stiffness: str = "nominal",
                                      tol: float = 1e-10, maxiter: int = _MAXIT, film=None,
                                      tilt_arm: str = "groove", start=None):
    r"""High-speed quasi-static load distribution with the per-ball details.

    Parameters
    ----------
    brg : BallBearing
    Fa : array_like      axial load on the inner ring [N], ≥ 0
    Fr : array_like      radial load on the inner ring along y (towards ψ = 0) [N]
    M : array_like       moment in the x–y plane [N m]; ``M`` and ``My`` ``None`` hold the tilts at 0
    n_rpm : array_like   inner-ring speed [rpm], ≥ 0 (outer ring fixed); broadcast with the loads
    Fz, My : array_like  radial load along z (ψ = 90°) [N] and moment about +y [N m]
                         (:func:`thermobear.loads.load_distribution_static`; axes in :mod:`thermobear.loads.rings`)
    control : str       raceway control of the gyroscopic moment: ``"outer"`` (Jones: λ_o = 2,
                        λ_i = 0, β from zero spin at the outer contact), ``"inner"`` (λ_i = 2,
                        λ_o = 0, β from the inner contact) or ``"both"`` (alias ``"none"``:
                        λ_i = λ_o = 1; β taken from the outer-control formula — a choice: the
                        split leaves β undetermined without a friction model)
    stiffness : str     ``"nominal"`` (K_i, K_o at the nominal contact angle, as the low-speed
                        default) or ``"per_ball"`` (K_i(α_i), K_o(α_o) at each ball's angles)
    tol : float         relative residual (forces / largest applied load) at which Newton stops
    maxiter : int       Newton iterations per attempt
    film : dict or FilmInputs, optional
                        ``dict(eta=..., alpha_p=...)`` [Pa s, 1/Pa] (scalars or one per load case):
                        the lubricant film in each contact's law, δ_c = δ_el,c(Q_c) − h_c(Q_c)
                        (module docstring, "Film contact law"); needs n_rpm > 0.  ``None`` (default):
                        dry Hertz contacts.
    tilt_arm : str      ``"groove"`` (ℜ_i, default) or ``"pitch"`` (d_m/2): :data:`thermobear.loads.rings.TILT_ARMS`
    start : (LoadDistribution, HighSpeedExtras), optional
                        a solution of these same cases or of nearby ones (this function, same options, the same
                        batch shape).  With ``film`` (the start dry, or with the film at other lubricant data): the
                        film solve starts from it instead of solving the dry contacts (its iterations are counted
                        as those of the dry solve).  Without: Newton starts from it instead of from the static
                        solution (e.g. the last step's answer of an outer iteration on the loads; the static
                        solve's refusals are not made then: a converged case has its equilibrium); where it does
                        not bring every case of the batch to ``tol``, the batch is solved from the static start
                        as without it.  Ignored where a case has no load at all

    Returns
    -------
    (LoadDistribution, HighSpeedExtras)
        ``Q_i ≠ Q_o`` and ``alpha_i ≠ alpha_o`` at speed; ``residual`` is the largest relative
        force residual of all ball and ring equations, ``iterations`` the Newton iterations
        (with the film: those of the dry solve plus those of the film solve).  With the film
        every contact has Q > 0, and the extras carry the films, the elastic approaches and the
        entrainment speeds.

    Raises
    ------
    InputError       bad option or negative / non-finite speed or load
    NoEquilibrium    loads the bearing cannot carry (from the low-speed check), or a loaded
                     angular-contact ball whose contact angle would fall to ≤ 0
    NoConvergence    Newton (with continuation in speed) did not reach the tolerance; with the film,
                     the film solve from the dry solution (direct, then by continuation in viscosity)
                     did not, or a contact's film law could not be inverted

    Notes
    -----
    Jones (1960); Harris (2001) §8.2–8.3 (eqs 8.9 F_c, 8.34 M_g, 8.60–8.66 equilibrium); Harris &
    Kotzalas (2007) ch. 3.  Equations, sign derivation and solver: module docstring.
    At n = 0 the solution equals :func:`thermobear.loads.load_distribution`.

    Examples
    --------
    7210 (α0 = 40°) under 450 N axial load at 20 000 rpm: the centrifugal force (443 N) exceeds
    the static ball load (≈ 45 N); α_o falls to 2.7°, α_i rises to 59°, Q_o ≫ Q_i.

    >>> from thermobear.contact.geometry import bearing
    >>> ld, ex = load_distribution_high_speed_full(bearing("7210"), Fa=450.0, n_rpm=20000.0)
    >>> [round(float(np.rad2deg(a[0])), 1) for a in (ld.alpha_i, ld.alpha_o)]
    [59.4, 2.7]
    >>> round(float(ld.Q_i[0]), 1), round(float(ld.Q_o[0]), 1), round(float(ex.Fc[0]), 1)
    (34.8, 461.5, 442.8)

    With the film contact law (mineral oil at 50 °C, seed 004), Fa 450 N, Fr 750 N at 4800 rpm: the dry
    solution leaves two inner contacts open, the film law loads every contact.

    >>> b = bearing("7210")
    >>> dry = load_distribution_high_speed(b, 450.0, 750.0, n_rpm=4800.0)
    >>> wet = load_distribution_high_speed(b, 450.0, 750.0, n_rpm=4800.0, film=dict(eta=0.0221, alpha_p=2e-8))
    >>> int((dry.Q_i > 0).sum()), int((wet.Q_i > 0).sum()), wet.residual < 1e-10
    (13, 15, True)
    """
    _check_options(control, stiffness, tol, maxiter)
    control = _ALIASES.get(control, control)
    n_in = np.asarray(n_rpm, dtype=float)
    if np.any(~np.isfinite(n_in)) or np.any(n_in < 0):
        raise InputError("n_rpm", n_rpm, "inner-ring speed must be finite and >= 0 [rpm] (outer ring fixed)")
    loads = ring_loads(brg, Fa, Fr, M, Fz, My, extra=(n_in,))
    shape, n_b = loads.shape, loads.extra[0]
    arm_length(brg, tilt_arm)                    # (checks tilt_arm before any solve)
    if film is not None:
        f_eta, f_ap = film_inputs(film, shape)
        if np.any(n_b <= 0):
            raise InputError("n_rpm", n_rpm, "must be > 0 with the film contact law (a film needs entrainment; "
                             "at n = 0 the contacts are dry: film=None)")
    if film is None:
        f_eta = f_ap = None
    nb = loads.nb
    z0 = None if start is None else _dry_start(brg, loads, start, arm_length(brg, tilt_arm))
    if nb <= _CHUNK:
        ld, ex = _solve(brg, loads, n_b, f_eta, f_ap, stiffness, control, tol, maxiter, tilt_arm, z0)
    else:       # independent cases: solved a chunk at a time (numpy's temporaries stay small and in the cache)
        parts = [_solve(brg, loads.rows(np.arange(k, min(k + _CHUNK, nb))), n_b[k:k + _CHUNK],
                        None if film is None else f_eta[k:k + _CHUNK], None if film is None else f_ap[k:k + _CHUNK],
                        stiffness, control, tol, maxiter, tilt_arm,
                        None if z0 is None else (z0[0][k:k + _CHUNK], z0[1][k:k + _CHUNK]))
                 for k in range(0, nb, _CHUNK)]
        ld, ex = (_merge([p[j] for p in parts]) for j in (0, 1))
    return _reshape(ld, shape, Fa, Fr), _reshape(ex, shape)


def _dry_start(brg, loads, start, R):
    """(z (nb, ndof + 2Z), iterations (nb,)) of a solution ``start`` = (LoadDistribution, HighSpeedExtras) of the
    flat batch ``loads`` (:func:`load_distribution_high_speed_full`), or None where it does not fit it."""
    ld, ex = start
    nb, Z, A, ng = loads.nb, brg.Z, brg.A, loads.ndof
    if np.any(np.max(np.abs(loads.F), axis=1) == 0.0) or np.shape(ex.X1) != loads.shape + (Z,):
        return None                  # (no load: the result reports the rings at 0, not where they were held)
    flat = [np.reshape(np.asarray(v, float), nb) for v in (ld.delta_a, ld.delta_r, ld.theta, ld.delta_z, ld.theta_y)]
    g = np.stack([flat[0] / A, flat[1] / A, flat[2] * R / A, flat[3] / A, flat[4] * R / A][:ng], axis=1)
    z = np.concatenate([g, np.reshape(ex.X1, (nb, Z)) / A, np.reshape(ex.X2, (nb, Z)) / A], axis=1)
    return z, np.full(nb, int(ld.iterations))


def _solve(brg, loads, n_b, f_eta, f_ap, stiffness, control, tol, maxiter, tilt_arm, z_start=None):
    """The solution of a flat batch of cases (:class:`thermobear.loads.rings.RingLoads`, speeds ``n_b``):
    (LoadDistribution, HighSpeedExtras) with a leading axis; ``z_start``: (unknowns, iterations) of a given start
    (:func:`_dry_start`): with the film, the dry solution; without, a nearby one Newton starts from."""
    R = arm_length(brg, tilt_arm)
    opt = NewtonOptions(tol=tol, maxiter=maxiter, step_cap=_STEP_CAP, window=_NONMONOTONE, polish=_POLISH)
    Fa_b, Fr_b = loads.Fa, loads.Fr
    pb = None if z_start is None else _hs_problem(brg, loads, n_b, stiffness, control, R)
    warm = None if z_start is None or f_eta is not None else newton(pb, z_start[0].copy(), opt)   # dry, from nearby
    if warm is not None and np.all(warm.converged):     # (else the static start, as without a start)
        z, st, norm, its = warm.z, warm.state, warm.norm, warm.iterations
    elif z_start is not None and f_eta is not None:
        z, its = z_start[0].copy(), z_start[1].copy()
        st = pb.evaluate(z)
        norm = st.norm
    else:
        # low-speed solution: NoEquilibrium cases, and the start
        F = loads.F
        ls = load_distribution_static(brg, F[:, 0], F[:, 1], F[:, 2] if loads.tilt_free else None, Fz=F[:, 3],
                                      My=F[:, 4] if loads.tilt_free else None, stiffness=stiffness, tilt_arm=tilt_arm)
        pb, z0 = _problem(brg, ls, loads, n_b, stiffness, control, R)
        z, st, norm, its = _solve_dry(pb, z0, opt, loads, n_b, control)
    if f_eta is not None:
        z, st, norm, its = _film_stage(pb, z, st, its, f_eta, f_ap, opt, loads, n_b)
    lam_i = pb.lam_i
    if lam_i != 0.0:
        # a converged point where the gyroscopic friction alone carries F_a has every inner contact
        # open (friction without a normal load): the degenerate end of the branch, no equilibrium
        gyro = (lam_i * st.Mg / brg.D * st.n[:, 2 * brg.Z:3 * brg.Z]).sum(1)
        bad = (n_b > 0) & (Fa_b > 0) & (gyro >= Fa_b * (1.0 - 1e-6))
        if np.any(bad):
            k = int(np.argmax(bad))
            raise NoEquilibrium(
                f"control = '{control}' at Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, n = {n_b[k]:g} rpm: the gyroscopic "
                f"friction the inner raceway must supply pushes the inner ring axially with {gyro[k]:.4g} N >= Fa; "
                "no positive contact loads balance it. Use control = 'outer' or a larger axial load",
                iterations=int(its[k]), residual=float(norm[k]))
    return _results(pb, z, st, norm, its, loads, n_b, control, f_eta is not None)


def _merge(parts):
    """One result (LoadDistribution or HighSpeedExtras) of a flat batch from the results of its chunks."""
    first, out = parts[0], {}
    for f in fields(first):
        v = getattr(first, f.name)
        if f.name in ("psi", "lambda_i", "lambda_o", "control", "Fa", "Fr") or v is None:
            out[f.name] = v
        elif f.name in ("residual", "film_law_residual", "film_cage_lag"):
            out[f.name] = max(getattr(p, f.name) for p in parts)
        elif f.name == "iterations":
            out[f.name] = max(p.iterations for p in parts)
        else:
            out[f.name] = np.concatenate([getattr(p, f.name) for p in parts])
    return replace(first, **out)


def _reshape(res, shape, Fa=None, Fr=None):
    """A flat result (leading axis nb) in the loads' shape (floats / (Z,) arrays for scalar loads)."""
    out = {}
    for f in fields(res):
        v = getattr(res, f.name)
        if isinstance(v, np.ndarray) and f.name not in ("psi", "Fa", "Fr"):
            out[f.name] = unbatch(shape, v, v.ndim == 2)
    if Fa is not None:
        out["Fa"], out["Fr"] = np.asarray(Fa, dtype=float), np.asarray(Fr, dtype=float)
    return replace(res, **out)


def _hs_problem(brg, loads, n_b, stiffness, control, R):
    """The high-speed problem of a batch (:class:`thermobear.loads.highspeed_model._HSProblem`); ``R`` the tilt
    arm [m]."""
    lam_i, lam_o, kin_control = HS_CONTROLS[control]
    nb = loads.nb
    F_app = loads.applied(R)
    omega = n_b * np.pi / 30.0
    w_c0 = 0.5 * omega * (1.0 - brg.gamma(brg.alpha0))
    Fc0 = 0.5 * brg.ball_mass * brg.dm * w_c0**2
    load_max = np.max(np.abs(F_app), axis=1)
    zero = load_max == 0.0
    scale = np.maximum(np.maximum(force_scale(brg, F_app), Fc0), 1e-300)
    free_g = np.tile(loads.free(), (nb, 1))
    if brg.kind == "thrust":
        # the shaft washer is located radially by the shaft (Fr = 0 is enforced): hold δr = 0.
        # At speed the balls thrown outwards give the washer a negative radial stiffness, so a
        # free δr would only find the symmetric solution by accident.
        free_g[:, 1::2] = 0.0                                           # δr (and δz)
        if np.any(zero & (n_b > 0)):
            k = int(np.argmax(zero & (n_b > 0)))
            raise NoEquilibrium(
                f"a thrust ball bearing at n = {n_b[k]:g} rpm needs an axial load (minimum load): with Fa = 0 the "
                "centrifugal force throws the balls outwards and nothing holds them between the washers")
    free_g[zero] = 0.0                       # no load: the rings stay centred, only the balls move
    return _HSProblem(brg, F_app, scale, omega, free_g, stiffness, lam_i, lam_o, kin_control, R)


def _problem(brg, ls, loads, n_b, stiffness, control, R):
    """The high-speed problem of a batch and its unknowns at the static solution ``ls`` (rings there, balls
    on the lines of groove centres); ``R`` the tilt arm [m]."""
    pb = _hs_problem(brg, loads, n_b, stiffness, control, R)
    A, nb, ng = brg.A, loads.nb, loads.ndof
    zero = np.max(np.abs(pb.F_app), axis=1) == 0.0
    g0 = np.zeros((nb, ng))
    g0[:, 0] = np.reshape(ls.delta_a, nb) / A
    if brg.kind == "thrust":
        # unloaded thrust bearing: washers just touching the balls (the centred position
        # would put both groove centres on one point)
        g0[zero, 0] = np.sin(brg.alpha0)
    g0[:, 1] = np.reshape(ls.delta_r, nb) / A
    g0[:, 2] = np.reshape(ls.theta, nb) * R / A
    if ng == 5:
        g0[:, 3] = np.reshape(ls.delta_z, nb) / A
        g0[:, 4] = np.reshape(ls.theta_y, nb) * R / A
    return pb, static_start(pb, g0)


def _solve_dry(pb, z0, opt, loads, n_b, control):
    """Dry contacts: Newton from the placed start; the cases that fail again by continuation in speed from
    the static solution.  Returns (z, state, residual, iterations) or raises (NoEquilibrium where the
    branch of equilibria ends, NoConvergence)."""
    zs = _start(pb, z0) if np.any(pb.omega > 0) else z0
    r = newton(pb, zs, opt)
    z, st, norm, its, done = r.z, r.state, r.norm, r.iterations, r.converged
    if not np.all(done):
        _diagnose(pb, z, done, loads, n_b, its, norm, zs)
    if not np.all(done) and np.any(n_b[~done] > 0):
        # continuation in speed for the failed cases, warm-started from the static solution; a case that
        # fails at some speed fraction stops there (its branch of equilibria ends)
        idx = np.flatnonzero(~done)

        def solve(rows, zz, frac, stage):
            sub = pb.rows(idx[rows])
            sub.set_cases(sub.F_app, sub.scale, sub.omega * frac, sub.free_g)
            return newton(sub, _start(sub, zz) if stage == 0 else zz, opt)

        c = continuation(solve, z0[idx], np.tile(_SPEED_STEPS, (idx.size, 1)))
        fin = c.ok
        z = z.copy()
        z[idx[fin]] = c.z[fin]
        norm = norm.copy()
        norm[idx] = c.norm
        done[idx[fin]] = True
        its[idx] += c.iterations
        st = pb.evaluate(z)
        fold = ~fin & (c.reached >= 0)
        if np.any(fold):
            j = int(np.flatnonzero(fold)[0])
            k = int(idx[j])
            A = pb.A
            raise NoEquilibrium(
                f"no high-speed equilibrium at n = {n_b[k]:g} rpm for {loads.case(k)} "
                f"(control = '{control}'): continuation in speed found equilibria up to "
                f"{_SPEED_STEPS[c.reached[j]] * n_b[k]:.4g} rpm, then none — the centrifugal and gyroscopic loads "
                "outgrow what the contacts can balance (e.g. the cage speed runs away when a raceway-control "
                "hypothesis no longer fits the contact angles); raise the axial load or preload, or check the "
                "control hypothesis", iterations=int(its[k]), residual=float(c.norm[j]), last=c.z[j] * A)
    if not np.all(done):
        _diagnose(pb, z, done, loads, n_b, its, norm)
        k = int(np.argmax(np.where(done, -np.inf, np.nan_to_num(norm, nan=np.inf))))
        raise NoConvergence(
            f"high-speed load distribution did not reach equilibrium for {loads.case(k)}, "
            f"n = {n_b[k]:g} rpm: relative residual {norm[k]:.3g} after {its[k]} Newton "
            "iterations (direct and with continuation in speed)",
            iterations=int(its[k]), residual=float(norm[k]), last=z[k] * pb.A)
    return z, st, norm, its


def _film_stage(pb, z, st0, its, eta, ap, opt, loads, n_b):
    r"""Film stage: Newton on the film contact law, started from the dry solution (z, state ``st0``).

    The warm-start loads are the dry ones (an open contact starts at 1e-9 of the force scale; the
    inversion's bracket expands from there), the frozen cage speed the dry one.  Cases that fail are
    re-solved from the dry solution by continuation in viscosity, η·(1e-6, 1e-4, 1e-2, 0.1, 1): at
    η·1e-6 the films are ~1e-4 of the final ones (h ∝ η^0.6–0.7 in the EHL regimes, ∝ η in IVR)."""
    Q0 = np.maximum(st0.Q, 1e-9 * pb.scale[:, None])
    pb.film = _FilmLaw(pb.brg, eta, ap)
    pb.fz = {"W": st0.W.copy(), "Q": Q0}
    z0, W0 = z.copy(), st0.W.copy()
    r = newton(pb, z, opt)
    z, st, norm, done = r.z, r.state, r.norm, r.converged
    its = its + r.iterations
    if not np.all(done):
        idx = np.flatnonzero(~done)
        fzW, fzQ = W0[idx], Q0[idx]

        def solve(rows, zz, frac, stage):
            sub = pb.rows(idx[rows])
            sub.film = _FilmLaw(pb.brg, eta[idx[rows]] * np.reshape(frac, (-1, 1)), ap[idx[rows]])   # (rows, 1)
            sub.fz = {"W": fzW[rows].copy(), "Q": fzQ[rows].copy()}
            out = newton(sub, zz, opt)
            fzW[rows], fzQ[rows] = out.state.W, out.state.Q
            return out

        c = continuation(solve, z0[idx], np.tile(_ETA_STEPS, (idx.size, 1)))
        its[idx] += c.iterations
        if c.ok.any():
            rows_last, st_last = c.states[len(_ETA_STEPS) - 1]
            ok = c.ok[rows_last]
            k = idx[rows_last[ok]]
            z = z.copy()
            z[k] = c.z[rows_last[ok]]
            st.put(k, st_last.take(np.flatnonzero(ok)))
            norm = st.norm
            done = norm <= opt.tol
    if not np.all(done):
        k = int(np.argmax(np.where(done, -np.inf, np.nan_to_num(norm, nan=np.inf))))
        raise NoConvergence(
            f"high-speed load distribution with the film contact law did not reach equilibrium for "
            f"{loads.case(k)}, n = {n_b[k]:g} rpm: relative residual "
            f"{norm[k]:.3g} after {its[k]} Newton iterations (from the dry solution, then by continuation in "
            "viscosity)" + ("; with this raceway-control hypothesis every ball, also one across a film-bridged "
                           "gap, must take gyroscopic friction at the inner race — try control = 'outer'"
                           if pb.lam_i != 0.0 else ""), iterations=int(its[k]), residual=float(norm[k]),
            last=z[k] * pb.A)
    return z, st, norm, its


def _diagnose(pb, z, done, loads, n_b, its, norm, z_start=None):
    """Raise NoEquilibrium for an unconverged case whose load cannot balance the friction the
    control hypothesis demands from the inner raceway (the inner ring receives Σ λ_i (M_g/D) cos α_i
    axially from the gyroscopic friction; when that reaches F_a — at the last iterate or at the start
    ``z_start`` — Q_i sin α_i would have to be < 0: checked first, it is the cause), or whose loaded balls
    were driven over the low shoulder of an angular contact bearing (α_i ≤ 0)."""
    st = pb.evaluate(z)
    Fa_b, Fr_b = loads.Fa, loads.Fr
    if pb.lam_i != 0.0:
        Z = pb.Z
        gyro = (pb.lam_i * st.Mg / pb.brg.D * st.n[:, 2 * Z:3 * Z]).sum(1)
        if z_start is not None:
            s0 = pb.evaluate(z_start)
            gyro = np.fmax(gyro, (pb.lam_i * s0.Mg / pb.brg.D * s0.n[:, 2 * Z:3 * Z]).sum(1))
        bad = ~done & (gyro >= np.maximum(Fa_b, 0.0)) & (n_b > 0)
        if np.any(bad):
            k = int(np.argmax(bad))
            raise NoEquilibrium(
                f"control = '{'inner' if pb.lam_o == 0 else 'both'}' at Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, "
                f"n = {n_b[k]:g} rpm: the gyroscopic friction the inner raceway must supply pushes the inner ring "
                f"axially with {gyro[k]:.4g} N >= Fa; no positive contact loads balance it. Use control = 'outer' "
                "or a larger axial load", iterations=int(its[k]), residual=float(norm[k]))
    if pb.brg.kind == "angular_contact":
        Z = pb.Z
        bad = ~done & np.any((st.dl[:, :Z] > 0) & (np.arctan2(st.V[:, :Z], st.V[:, 2 * Z:3 * Z]) <= 0), axis=1)
        if np.any(bad):
            k = int(np.argmax(bad))
            raise NoEquilibrium(
                f"angular contact bearing at Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, n = {n_b[k]:g} rpm: no "
                "equilibrium with positive inner contact angles (the balls would run over the low shoulder); "
                "raise the axial load or preload", iterations=int(its[k]), residual=float(norm[k]))


def _results(pb, z, st, norm, its, loads, n_b, control, with_film):
    """LoadDistribution and HighSpeedExtras at the solution, flat (leading axis: the cases; ``loads``: the
    :class:`thermobear.loads.rings.RingLoads` of the batch, ``n_b`` its speeds [rpm])."""
    Fa_b, Fr_b = loads.Fa, loads.Fr
    brg, A, R, Z = pb.brg, pb.A, pb.R, pb.Z
    zero = np.max(np.abs(pb.F_app), axis=1) == 0.0
    Z2 = 2 * Z
    if with_film:
        Qi, Qo = st.Q[:, :Z], st.Q[:, Z:]
    else:
        Q = np.where(st.dl > 0, st.Q, 0.0)
        Qi, Qo = Q[:, :Z], Q[:, Z:]
    al = np.arctan2(st.V[:, :Z2], st.V[:, Z2:])
    a_i, a_o = al[:, :Z], al[:, Z:]
    if brg.kind == "angular_contact" and np.any((Qi > 0) & (a_i <= 0)):
        k = int(np.argmax(np.any((Qi > 0) & (a_i <= 0), axis=1)))
        raise NoEquilibrium(
            f"angular contact bearing at Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, n = {n_b[k]:g} rpm: a loaded "
            "ball's inner contact angle would be <= 0 (contact over the low shoulder); raise the axial load "
            "or preload", iterations=int(its[k]), residual=float(norm[k]))
    free = (Qi == 0) & (Qo == 0)
    if brg.kind != "deep_groove":
        a_i, a_o = np.where(free, brg.alpha0, a_i), np.where(free, brg.alpha0, a_o)
    else:
        a_i, a_o = np.where(zero[:, None] & free, 0.0, a_i), np.where(zero[:, None] & free, 0.0, a_o)
    dl = st.d_el if with_film else np.maximum(st.dl, 0.0)
    dn = dl[:, :Z] + dl[:, Z:]
    g = np.zeros((z.shape[0], 5))
    g[:, :pb.ng] = z[:, :pb.ng]
    ones = np.ones((z.shape[0], Z))

    def sh(v):
        return np.array(v, dtype=float)

    shz = sh
    ld = LoadDistribution(
        delta_a=sh(np.where(zero, 0.0, g[:, 0] * A)), delta_r=sh(np.where(zero, 0.0, g[:, 1] * A)),
        theta=sh(np.where(zero, 0.0, g[:, 2] * A / R)), Q_i=shz(Qi), Q_o=shz(Qo), alpha_i=shz(a_i),
        alpha_o=shz(a_o), psi=azimuths(Z), delta_n=shz(dn), residual=float(norm.max()) if norm.size else 0.0,
        iterations=int(its.max()) if its.size else 0, Fa=Fa_b, Fr=Fr_b, M=sh(loads.M),
        delta_z=sh(np.where(zero, 0.0, g[:, 3] * A)), theta_y=sh(np.where(zero, 0.0, g[:, 4] * A / R)),
        Fz=sh(loads.F[:, 3]), My=sh(loads.F[:, 4]))
    ex = HighSpeedExtras(
        Fc=shz(st.Fc * ones), Mg=shz(st.Mg), omega_c=shz(st.W * ones), omega_R=shz(st.wR),
        beta=shz(np.arctan2(-st.msb, st.cb)), X1=shz(st.X1), X2=shz(st.X2),
        delta_i=shz(st.dl[:, :Z]), delta_o=shz(st.dl[:, Z:]), lambda_i=pb.lam_i, lambda_o=pb.lam_o,
        control=control, n_rpm=sh(n_b))
    if with_film:
        u = st.f_v * (0.5 * brg.dm) * (1.0 + np.repeat([-1.0, 1.0], Z) * (brg.D / brg.dm) * np.cos(st.f_al))
        ex = replace(ex, h_i=shz(st.h[:, :Z]), h_o=shz(st.h[:, Z:]),
                     delta_el_i=shz(st.d_el[:, :Z]), delta_el_o=shz(st.d_el[:, Z:]),
                     u_i=shz(u[:, :Z]), u_o=shz(u[:, Z:]),
                     film_law_residual=float(st.f_rel.max()),
                     film_cage_lag=float(np.max(np.abs(st.W - st.fz_W)[:, 0] / pb.omega)))
    return ld, ex


def load_distribution_high_speed(brg: BallBearing, Fa=0.0, Fr=0.0, M=None, n_rpm=0.0, *, Fz=0.0, My=None,
                                 control: str = "outer", stiffness: str = "nominal",
                                 tol: float = 1e-10, maxiter: int = _MAXIT, film=None,
                                 tilt_arm: str = "groove", start=None) -> LoadDistribution:
    r"""High-speed quasi-static load distribution (Jones 1960; Harris 2001 ch. 8).

    Same parameters as :func:`load_distribution_high_speed_full`; returns only the
    :class:`thermobear.loads.LoadDistribution` (centrifugal forces, gyroscopic moments,
    ball speeds and positions are in the ``_full`` variant).

    Examples
    --------
    At n = 0 it is the low-speed solution:

    >>> from thermobear.contact.geometry import bearing
    >>> from thermobear.loads import load_distribution
    >>> b = bearing("7210")
    >>> hs, ls = load_distribution_high_speed(b, Fa=450.0, Fr=300.0), load_distribution(b, Fa=450.0, Fr=300.0)
    >>> bool(np.allclose(hs.Q_o, ls.Q, rtol=1e-8, atol=1e-9 * 450) and np.allclose(hs.Q_i, hs.Q_o, rtol=1e-8))
    True
    """
    return load_distribution_high_speed_full(brg, Fa, Fr, M, n_rpm, Fz=Fz, My=My, control=control,
                                             stiffness=stiffness, tol=tol, maxiter=maxiter, film=film,
                                             tilt_arm=tilt_arm, start=start)[0]

r"""High-speed quasi-static load distribution of a ball bearing (Jones 1960; Harris 2001 ch. 8).

At speed each ball carries a centrifugal force F_c and a gyroscopic moment M_g,
so the inner and outer contacts no longer share one line of action: α_o falls,
α_i rises and Q_o > Q_i.  Rigid rings, outer ring fixed, inner ring rotating at
n [rpm] and displaced by (δa, δr, θ) exactly as in :mod:`thermobear.loads.static`
(ISO/TS 16281 convention: δa measured from the centred position).

Geometry of ball j (PHYSICS.md §3.3).  x axial (the direction in which F_a
pushes the inner ring), r radial outward through the ball centre; O_o and O_i
the outer and inner groove curvature centres, C the ball centre:

    O_i − O_o = (A1_j, A2_j) = (δa + ℜ_i θ cos ψ_j,  A cos α0 + δr cos ψ_j)
    C − O_o   = (X1_j, X2_j) = ((f_o − ½)D + δo_j)(sin αo_j, cos αo_j)
    O_i − C   = (A1_j − X1_j, A2_j − X2_j) = ((f_i − ½)D + δi_j)(sin αi_j, cos αi_j)

The two distance equations (PHYSICS.md §3.3 eqs 1–2) are explicit in δi, δo,

    δo = |C − O_o| − (f_o − ½)D,     δi = |O_i − C| − (f_i − ½)D,

so they are satisfied identically and the unknowns left per ball are X1, X2;
α_i, α_o are the directions of those two vectors.  Q_i = K_i δi^1.5,
Q_o = K_o δo^1.5.

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

identical to PHYSICS.md §3.3 eqs 3–4 written with M_g,Harris = −M_g (the public
code PHYSICS.md warns about swaps X1/X2 in the radial equation; not copied).
Inner-ring equilibrium (the inner ring receives −(Q_i n_i + λ_i (M_g/D) e_i) from
each ball; the friction force acts at the contact point, a distance f_i D from
O_i, hence the couple term):

    F_a   = Σ (Q_i sin αi + λ_i (M_g/D) cos αi)
    F_r   = Σ (Q_i cos αi − λ_i (M_g/D) sin αi) cos ψ
    M     = Σ [(Q_i sin αi + λ_i (M_g/D) cos αi) ℜ_i − λ_i f_i M_g] cos ψ

(Harris 2001 §8; PHYSICS.md §3.3 global equations with M_g,Harris = −M_g).  With
outer-raceway control every M_g term leaves the global equations.

Kinematics: one rigid cage.  Every ball orbits at the cage speed ω_c, the Q_i-weighted mean of
the balls' own no-slip orbital speeds (:func:`thermobear.contact.kinematics.ball_kinematics` at each
ball's current α_i, α_o; :func:`thermobear.contact.kinematics.common_cage_speed`), and spins at the
load-weighted least-squares ω_R of :func:`thermobear.contact.kinematics.caged_ball_kinematics`.  Harris's
model lets each ball orbit at its own speed; under combined load at speed those differ by 50 %
and more, and a ball outside the load zone would orbit at the speed its gap's "contact angle"
implies (with a centrifugal force to match).  Every residual is evaluated with the kinematics
recomputed at the iterate, so a converged residual is the fixed point of the coupled problem.

Solver: Newton on the 2Z + 3 unknowns (X per ball, δa, δr, θ) — the 4Z + 3 of Harris with
δi, δo eliminated exactly — vectorised over the balls and a batch of load cases.  The
Jacobian is exact and analytic: contact stiffness matrices, and the derivatives of β, the
balls' own orbital speeds, ω_R, F_c and M_g with respect to α_i, α_o, Q_i, Q_o and the cage
speed (:meth:`_Problem.newton_step`); the cage speed, a load-weighted mean over all balls, enters
as a fourth global unknown whose residual is zero at every iterate, so the per-ball 2×2 blocks
are eliminated in closed form (Schur complement) and one 4×4 system is solved per case.
Convergence is quadratic.  Globalisation: a ball's step follows the polar path about the outer
groove centre (a ball resting on the outer race rolls along it instead of being pushed into
it); a ball's step that would close an open contact is shortened to the approach carrying its
own force scale; steps are capped at 0.1 A; a backtracking line search asks for a decrease
against the largest of the last 5 residuals (non-monotone: a light ball changing between
resting, wedged and floating may raise the residual for one step); a light ball whose residual
stalls the line search is re-placed (:func:`_relax`).  Start (:func:`_start`): the static
solution of :func:`thermobear.loads.load_distribution`, loaded balls pushed out by their F_c,
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
:func:`thermobear.loads.film._invert`, warm-started from the loads of the frozen iterate carried to
first order; dQ/dδ = 1/(dδ_el/dQ − dh/dQ) > 0, the film derivative analytic (chain rule through the
NVM blend, :class:`thermobear.loads.film._NVMFixed`).  In the Jacobian the contact law also carries
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
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from functools import lru_cache

import numpy as np

from thermobear.errors import InputError, NoConvergence, NoEquilibrium
from thermobear.contact.geometry import BallBearing
from thermobear.loads.static import STIFFNESS_MODES, LoadDistribution, load_distribution
from thermobear.loads.film import _carry, _FilmAt, _NVMFixed, _invert

__all__ = ["HighSpeedExtras", "FilmInputs", "load_distribution_high_speed", "load_distribution_high_speed_full",
           "HS_CONTROLS"]

#: raceway-control hypotheses: name -> (λ_i, λ_o, control passed to ball_kinematics for β)
HS_CONTROLS = {"outer": (0.0, 2.0, "outer"), "inner": (2.0, 0.0, "inner"), "both": (1.0, 1.0, "outer")}
_ALIASES = {"none": "both"}
_EPS_TENSION = 1e-12    # linear stiffness of an open contact, relative to K √A (numerical regularisation)
_MAXIT = 100
_STEP_CAP = 0.1         # largest Newton move of a ball centre or ring per step, in units of A
_POLISH = 2            # Newton steps allowed after the tolerance is met, towards tol·1e-3
_NONMONOTONE = 5        # line search: sufficient decrease against the largest of the last 5 norms
_BALL_CAP = 0.05        # largest move of a ball centre per step of the per-ball start, in units of A
_BALL_MAXIT = 40        # Newton steps of the per-ball start
_BALL_HALVINGS = 12     # line-search halvings of the per-ball start
_RELAX = 1e-2          # a light ball is re-placed when its residual exceeds this share of its F_c + friction
_BALL_TOL = 1e-4        # per-ball start: force residual relative to the ball's external force
_SGN_E = np.array([1.0, -1.0])                  # (cos α, sin α) -> e = (cos α, −sin α)
_SGN_2 = np.array([[1.0, -1.0], [-1.0, 1.0]])   # cofactor signs of a 2×2 inverse


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


@dataclass(frozen=True)
class FilmInputs:
    """Lubricant data of the film contact law: one temperature for every contact of a load case.

    Attributes
    ----------
    eta : array_like      dynamic viscosity at the inlets [Pa s], > 0 (scalar or one per load case)
    alpha_p : array_like  pressure–viscosity coefficient [1/Pa], ≥ 0 (scalar or one per load case)
    """

    eta: float
    alpha_p: float


class _FilmLaw:
    r"""Film contact law of both contacts of every ball, stacked on a last axis (inner, outer).

    δ_c = (Q_c/K_c)^(2/3) − h_c(Q_c, α_c)   with h_c the NVM central film
    (:func:`thermobear.lubrication.film.film_thickness_nvm`) at R_x,c = (D/2)(1 ∓ γ'cos α_c), R_y,c, the mean
    entrainment speed u_c = v_c (d_m/2)(1 ∓ γ'cos α_c), v = (|ω − ω_cage|, ω_cage) (caged kinematics,
    :func:`thermobear.contact.kinematics.caged_ball_kinematics`, outer ring fixed), one η and α_p per case.
    :meth:`at` gives the law at fixed angles that :func:`thermobear.loads.film._invert` inverts."""

    def __init__(self, brg, eta, alpha_p, K=None, v=None):
        self.brg, self.eta, self.ap, self.K, self.v = brg, eta, alpha_p, K, v
        self.Ep = brg.E_prime
        self.gp = brg.D / brg.dm
        self.sgn = np.array([-1.0, 1.0])
        self.Ry = np.array([brg.Ry_i, brg.Ry_o])

    def take(self, m):
        """The per-case data of a subset of the batch (eta, alpha_p have shape (nb, 1, 1))."""
        return _FilmLaw(self.brg, self.eta[m], self.ap[m])

    def bind(self, K, v):
        """The law with the contact constants K [N/m^1.5] and orbital speed factors v [rad/s] set."""
        return _FilmLaw(self.brg, self.eta, self.ap, K, v)

    def at(self, alpha):
        r"""The law at contact angles α [rad], shape (nb, Z, 2) (:class:`thermobear.loads.film._FilmAt`):
        R_x and u both ∝ 1 ∓ γ'cos α, ∂ln R_x/∂α = ∂ln u/∂α = ±γ' sin α / (1 ∓ γ'cos α); K held."""
        gc = self.sgn * (self.gp * np.cos(alpha))
        fac = 1.0 + gc
        dln = -self.sgn * (self.gp * np.sin(alpha)) / fac
        nvm = _NVMFixed(0.5 * self.brg.D * fac, self.Ry, self.v * (0.5 * self.brg.dm) * fac, self.eta, self.ap,
                        self.Ep)
        return _FilmAt(self.K, nvm, False, dln, dln)


def _film_inputs(film, shape):
    """Validated η [Pa s] and α_p [1/Pa] of ``film`` (mapping or :class:`FilmInputs`), shape (nb, 1, 1)."""
    if isinstance(film, FilmInputs):
        film = {"eta": film.eta, "alpha_p": film.alpha_p}
    if not hasattr(film, "keys") or set(film.keys()) != {"eta", "alpha_p"}:
        raise InputError("film", film, "None, FilmInputs(eta, alpha_p) or a dict with exactly the keys "
                         "'eta' [Pa s] and 'alpha_p' [1/Pa]")
    out = []
    for key, lo in (("eta", "> 0 [Pa s]"), ("alpha_p", ">= 0 [1/Pa]")):
        a = np.asarray(film[key], dtype=float)
        bad = ~np.isfinite(a) | ((a <= 0) if key == "eta" else (a < 0))
        if np.any(bad):
            raise InputError(f"film.{key}", film[key], f"must be finite and {lo}")
        try:
            a = np.broadcast_to(a, shape)
        except ValueError:
            raise InputError(f"film.{key}", film[key], f"must broadcast to the load batch {shape}") from None
        out.append(a.reshape(-1, 1, 1).copy())
    return out


@lru_cache(maxsize=32)
def _stiffness_constants(brg):
    """K_i, K_o at the nominal contact angle [N/m^1.5] and the open-contact regularising stiffness
    ε K_n √A [N/m] of a bearing (cached: a BallBearing is immutable and hashable)."""
    an = brg.alpha_nominal
    return float(brg.K_i(an)), float(brg.K_o(an)), _EPS_TENSION * float(brg.Kn()) * np.sqrt(brg.A)


class _State:
    """Arrays of one Newton iterate, every one with the batch as its leading axis (set by
    :meth:`_Problem.state`)."""

    def take(self, m):
        new = _State.__new__(_State)
        new.__dict__ = {k: v[m] for k, v in self.__dict__.items()}
        return new

    def put(self, m, other):
        for k, v in self.__dict__.items():
            v[m] = other.__dict__[k]


class _Problem:
    """Fixed data of one batch: bearing constants, loads, weights.  Arrays have shape (nb, Z[, ...]).

    For one load case every array is tiny: a solve costs the number of numpy calls, not the
    arithmetic (the hot paths skip masks that are all true and preallocate their stacks)."""

    def __init__(self, brg, F_app, scale, omega, free_g, stiffness, lam_i, lam_o, kin_control):
        self.brg = brg
        self.Z, self.A, self.R = brg.Z, brg.A, brg.R_inner_locus
        self.psi = 2.0 * np.pi * np.arange(brg.Z) / brg.Z
        self.c = np.cos(self.psi)[None, :]
        self.ci0 = (brg.fi - 0.5) * brg.D          # |O_i − C| unloaded [m]
        self.co0 = (brg.fo - 0.5) * brg.D          # |C − O_o| unloaded [m]
        self.A2_0 = self.A * np.cos(brg.alpha0)    # radial groove-centre offset, centred rings [m]
        self.F_app, self.scale, self.free_g = F_app, scale, free_g
        self.omega = omega                          # (nb,) inner-ring speed [rad/s]
        self.w_ref = np.maximum(omega, 1.0)         # (nb,) scale of the cage-speed unknown [rad/s]
        self.stiffness = stiffness
        self.lam_i, self.lam_o, self.kin_control = lam_i, lam_o, kin_control
        self.Ki0, self.Ko0, self.k_eps = _stiffness_constants(brg)
        self.D, self.dm, self.fi = brg.D, brg.dm, brg.fi
        self.gp = brg.D / brg.dm
        self.m = brg.ball_mass
        self.J = self.m * brg.D**2 / 10.0
        # dA/dg / A per ball: Wt = [[1, 0, c], [0, c, 0]] (2×3) and its transpose (3×2)
        c = np.cos(self.psi)
        self.Wt = np.zeros((1, brg.Z, 2, 3))
        self.Wt[0, :, 0, 0] = 1.0
        self.Wt[0, :, 0, 2] = c
        self.Wt[0, :, 1, 1] = c
        self.W = np.swapaxes(self.Wt, -1, -2).copy()
        self.film = None            # _FilmLaw of the film contact law (None: dry Hertz contacts)
        self.fz = None              # film law: frozen cage speed "W" (nb, 1) and warm-start loads "Q" (nb, Z, 2)
        self._prep()

    def _prep(self):
        """Per-case factors of the Newton step (from scale, w_ref and free_g; call again after changing them)."""
        s = self.scale
        self.As = (self.A / s)[:, None, None, None]
        self.wrs = (self.w_ref / s)[:, None, None]
        self.Aw = (self.A / self.w_ref)[:, None, None]
        act = np.ones((s.size, 4))
        act[:, :3] = self.free_g
        self.act = act
        self.act2 = act[:, :, None] * act[:, None, :]
        self.eye_fix = np.eye(4)[None] * (1.0 - act)[:, :, None]

    def centres(self, g):
        """Inner groove-centre offsets A1, A2 [m] from scaled globals g = (δa/A, δr/A, θℜ/A)."""
        A, c = self.A, self.c
        return A * (g[:, 0:1] + g[:, 2:3] * c), self.A2_0 + (A * g[:, 1:2]) * c

    def _contact_force(self, delta, K):
        """Hertz load K δ^1.5 and dQ/dδ at approach δ; an open contact (δ ≤ 0) gets the linear
        tension stiffness k_ε."""
        pos = delta > 0
        if pos.all():
            sq = np.sqrt(delta)
            return K * delta * sq, 1.5 * K * sq
        sq = np.sqrt(np.where(pos, delta, 0.0))
        Q = np.where(pos, K * delta * sq, self.k_eps * delta)
        dQ = np.where(pos, 1.5 * K * sq, self.k_eps)
        return Q, dQ

    def state(self, x, g):
        r"""Everything at scaled unknowns x = X/A (nb, Z, 2) and g (nb, 3).

        Kinematics (:func:`thermobear.contact.kinematics.ball_kinematics`, written with sin α, cos α of the
        contact normals; outer control shown, inner control swaps the roles): tan β = −sin α_o /
        (cos α_o + γ'), γ' = D/dm, contact radii R_o = (dm/2)(1 + γ' cos α_o), R_i = (dm/2)(1 − γ'
        cos α_i), lever arms E = (D/2) cos(α + β); each ball's own no-slip orbital speed
        ω_c,j = ω R_i E_o / (R_o E_i + R_i E_o); cage speed ω_cage = Σ Q_i ω_c,j / Σ Q_i
        (:func:`thermobear.contact.kinematics.common_cage_speed`); ball spin the load-weighted least-squares
        ω_R = −[Q_o E_o R_o ω_cage + Q_i E_i R_i (ω − ω_cage)] / (Q_o E_o² + Q_i E_i²)
        (:func:`thermobear.contact.kinematics.caged_ball_kinematics`; own no-slip −ω R_o R_i / det when
        both contacts are open); F_c = ½ m dm ω_cage², M_g = J ω_R ω_cage sin β."""
        st = _State.__new__(_State)
        A = self.A
        A1, A2 = self.centres(g)
        X1, X2 = A * x[..., 0], A * x[..., 1]
        p, q = A1 - X1, A2 - X2
        d_i, d_o = np.hypot(p, q), np.hypot(X1, X2)
        si, ci, so, co = p / d_i, q / d_i, X1 / d_o, X2 / d_o
        dl_i, dl_o = d_i - self.ci0, d_o - self.co0
        if self.stiffness == "per_ball":
            Ki, Ko = self.brg.K_i(np.arctan2(p, q)), self.brg.K_o(np.arctan2(X1, X2))
        else:
            Ki, Ko = self.Ki0, self.Ko0
        if self.film is None:
            Qi, dQi = self._contact_force(dl_i, Ki)
            Qo, dQo = self._contact_force(dl_o, Ko)
        else:
            Qi, dQi, Qo, dQo, fl = self._film_force(p, q, X1, X2, dl_i, dl_o, Ki, Ko)
        # kinematics of each ball at its own contact angles
        gp, hdm, hD = self.gp, 0.5 * self.dm, 0.5 * self.D
        w = self.omega[:, None]
        if self.kin_control == "outer":
            rb2 = 1.0 + 2.0 * gp * co + gp * gp
            rb = np.sqrt(rb2)
            cb, sb = (co + gp) / rb, -so / rb
            ceo, seo = (1.0 + gp * co) / rb, gp * so / rb                 # cos, sin (α_o + β)
            cei, sei = ci * cb - si * sb, si * cb + ci * sb
        else:
            rb2 = 1.0 - 2.0 * gp * ci + gp * gp
            rb = np.sqrt(rb2)
            cb, sb = (ci - gp) / rb, -si / rb
            cei, sei = (1.0 - gp * ci) / rb, -gp * si / rb
            ceo, seo = co * cb - so * sb, so * cb + co * sb
        Ro, Ri = hdm * (1.0 + gp * co), hdm * (1.0 - gp * ci)
        Eo, Ei = hD * ceo, hD * cei
        det = Ro * Ei + Ri * Eo
        w_own = w * Ri * Eo / det
        wR_own = -w * Ro * Ri / det
        # one cage
        qi, qo = np.maximum(Qi, 0.0), np.maximum(Qo, 0.0)
        qs = qi.sum(1, keepdims=True)
        has = qs > 0
        if has.all():
            wgt = qi / qs
        else:
            wgt = np.where(has, qi / np.where(has, qs, 1.0), 1.0 / self.Z)
        W = (wgt * w_own).sum(1, keepdims=True)                            # (nb, 1)
        den = qo * Eo * Eo + qi * Ei * Ei
        pos = den > 0
        num = -(qo * Eo * Ro * W + qi * Ei * Ri * (w - W))
        if pos.all():
            wR = num / den
        else:
            wR = np.where(pos, num / np.where(pos, den, 1.0), wR_own)
        Fc = 0.5 * self.m * self.dm * W * W                                 # (nb, 1)
        Mg = self.J * wR * W * sb
        # forces on the ball: inner ring Q_i n_i + T_i e_i, outer ring −(Q_o n_o + T_o e_o), e = (cos α, −sin α)
        if self.lam_i:
            Ti = self.lam_i / self.D * Mg
            Fi1, Fi2 = Qi * si + Ti * ci, Qi * ci - Ti * si
        else:
            Fi1, Fi2 = Qi * si, Qi * ci
        if self.lam_o:
            To = self.lam_o / self.D * Mg
            Fo1, Fo2 = Qo * so + To * co, Qo * co - To * so
        else:
            Fo1, Fo2 = Qo * so, Qo * co
        s = self.scale[:, None]
        r_b = np.empty(Fi1.shape + (2,))
        np.subtract(Fi1, Fo1, out=r_b[..., 0])
        np.add(Fi2 - Fo2, Fc, out=r_b[..., 1])
        r_b /= s[..., None]
        c = self.c
        Fx = Fi1 - (self.lam_i * self.fi / self.R) * Mg if self.lam_i else Fi1
        r_g = np.empty(self.F_app.shape)
        r_g[:, 0] = Fi1.sum(1)
        r_g[:, 1] = (Fi2 * c).sum(1)
        r_g[:, 2] = (Fx * c).sum(1)
        r_g -= self.F_app
        r_g /= s
        st.__dict__.update(
            X1=X1, X2=X2, p=p, q=q, d_i=d_i, d_o=d_o, si=si, ci=ci, so=so, co=co, dl_i=dl_i, dl_o=dl_o,
            Qi=Qi, Qo=Qo, dQi=dQi, dQo=dQo, rb2=rb2, cb=cb, sb=sb, seo=seo, sei=sei, Ro=Ro, Ri=Ri,
            Eo=Eo, Ei=Ei, det=det, w_own=w_own, wR_own=wR_own, qs=qs, wgt=wgt, W=W, den=den, wR=wR,
            Fc=Fc, Mg=Mg, Fi1=Fi1, Fi2=Fi2, Fo1=Fo1, Fo2=Fo2, r_b=r_b, r_g=r_g)
        if self.film is not None:
            st.__dict__.update(fl)
        return st

    def _film_force(self, p, q, X1, X2, dl_i, dl_o, Ki, Ko):
        r"""Contact loads and dQ/dδ of both contacts under the film law (:class:`_FilmLaw`).

        The law δ_c = δ_el,c(Q_c) − h_c(Q_c, α_c) is inverted per contact for Q_c > 0 by the bracketed
        Newton iteration in ln Q of :func:`thermobear.loads.film._invert` (vectorised over the batch, the
        balls and both contacts), warm-started from the loads of the last Newton iterate.  The
        entrainment speeds use the cage speed frozen in ``self.fz`` (updated every Newton step by
        :func:`_newton`); dQ/dδ = 1/(dδ_el/dQ − dh/dQ) > 0.

        Warm start: the loads of the iterate frozen in ``self.fz`` carried to first order to this point,
        Δln Q = (Δδ − ∂G/∂α Δα + h ∂ln h/∂ln u Δln v) / (∂G/∂ln Q) (the derivatives of that iterate;
        only a starting value: the inversion is converged from it)."""
        fz = self.fz
        al = np.stack([np.arctan2(p, q), np.arctan2(X1, X2)], axis=-1)
        dl = np.stack([dl_i, dl_o], axis=-1)
        if np.ndim(Ki) == 0:
            K = np.array([Ki, Ko])
        else:
            K = np.stack(np.broadcast_arrays(Ki, Ko), axis=-1)
        W = fz["W"]                                                        # (nb, 1)
        v = np.stack([np.abs(self.omega[:, None] - W), W], axis=-1)        # (nb, 1, 2)
        Q0 = fz["Q"]
        if "GQ" in fz:
            Q0 = _carry(Q0, fz["GQ"], (dl - fz["dl"]) - fz["Ga"] * (al - fz["al"]) + fz["hu"] * np.log(v / fz["v"]))
        law = self.film.bind(K, v).at(al)
        Q, d_el, h, GQ, Ga, h_u, nit, rel = _invert(law, dl, al, Q0)
        dQ = Q / GQ
        nb = Q.shape[0]
        fl = dict(f_al=al, f_Ga=Ga, f_GQ=GQ, f_hu=h_u, f_v=v, h_i=h[..., 0], h_o=h[..., 1],
                  del_i=d_el[..., 0], del_o=d_el[..., 1], f_rel=np.full(nb, rel), f_W=W.copy())
        return Q[..., 0], dQ[..., 0], Q[..., 1], dQ[..., 1], fl

    def norm(self, st):
        nb = np.abs(st.r_b).max(axis=(1, 2))
        ng = (np.abs(st.r_g) * self.free_g).max(axis=1)
        return np.maximum(nb, ng)

    def closing_limit(self, st, dx, dg):
        r"""Per-ball factor (≤ 1) on a Newton step dx that would close an open contact.

        An open contact has no stiffness in the linear model, so Newton moves a ball with one
        open contact as if the race were not there; near a wedge (a ball outside the load zone
        held between both races with loads ~F_c) the step then buries the ball deep in that race.
        The ball's step is shortened so that the predicted approach of an open contact,
        δ + n·(ΔA − ΔX) (inner) or δ + n·ΔX (outer), reaches at most δ_η = (F/K)^(2/3), the approach
        that carries the ball's force scale F = max(F_c, |r_b|) — the next step then sees the contact."""
        A = self.A
        c = self.c
        dA1 = A * (dg[:, 0:1] + dg[:, 2:3] * c)
        dA2 = (A * dg[:, 1:2]) * c
        dX1, dX2 = A * dx[..., 0], A * dx[..., 1]
        dd_i = st.si * (dA1 - dX1) + st.ci * (dA2 - dX2)
        dd_o = st.so * dX1 + st.co * dX2
        F = np.maximum(st.Fc, np.max(np.abs(st.r_b), axis=-1) * self.scale[:, None])
        kap = np.ones(dd_i.shape)
        for dl, dd, K in ((st.dl_i, dd_i, self.Ki0), (st.dl_o, dd_o, self.Ko0)):
            d_eta = (F / K) ** (2.0 / 3.0)
            over = (dl < 0) & (dl + dd > d_eta)
            if over.any():
                kap = np.where(over, np.minimum(kap, (d_eta - dl) / np.where(over, dd, 1.0)), kap)
        return kap

    def newton_step(self, st):
        r"""Exact Newton direction (dx, dg) at the iterate ``st``.

        Unknowns: x (2 per ball), the three ring globals g and, as a fourth global, the cage speed
        with the residual r_W = (ω_cage − Σ Q_i ω_c,j / Σ Q_i)/ω_ref, zero at every iterate: its row
        carries the dependence of the cage speed on every ball (a rank-one coupling), so the
        Newton step of the augmented system is that of the reduced one.  The per-ball 2×2 blocks
        are eliminated in closed form (Schur complement; a 4×4 system per case).  All kinematic
        derivatives (of β, the contact radii, ω_c,j, ω_R, F_c and M_g with respect to α_i, α_o, Q_i,
        Q_o and ω_cage) are analytic; dα_i/d(A − X) = e_i/d_i, dα_o/dX = e_o/d_o."""
        A, D, J = self.A, self.D, self.J
        gp, hdm, hD = self.gp, 0.5 * self.dm, 0.5 * self.D
        w = self.omega[:, None]
        si, ci, so, co = st.si, st.ci, st.so, st.co
        Qi, Qo, dQi, dQo = st.Qi, st.Qo, st.dQi, st.dQo
        Ro, Ri, Eo, Ei, det, W, wR, sb, cb = st.Ro, st.Ri, st.Eo, st.Ei, st.det, st.W, st.wR, st.sb, st.cb
        # --- derivatives of the kinematics with respect to α_i (suffix _i) and α_o (suffix _o)
        if self.kin_control == "outer":
            b_o, b_i = -(1.0 + gp * co) / st.rb2, 0.0
            Eo_o, Eo_i = -hD * st.seo * (1.0 + b_o), 0.0
            Ei_i, Ei_o = -hD * st.sei, -hD * st.sei * b_o
        else:
            b_i, b_o = -(1.0 - gp * ci) / st.rb2, 0.0
            Ei_i, Ei_o = -hD * st.sei * (1.0 + b_i), 0.0
            Eo_o, Eo_i = -hD * st.seo, -hD * st.seo * b_i
        Ro_o, Ri_i = -hdm * gp * so, hdm * gp * si
        det_i = Ro * Ei_i + Ri_i * Eo + Ri * Eo_i
        det_o = Ro_o * Ei + Ro * Ei_o + Ri * Eo_o
        wo_i = (w * (Ri_i * Eo + Ri * Eo_i) - st.w_own * det_i) / det
        wo_o = (w * Ri * Eo_o - st.w_own * det_o) / det
        qi, qo = np.maximum(Qi, 0.0), np.maximum(Qo, 0.0)
        pos = st.den > 0
        allpos = bool(pos.all())
        den1 = st.den if allpos else np.where(pos, st.den, 1.0)
        wmW = w - W
        wR_i = (-qo * W * Eo_i * Ro - qi * wmW * (Ei_i * Ri + Ei * Ri_i)
                - 2.0 * wR * (qo * Eo * Eo_i + qi * Ei * Ei_i)) / den1
        wR_o = (-qo * W * (Eo_o * Ro + Eo * Ro_o) - qi * wmW * Ei_o * Ri
                - 2.0 * wR * (qo * Eo * Eo_o + qi * Ei * Ei_o)) / den1
        if not allpos:
            wR_i = np.where(pos, wR_i, (-w * Ro * Ri_i - st.wR_own * det_i) / det)
            wR_o = np.where(pos, wR_o, (-w * Ro_o * Ri - st.wR_own * det_o) / det)
        JW = J * W
        Mg_i = JW * (wR_i * sb + wR * cb * b_i)
        Mg_o = JW * (wR_o * sb + wR * cb * b_o)
        JWsb = JW * sb
        if allpos:
            Mg_W = J * sb * (wR + W * ((qi * Ei * Ri - qo * Eo * Ro) / den1))
            Mg_Qi = (JWsb * (-Ei * Ri * wmW - wR * Ei * Ei) / den1) * (Qi > 0)
            Mg_Qo = (JWsb * (-Eo * Ro * W - wR * Eo * Eo) / den1) * (Qo > 0)
        else:
            Mg_W = J * sb * (wR + W * np.where(pos, (qi * Ei * Ri - qo * Eo * Ro) / den1, 0.0))
            Mg_Qi = np.where(pos & (Qi > 0), JWsb * (-Ei * Ri * wmW - wR * Ei * Ei) / den1, 0.0)
            Mg_Qo = np.where(pos & (Qo > 0), JWsb * (-Eo * Ro * W - wR * Eo * Eo) / den1, 0.0)
        Fc_W = self.m * self.dm * W
        # cage speed: ∂ω_cage/∂Q_i, ∂α_i, ∂α_o of each ball
        if (st.qs > 0).all():
            W_Q = ((st.w_own - W) / st.qs) * (Qi > 0)
        else:
            W_Q = np.where((st.qs > 0) & (Qi > 0), (st.w_own - W) / np.where(st.qs > 0, st.qs, 1.0), 0.0)
        W_i, W_o = st.wgt * wo_i, st.wgt * wo_o
        # --- geometry: n = (sin α, cos α), e = (cos α, −sin α); p = A_offset − X
        n_i, n_o = np.empty(si.shape + (2,)), np.empty(si.shape + (2,))
        n_i[..., 0], n_i[..., 1], n_o[..., 0], n_o[..., 1] = si, ci, so, co
        e_i, e_o = n_i[..., ::-1] * _SGN_E, n_o[..., ::-1] * _SGN_E
        gi = e_i / st.d_i[..., None]                      # dα_i/dp
        go = e_o / st.d_o[..., None]                      # dα_o/dX
        if self.film is not None:
            # film law: Q_c(δ_c, α_c), ∂Q/∂α = −(∂G/∂α) dQ/dδ, so dQ/dp = dQ/dδ n + ∂Q/∂α e/d
            Qa = -st.f_Ga * np.stack([dQi, dQo], axis=-1)           # ∂G/∂α of the inversion (analytic)
            Qa_i, Qa_o = Qa[..., 0], Qa[..., 1]
            Mg_i = Mg_i + Mg_Qi * Qa_i
            Mg_o = Mg_o + Mg_Qo * Qa_o
            W_i = W_i + W_Q * Qa_i
        mi = Mg_i[..., None] * gi + (Mg_Qi * dQi)[..., None] * n_i       # dM_g/dp
        mo = Mg_o[..., None] * go + (Mg_Qo * dQo)[..., None] * n_o       # dM_g/dX
        bi = W_i[..., None] * gi + (W_Q * dQi)[..., None] * n_i           # dω_cage/dp
        bo = W_o[..., None] * go                                          # dω_cage/dX
        # contact stiffness matrices d(Q n + T e)/dp = dQ n nᵀ + (Q e − T n) eᵀ / d
        if self.lam_i:
            Ti = self.lam_i / D * st.Mg
            ti = Qi[..., None] * e_i - Ti[..., None] * n_i
        else:
            ti = Qi[..., None] * e_i
        if self.lam_o:
            To = self.lam_o / D * st.Mg
            to = Qo[..., None] * e_o - To[..., None] * n_o
        else:
            to = Qo[..., None] * e_o
        if self.film is not None:                                         # d(Q n)/dp ∋ n (∂Q/∂α) eᵀ/d
            ti = ti + Qa_i[..., None] * n_i
            to = to + Qa_o[..., None] * n_o
        Gi = (dQi[..., None, None] * n_i[..., :, None] * n_i[..., None, :]
              + (ti / st.d_i[..., None])[..., :, None] * e_i[..., None, :])
        Go = (dQo[..., None, None] * n_o[..., :, None] * n_o[..., None, :]
              + (to / st.d_o[..., None])[..., :, None] * e_o[..., None, :])
        v = (self.lam_i * e_i - self.lam_o * e_o) / D                     # ∂r_b/∂M_g
        Hi = Gi + v[..., :, None] * mi[..., None, :]                     # d r_b / dp
        Ho = v[..., :, None] * mo[..., None, :] - Go                     # d r_b / dX
        s = self.scale
        As = self.As
        nb, Z = Qi.shape
        Jbb = As * (Ho - Hi)
        # per-ball right-hand sides [∂r_b/∂g, ∂r_b/∂ω_cage, r_b], eliminated together below
        Jbg = np.empty((nb, Z, 2, 5))
        np.multiply(As, Hi @ self.Wt, out=Jbg[..., :3])
        a_b = v * Mg_W[..., None]
        a_b[..., 1] += Fc_W
        np.multiply(a_b, self.wrs, out=Jbg[..., 3])
        Jbg[..., 4] = st.r_b
        Jgb = np.empty((nb, Z, 4, 2))
        WGi = self.W @ Gi
        if self.lam_i:
            u = self.W @ (self.lam_i / D * e_i)[..., None]                 # (nb, Z, 3, 1)
            u[..., 2, 0] -= self.lam_i * self.fi / self.R * self.c
            Li = WGi + u * mi[..., None, :]
            Jgb[..., :3, :] = As * (u * mo[..., None, :] - Li)
            Jgg_b = Li @ self.Wt
            S_W = (u[..., 0] * Mg_W[..., None]).sum(1) * (self.w_ref / s)[:, None]
        else:
            np.multiply(-As, WGi, out=Jgb[..., :3, :])
            Jgg_b = WGi @ self.Wt
            S_W = 0.0
        np.multiply(self.Aw, bi - bo, out=Jgb[..., 3, :])
        S = np.empty((nb, 4, 4))
        np.multiply(self.As[..., 0], Jgg_b.sum(1), out=S[:, :3, :3])
        S[:, :3, 3] = S_W
        S[:, 3, :3] = -self.Aw[..., 0] * (bi[..., None, :] @ self.Wt)[..., 0, :].sum(1)
        S[:, 3, 3] = 1.0
        # per-ball 2×2 inverse [[d, −b], [−c, a]] / det
        det2 = Jbb[..., 0, 0] * Jbb[..., 1, 1] - Jbb[..., 0, 1] * Jbb[..., 1, 0]
        big = np.abs(Jbb).max(axis=(-1, -2))
        if (np.abs(det2) < (1e-14 * big) ** 2).any():      # ball exactly at the edge of contact
            tiny = 1e-14 * np.maximum(big, 1e-300)
            bad = np.abs(det2) < tiny ** 2
            Jbb = Jbb - (bad * tiny)[..., None, None] * np.eye(2)
            det2 = Jbb[..., 0, 0] * Jbb[..., 1, 1] - Jbb[..., 0, 1] * Jbb[..., 1, 0]
        Binv = Jbb[..., ::-1, ::-1].swapaxes(-1, -2) * _SGN_2 / det2[..., None, None]
        YB = Binv @ Jbg                                     # (nb, Z, 2, 5): Y = B⁻¹ J_bg and B⁻¹ r_b
        T = (Jgb @ YB).sum(1)                               # (nb, 4, 5)
        S -= T[..., :4]
        rhs = T[..., 4]
        rhs[:, :3] -= st.r_g
        rhs *= self.act
        S *= self.act2
        S += self.eye_fix
        try:
            dG = np.linalg.solve(S, rhs[..., None])        # (nb, 4, 1)
        except np.linalg.LinAlgError:                       # a singular case: regularise it
            sd = np.abs(np.linalg.det(S))
            S = np.where((sd < 1e-300)[:, None, None], S + 1e-6 * np.eye(4)[None], S)
            dG = np.linalg.solve(S, rhs[..., None])
        ext = np.empty((nb, 1, 5, 1))
        ext[:, 0, :4] = dG
        ext[:, 0, 4] = 1.0
        dx = YB @ ext
        return np.negative(dx[..., 0], out=dx[..., 0]), dG[:, :3, 0]


def _newton(pb, x, g, tol, maxiter, st=None):
    """Damped Newton.  Returns x, g, norm, iterations, done mask and the state at (x, g)."""
    if st is None:
        st = pb.state(x, g)
    norm = pb.norm(st)
    floor = np.zeros(norm.shape, bool)
    hist = np.repeat(norm[:, None], _NONMONOTONE, axis=1)     # last accepted norms per case (a ring buffer)
    polish = np.zeros(norm.shape, int)         # steps taken after reaching tol
    it = 0
    for it in range(1, maxiter + 1):
        if pb.film is not None:
            # film law: the entrainment speeds of this step use the cage speed of this iterate
            st, norm = _film_refresh(pb, x, g, st, norm)
        # past tol, up to _POLISH more steps towards tol·1e-3: Newton converges quadratically, so
        # they cost little and fix the ill-conditioned positions of lightly loaded balls
        todo = (norm > tol * 1e-3) & ~floor & (polish < _POLISH)
        every = bool(todo.all())
        if not every and not todo.any():
            it -= 1
            break
        sub = pb if every else _Sub(pb, todo)
        st_t = st if every else st.take(todo)
        dx, dg = sub.newton_step(st_t)
        if (st_t.dl_i < 0).any() or (st_t.dl_o < 0).any():
            dx *= sub.closing_limit(st_t, dx, dg)[..., None]
        # cap the step (a Hertz contact has zero stiffness where it opens: an unlimited
        # Newton step from there can throw a ball through its groove centre)
        big = np.maximum(np.abs(dx).max(axis=(1, 2)), np.abs(dg).max(axis=1))
        cap = np.minimum(1.0, _STEP_CAP / np.maximum(big, 1e-300))
        dx *= cap[:, None, None]
        dg *= cap[:, None]
        ref = hist.max(axis=1)
        x_t, g_t, n_t = (x, g, ref) if every else (x[todo], g[todo], ref[todo])
        pol = _polar(x_t, dx)
        # the full step first (accepted, as a rule, from the second step on)
        tx, tg = _polar_move(pol, None), g_t + dg
        st_try = sub.state(tx, tg)
        nt = sub.norm(st_try)
        ok = (nt < (1.0 - 1e-4) * n_t) & np.isfinite(nt)
        full = bool(ok.all())
        if full:
            best_x, best_g, best_st, acc = tx, tg, st_try, ok
        else:
            lam = np.ones(n_t.shape)
            best_st = st_try                        # states at the accepted trial points (reused below)
            best_x, best_g = np.where(ok[:, None, None], tx, x_t), np.where(ok[:, None], tg, g_t)
            acc = ok
            lam = np.where(acc, lam, 0.5 * lam)
            for _ in range(29):
                tx = _polar_move(pol, lam[:, None])
                tg = g_t + lam[:, None] * dg
                st_try = sub.state(tx, tg)
                nt = sub.norm(st_try)
                ok = (nt < (1.0 - 1e-4 * lam) * n_t) & ~acc & np.isfinite(nt)
                if ok.any():
                    best_x[ok], best_g[ok] = tx[ok], tg[ok]
                    best_st.put(ok, st_try.take(ok))
                acc |= ok
                if acc.all():
                    break
                lam = np.where(acc, lam, 0.5 * lam)
            stuck = ~acc                            # take the smallest step anyway (leave flat regions)
            if stuck.any():
                best_x[stuck] = _polar_move(pol, lam[:, None])[stuck]
                best_g[stuck] = g_t[stuck] + lam[stuck, None] * dg[stuck]
        if every:
            x, g = best_x, best_g
        else:
            x, g = x.copy(), g.copy()
            x[todo], g[todo] = best_x, best_g
        prev = norm
        if every and full:
            st, norm = best_st, nt                  # every case took the full step (nt finite)
        else:
            if every and acc.all():
                st = best_st                        # every case took an evaluated trial point
            else:
                st = pb.state(x, g)
            norm = pb.norm(st)
            norm = np.where(np.isfinite(norm), norm, np.inf)
            if not (full or (acc.all() and np.all(lam == 1.0))):    # a damped step: look for stalled light balls
                x, st, norm = _relax(pb, x, g, st, norm, todo)
        floor |= todo & (norm <= 1e-9) & (norm > 0.5 * prev)
        hist[:, it % _NONMONOTONE] = norm
        polish += todo & (prev <= tol)
    else:
        it = maxiter
    return x, g, norm, it, norm <= np.maximum(tol, np.where(floor, 1e-9, tol)), st


def _film_refresh(pb, x, g, st, norm):
    """Freeze the cage speed and the warm-start loads of the film law at the iterate ``st`` and
    re-evaluate the iterate with them (skipped when the cage speed has not moved).  With the loads go
    the approaches, angles, speed factors and law derivatives of the iterate, from which
    :meth:`_Problem._film_force` carries the warm start to a new point."""
    lag_k = np.abs(st.W - pb.fz["W"])[:, 0] / pb.w_ref
    lag = np.max(lag_k) if st.W.size else 0.0
    pb.fz = {"W": st.W.copy(), "Q": np.stack([st.Qi, st.Qo], axis=-1), "dl": np.stack([st.dl_i, st.dl_o], axis=-1),
             "al": st.f_al, "v": st.f_v, "GQ": st.f_GQ, "Ga": st.f_Ga, "hu": st.f_hu}
    if lag <= 1e-15 or np.all(lag_k <= _LAG_SKIP * norm):
        return st, norm
    st = pb.state(x, g)
    n = pb.norm(st)
    return st, np.where(np.isfinite(n), n, np.inf)


def _relax(pb, x, g, st, norm, todo):
    r"""Re-place the light balls whose force residual is large against their own loads.

    A ball outside the load zone carries loads ~F_c, tiny against the ring loads; near the
    transitions between resting on the outer race, wedging between both races and (at n → 0)
    floating, the Newton model of its contacts is poor, and the line search on the largest
    residual of the case then stalls on that one ball.  Such a ball (static-type load Q_i ≤ |f|,
    residual > 1 % of |f|, among the largest residuals of its case; f its centrifugal force plus
    gyroscopic friction at the iterate, frozen) is placed again by :func:`_place` with the rings
    held; the case keeps the new positions if its residual falls.  Near the solution no ball
    qualifies, so the quadratic convergence of Newton is untouched."""
    s = pb.scale[:, None]
    rb = np.max(np.abs(st.r_b), axis=-1)
    f1 = st.r_b[..., 0] * s - (st.Qi * st.si - st.Qo * st.so)
    f2 = st.r_b[..., 1] * s - (st.Qi * st.ci - st.Qo * st.co)
    fn = np.hypot(f1, f2)
    light = ((np.maximum(st.Qi, 0.0) <= fn) & (rb * s > _RELAX * fn) & (rb >= 0.1 * norm[:, None])
             & (fn > 0) & todo[:, None])
    if not light.any() or pb.stiffness == "per_ball" or pb.film is not None:
        return x, st, norm
    A = pb.A
    k = np.flatnonzero(light)
    A1, A2 = pb.centres(g)
    shape = light.shape
    X1, X2 = _place(st.X1.ravel()[k], st.X2.ravel()[k], A1.ravel()[k], A2.ravel()[k], f1.ravel()[k],
                    f2.ravel()[k], pb.Ki0, pb.Ko0, (1e-9 / A) * np.broadcast_to(s, shape).ravel()[k],
                    _BALL_TOL * fn.ravel()[k], pb.ci0, pb.co0, _BALL_CAP * A)
    xn = x.copy()
    xf = xn.reshape(-1, 2)
    xf[k, 0], xf[k, 1] = X1 / A, X2 / A
    cases = light.any(axis=1)
    sub = _Sub(pb, cases)
    st2 = sub.state(xn[cases], g[cases])
    n2 = sub.norm(st2)
    better = n2 < norm[cases]
    if not better.any():
        return x, st, norm
    idx = np.flatnonzero(cases)[better]
    x = x.copy()
    x[idx] = xn[idx]
    st.put(idx, st2.take(better))
    norm = norm.copy()
    norm[idx] = n2[better]
    return x, st, norm


def _polar(x, dx):
    """Ball centres x (…, 2) and a step dx in polar form about the outer groove centre: radius ρ,
    angle α_o, dρ = n_o·dx, dα = e_o·dx/ρ (n_o = (sin α_o, cos α_o), e_o = (cos α_o, −sin α_o))."""
    x1, x2, d1, d2 = x[..., 0], x[..., 1], dx[..., 0], dx[..., 1]
    rho = np.hypot(x1, x2)
    return rho, np.arctan2(x1, x2), (x1 * d1 + x2 * d2) / rho, (x2 * d1 - x1 * d2) / (rho * rho)


def _polar_move(pol, lam):
    """x moved by the fraction lam of the step along the polar path: (ρ + λ dρ)(sin, cos)(α + λ dα).
    To first order the Newton step itself; a ball resting on the outer race keeps its approach δ_o
    when it rolls along the race (a straight tangential step would push it into the race by
    ≈ step²/2ρ, far more than the δ_o of a lightly loaded ball).  ``lam=None``: the full step."""
    rho, a, drho, da = pol
    if lam is None:
        r, t = rho + drho, a + da
    else:
        r, t = rho + lam * drho, a + lam * da
    out = np.empty(r.shape + (2,))
    np.multiply(r, np.sin(t), out=out[..., 0])
    np.multiply(r, np.cos(t), out=out[..., 1])
    return out


class _Sub(_Problem):
    """View of a _Problem restricted to a subset of the batch."""

    def __init__(self, pb, mask):            # noqa: D107  (no super().__init__: copy and slice)
        self.__dict__.update(pb.__dict__)
        self.F_app, self.scale = pb.F_app[mask], pb.scale[mask]
        self.free_g, self.omega, self.w_ref = pb.free_g[mask], pb.omega[mask], pb.w_ref[mask]
        if pb.film is not None:
            self.film = pb.film.take(mask)
            self.fz = None if pb.fz is None else {k: v[mask] for k, v in pb.fz.items()}
        self._prep()


def _check_options(control, stiffness, tol, maxiter):
    if not isinstance(control, str) or _ALIASES.get(control, control) not in HS_CONTROLS:
        raise InputError("control", control, f"must be one of {', '.join(HS_CONTROLS)} (or 'none' = 'both')")
    if stiffness not in STIFFNESS_MODES:
        raise InputError("stiffness", stiffness, f"must be one of {', '.join(STIFFNESS_MODES)}")
    if not (isinstance(tol, (int, float)) and 0.0 < tol < 1e-3):
        raise InputError("tol", tol, "relative residual tolerance must lie in (0, 1e-3)")
    if not (isinstance(maxiter, (int, np.integer)) and maxiter >= 1):
        raise InputError("maxiter", maxiter, "must be an integer >= 1")


def load_distribution_high_speed_full(brg: BallBearing, Fa=0.0, Fr=0.0, M=None, n_rpm=0.0, *,
                                      control: str = "outer", stiffness: str = "nominal",
                                      tol: float = 1e-10, maxiter: int = _MAXIT, film=None):
    r"""High-speed quasi-static load distribution with the per-ball details.

    Parameters
    ----------
    brg : BallBearing
    Fa : array_like      axial load on the inner ring [N], ≥ 0
    Fr : array_like      radial load on the inner ring [N], ≥ 0, towards ψ = 0
    M : array_like       tilting moment [N m]; ``None`` holds the tilt at θ = 0
    n_rpm : array_like   inner-ring speed [rpm], ≥ 0 (outer ring fixed); broadcast with the loads
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
    Jones (1960); Harris (2001) §8.2–8.3 (eqs 8.9 F_c, 8.34 M_g, 8.60–8.66 equilibrium);
    PHYSICS.md §3.3 and §4.  Equations, sign derivation and solver: module docstring.
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
    lam_i, lam_o, kin_control = HS_CONTROLS[control]
    Fa_in, Fr_in = np.asarray(Fa, dtype=float), np.asarray(Fr, dtype=float)
    n_in = np.asarray(n_rpm, dtype=float)
    if np.any(~np.isfinite(n_in)) or np.any(n_in < 0):
        raise InputError("n_rpm", n_rpm, "inner-ring speed must be finite and >= 0 [rpm] (outer ring fixed)")
    M_in = None if M is None else np.asarray(M, dtype=float)
    shape = np.broadcast_shapes(Fa_in.shape, Fr_in.shape, n_in.shape, () if M_in is None else M_in.shape)
    Fa_b = np.broadcast_to(Fa_in, shape).ravel().copy()
    Fr_b = np.broadcast_to(Fr_in, shape).ravel().copy()
    n_b = np.broadcast_to(n_in, shape).ravel().copy()
    M_b = None if M_in is None else np.broadcast_to(M_in, shape).ravel().copy()
    if film is not None:
        f_eta, f_ap = _film_inputs(film, shape)
        if np.any(n_b <= 0):
            raise InputError("n_rpm", n_rpm, "must be > 0 with the film contact law (a film needs entrainment; "
                             "at n = 0 the contacts are dry: film=None)")

    # low-speed solution: input checks, NoEquilibrium cases, starting values
    ls = load_distribution(brg, Fa_b, Fr_b, M_b, stiffness=stiffness)
    Z, A, R = brg.Z, brg.A, brg.R_inner_locus
    nb = Fa_b.size
    Mv = np.zeros(nb) if M_b is None else M_b
    F_app = np.stack([Fa_b, Fr_b, Mv / R], axis=1)
    omega = n_b * np.pi / 30.0
    w_c0 = 0.5 * omega * (1.0 - brg.gamma(brg.alpha0))
    Fc0 = 0.5 * brg.ball_mass * brg.dm * w_c0**2
    load_max = np.max(np.abs(F_app), axis=1)
    zero = load_max == 0.0
    scale = np.maximum(np.maximum(load_max, Fc0), 1e-300)
    free_g = np.ones((nb, 3))
    if M_b is None:
        free_g[:, 2] = 0.0
    if brg.kind == "thrust":
        # the shaft washer is located radially by the shaft (Fr = 0 is enforced): hold δr = 0.
        # At speed the balls thrown outwards give the washer a negative radial stiffness, so a
        # free δr would only find the symmetric solution by accident.
        free_g[:, 1] = 0.0
    free_g[zero] = 0.0                       # no load: the rings stay centred, only the balls move
    pb = _Problem(brg, F_app, scale, omega, free_g, stiffness, lam_i, lam_o, kin_control)

    if brg.kind == "thrust" and np.any(zero & (n_b > 0)):
        k = int(np.argmax(zero & (n_b > 0)))
        raise NoEquilibrium(
            f"a thrust ball bearing at n = {n_b[k]:g} rpm needs an axial load (minimum load): with Fa = 0 the "
            "centrifugal force throws the balls outwards and nothing holds them between the washers")
    g0 = np.zeros((nb, 3))
    g0[:, 0] = np.reshape(ls.delta_a, nb) / A
    if brg.kind == "thrust":
        # unloaded thrust bearing: washers just touching the balls (the centred position
        # would put both groove centres on one point)
        g0[zero, 0] = np.sin(brg.alpha0)
    g0[:, 1] = np.reshape(ls.delta_r, nb) / A
    g0[:, 2] = np.reshape(ls.theta, nb) * R / A
    x0 = _static_start(pb, g0)
    xs0 = _start(pb, x0, g0) if np.any(omega > 0) else x0

    x, g, norm, it, done, st = _newton(pb, xs0, g0.copy(), tol, maxiter)
    its = np.full(nb, it)
    if not np.all(done):
        _diagnose(pb, x, g, done, Fa_b, Fr_b, n_b, its, norm)
    if not np.all(done) and np.any(n_b[~done] > 0):
        # continuation in speed for the failed cases, warm-started from the static solution;
        # a case that fails at some speed fraction stops there (its branch of equilibria ends)
        idx = np.flatnonzero(~done)
        xs, gs = x0[idx].copy(), g0[idx].copy()
        alive = np.ones(idx.size, bool)
        reached = np.zeros(idx.size)             # largest speed fraction with an equilibrium
        ns = np.full(idx.size, np.inf)
        tot = np.zeros(idx.size, int)
        fracs = np.linspace(0.0, 1.0, 11)[1:]
        for frac in fracs:
            if not alive.any():
                break
            m = np.zeros(nb, bool)
            m[idx[alive]] = True
            sub = _Sub(pb, m)
            sub.omega = omega[m] * frac
            sub.w_ref = np.maximum(sub.omega, 1.0)
            sub._prep()
            xstart = xs[alive].copy()
            if frac == fracs[0]:
                xstart = _start(sub, xstart, gs[alive])
            xa, ga, na, k, da_, _ = _newton(sub, xstart, gs[alive].copy(), tol, maxiter)
            tot[alive] += k
            ok = np.flatnonzero(alive)[da_]
            xs[ok], gs[ok], reached[ok], ns[ok] = xa[da_], ga[da_], frac, na[da_]
            bad = np.flatnonzero(alive)[~da_]
            ns[bad] = na[~da_]
            alive[bad] = False
        fin = alive & (reached == 1.0)
        x[idx[fin]], g[idx[fin]], norm[idx[fin]], done[idx[fin]] = xs[fin], gs[fin], ns[fin], True
        st = pb.state(x, g)
        norm[idx[~fin]] = ns[~fin]
        its[idx] = it + tot
        fold = ~fin & (reached > 0)
        if np.any(fold):
            j = int(np.flatnonzero(fold)[0])
            k = int(idx[j])
            raise NoEquilibrium(
                f"no high-speed equilibrium at n = {n_b[k]:g} rpm for Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, "
                f"M = {Mv[k]:g} N m (control = '{control}'): continuation in speed found equilibria up to "
                f"{reached[j] * n_b[k]:.4g} rpm, then none — the centrifugal and gyroscopic loads outgrow what the "
                "contacts can balance (e.g. the cage speed runs away when a raceway-control hypothesis no longer "
                "fits the contact angles); raise the axial load or preload, or check the control hypothesis",
                iterations=int(its[k]), residual=float(ns[j]), last=np.concatenate([gs[j] * A, xs[j].ravel() * A]))
    if not np.all(done):
        _diagnose(pb, x, g, done, Fa_b, Fr_b, n_b, its, norm)
        k = int(np.argmax(np.where(done, -np.inf, norm)))
        raise NoConvergence(
            f"high-speed load distribution did not reach equilibrium for Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, "
            f"M = {Mv[k]:g} N m, n = {n_b[k]:g} rpm: relative residual {norm[k]:.3g} after {its[k]} Newton "
            "iterations (direct and with continuation in speed)",
            iterations=int(its[k]), residual=float(norm[k]), last=np.concatenate([g[k] * A, x[k].ravel() * A]))

    if film is not None:
        x, g, st, norm, its = _film_solve(pb, x, g, st, its, f_eta, f_ap, tol, maxiter, Fa_b, Fr_b, Mv, n_b)

    if lam_i != 0.0:
        # a converged point where the gyroscopic friction alone carries F_a has every inner contact
        # open (friction without a normal load): the degenerate end of the branch, no equilibrium
        gyro = (lam_i * st.Mg / brg.D * st.ci).sum(1)
        bad = (n_b > 0) & (Fa_b > 0) & (gyro >= Fa_b * (1.0 - 1e-6))
        if np.any(bad):
            k = int(np.argmax(bad))
            raise NoEquilibrium(
                f"control = '{control}' at Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, n = {n_b[k]:g} rpm: the gyroscopic "
                f"friction the inner raceway must supply pushes the inner ring axially with {gyro[k]:.4g} N >= Fa; "
                "no positive contact loads balance it. Use control = 'outer' or a larger axial load",
                iterations=int(its[k]), residual=float(norm[k]))
    if film is None:
        Qi = np.where(st.dl_i > 0, st.Qi, 0.0)
        Qo = np.where(st.dl_o > 0, st.Qo, 0.0)
    else:
        Qi, Qo = st.Qi, st.Qo
    a_i, a_o = np.arctan2(st.p, st.q), np.arctan2(st.X1, st.X2)
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
    dn = np.maximum(st.dl_i, 0.0) + np.maximum(st.dl_o, 0.0) if film is None else st.del_i + st.del_o
    da = np.where(zero, 0.0, g[:, 0] * A)
    dr = np.where(zero, 0.0, g[:, 1] * A)
    th = np.where(zero, 0.0, g[:, 2] * A / R)

    ones = np.ones((nb, Z))

    def sh(v):
        return v.reshape(shape) if shape else float(v[0])

    def shz(v):
        return v.reshape(shape + (Z,)) if shape else v[0]

    ld = LoadDistribution(
        delta_a=sh(da), delta_r=sh(dr), theta=sh(th), Q_i=shz(Qi), Q_o=shz(Qo), alpha_i=shz(a_i),
        alpha_o=shz(a_o), psi=pb.psi, delta_n=shz(dn), residual=float(norm.max()) if norm.size else 0.0,
        iterations=int(its.max()) if its.size else 0, Fa=Fa_in, Fr=Fr_in, M=sh(Mv))
    ex = HighSpeedExtras(
        Fc=shz(st.Fc * ones), Mg=shz(st.Mg), omega_c=shz(st.W * ones), omega_R=shz(st.wR),
        beta=shz(np.arctan2(st.sb, st.cb)), X1=shz(st.X1), X2=shz(st.X2), delta_i=shz(st.dl_i),
        delta_o=shz(st.dl_o), lambda_i=lam_i, lambda_o=lam_o, control=control,
        n_rpm=sh(n_b) if shape else float(n_b[0]))
    if film is not None:
        u = st.f_v * (0.5 * brg.dm) * (1.0 + np.array([-1.0, 1.0]) * (brg.D / brg.dm) * np.cos(st.f_al))
        ex = replace(ex, h_i=shz(st.h_i), h_o=shz(st.h_o), delta_el_i=shz(st.del_i), delta_el_o=shz(st.del_o),
                     u_i=shz(u[..., 0]), u_o=shz(u[..., 1]), film_law_residual=float(st.f_rel.max()),
                     film_cage_lag=float(np.max(np.abs(st.W - st.f_W)[:, 0] / omega)))
    return ld, ex


_ETA_STEPS = (1e-6, 1e-4, 1e-2, 1e-1, 1.0)    # continuation in viscosity of the film stage (fractions of η)
_LAG_SKIP = 0.05       # film refresh: keep the iterate when the cage-speed lag is below this fraction of its residual


def _film_solve(pb, x, g, st0, its, eta, ap, tol, maxiter, Fa_b, Fr_b, Mv, n_b):
    r"""Film stage: Newton on the film contact law, started from the dry solution (x, g).

    The warm-start loads are the dry ones (an open contact starts at 1e-9 of the force scale; the
    inversion's bracket expands from there), the frozen cage speed the dry one.  Cases that fail are
    re-solved from the dry solution by continuation in viscosity, η·(1e-6, 1e-4, 1e-2, 0.1, 1): at
    η·1e-6 the films are ~1e-4 of the final ones (h ∝ η^0.6–0.7 in the EHL regimes, ∝ η in IVR).
    ``st0`` is the dry state at (x, g)."""
    Q0 = np.maximum(np.stack([st0.Qi, st0.Qo], axis=-1), 1e-9 * pb.scale[:, None, None])
    pb.film = _FilmLaw(pb.brg, eta, ap)
    pb.fz = {"W": st0.W.copy(), "Q": Q0}
    x0, g0, fz0 = x.copy(), g.copy(), {k: v.copy() for k, v in pb.fz.items()}
    x, g, norm, it, done, st = _newton(pb, x, g, tol, maxiter)
    its = its + it
    if not np.all(done):
        idx = np.flatnonzero(~done)
        m = ~done
        sub = _Sub(pb, m)
        sub.fz = {k: v[m] for k, v in fz0.items()}
        xs, gs, st_s = x0[m], g0[m], None
        for frac in _ETA_STEPS:
            sub.film = _FilmLaw(pb.brg, eta[m] * frac, ap[m])
            if st_s is not None:
                sub.fz = {"W": st_s.W.copy(), "Q": np.stack([st_s.Qi, st_s.Qo], axis=-1)}
            xs, gs, ns, k, ok, st_s = _newton(sub, xs, gs, tol, maxiter)
            its[idx] += k
            if not ok.all():
                break
        if ok.all():
            x, g = x.copy(), g.copy()
            x[idx], g[idx], norm = xs, gs, norm.copy()
            norm[idx] = ns
            pb.fz = {k: v.copy() for k, v in pb.fz.items() if k in sub.fz}
            for k in pb.fz:
                pb.fz[k][idx] = sub.fz[k]
            st = pb.state(x, g)
            norm = np.where(np.isfinite(pb.norm(st)), pb.norm(st), np.inf)
            done = norm <= tol
    if not np.all(done):
        k = int(np.argmax(np.where(done, -np.inf, norm)))
        raise NoConvergence(
            f"high-speed load distribution with the film contact law did not reach equilibrium for "
            f"Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, M = {Mv[k]:g} N m, n = {n_b[k]:g} rpm: relative residual "
            f"{norm[k]:.3g} after {its[k]} Newton iterations (from the dry solution, then by continuation in "
            "viscosity)" + ("; with this raceway-control hypothesis every ball, also one across a film-bridged "
                           "gap, must take gyroscopic friction at the inner race — try control = 'outer'"
                           if pb.lam_i != 0.0 else ""), iterations=int(its[k]), residual=float(norm[k]),
            last=np.concatenate([g[k] * pb.A, x[k].ravel() * pb.A]))
    return x, g, st, norm, its


def _static_start(pb, g):
    """Ball centres of the static solution: on the line of groove centres, the approach
    A_j − A split between the contacts so that K_i δi^1.5 = K_o δo^1.5 (equal split for
    an open contact, where the regularising stiffness is the same on both sides)."""
    A1, A2 = pb.centres(g)
    Aj = np.hypot(A1, A2)
    s = Aj - pb.A
    Ki, Ko = pb.Ki0, pb.Ko0
    if pb.stiffness == "per_ball":
        al = np.arctan2(A1, A2)
        Ki, Ko = pb.brg.K_i(al), pb.brg.K_o(al)
    share_o = np.where(s > 0, Ki ** (2.0 / 3.0) / (Ki ** (2.0 / 3.0) + Ko ** (2.0 / 3.0)), 0.5)
    r_o = pb.co0 + share_o * s
    x = np.stack([r_o * A1 / Aj, r_o * A2 / Aj], axis=-1) / pb.A
    return x


def _diagnose(pb, x, g, done, Fa_b, Fr_b, n_b, its, norm):
    """Raise NoEquilibrium for an unconverged case whose load cannot balance the friction the
    control hypothesis demands from the inner raceway (the inner ring receives Σ λ_i (M_g/D) cos α_i
    axially from the gyroscopic friction; when that reaches F_a, Q_i sin α_i would have to be < 0:
    checked first, it is the cause), or whose loaded balls were driven over the low shoulder of an
    angular contact bearing (α_i ≤ 0)."""
    st = pb.state(x, g)
    if pb.lam_i != 0.0:
        gyro = (pb.lam_i * st.Mg / pb.brg.D * st.ci).sum(1)
        bad = ~done & (gyro >= np.maximum(Fa_b, 0.0)) & (n_b > 0)
        if np.any(bad):
            k = int(np.argmax(bad))
            raise NoEquilibrium(
                f"control = '{'inner' if pb.lam_o == 0 else 'both'}' at Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, "
                f"n = {n_b[k]:g} rpm: the gyroscopic friction the inner raceway must supply pushes the inner ring "
                f"axially with {gyro[k]:.4g} N >= Fa; no positive contact loads balance it. Use control = 'outer' "
                "or a larger axial load", iterations=int(its[k]), residual=float(norm[k]))
    if pb.brg.kind == "angular_contact":
        bad = ~done & np.any((st.dl_i > 0) & (np.arctan2(st.p, st.q) <= 0), axis=1)
        if np.any(bad):
            k = int(np.argmax(bad))
            raise NoEquilibrium(
                f"angular contact bearing at Fa = {Fa_b[k]:g} N, Fr = {Fr_b[k]:g} N, n = {n_b[k]:g} rpm: no "
                "equilibrium with positive inner contact angles (the balls would run over the low shoulder); "
                "raise the axial load or preload", iterations=int(its[k]), residual=float(norm[k]))


def _start(pb, x_static, g):
    r"""Starting ball positions at speed, the rings held at the static solution g.

    With the kinematics of the static positions each ball carries a centrifugal force and a
    gyroscopic friction, frozen here as one external force f (F_c r̂ included).

    * A ball whose static load exceeds |f| is pushed out: its outer contact takes the static
      inner-contact force plus F_c r̂ (Jones's usual start).
    * A lighter ball, or one outside the load zone, is placed where it is in equilibrium under f
      with the rings held: the minimum of its convex potential energy

          U(X) = ⅖ K_i δ_i₊^2.5 + ⅖ K_o δ_o₊^2.5 − f·X,
          δ_i = |O_i − X| − (f_i − ½)D,  δ_o = |X| − (f_o − ½)D,

      (−∇U = Q_i n_i − Q_o n_o + f is its force residual, the Hessian the sum of the contact
      stiffness matrices), by Newton's method with a step cap and an Armijo line search on U,
      on all such balls at once.  A ball with both contacts open moves along f until it touches
      a race and ends on the outer race or wedged between both races with loads of the order of
      its centrifugal force — not, as a push by F_c alone would put it, deep in the axially
      offset inner groove with kN contact loads.

    Only a start: :func:`_newton` then solves the coupled problem."""
    st = pb.state(x_static, g)
    A, ci0, co0 = pb.A, pb.ci0, pb.co0
    s = pb.scale[:, None]
    f1 = st.r_b[..., 0] * s - (st.Qi * st.si - st.Qo * st.so)
    f2 = st.r_b[..., 1] * s - (st.Qi * st.ci - st.Qo * st.co)
    fn = np.hypot(f1, f2)
    Ki, Ko = pb.Ki0, pb.Ko0
    if pb.stiffness == "per_ball":
        Ki, Ko = pb.brg.K_i(np.arctan2(st.p, st.q)), pb.brg.K_o(np.arctan2(st.X1, st.X2))
    # loaded balls: pushed out
    Qs = np.maximum(st.Qi, 0.0)
    g1, g2 = Qs * st.si, Qs * st.ci + st.Fc
    Qo = np.hypot(g1, g2)
    r_o = (co0 + (Qo / Ko) ** (2.0 / 3.0)) / np.where(Qo > 0, Qo, 1.0)
    X1 = np.where(st.Fc > 0, r_o * g1, st.X1)
    X2 = np.where(st.Fc > 0, r_o * g2, st.X2)
    # light and unloaded balls: placed (flattened over the batch)
    k = np.flatnonzero((Qs <= fn) & (fn > 0))
    if k.size:
        A1, A2 = pb.centres(g)
        shape = X1.shape
        X1, X2 = X1.ravel(), X2.ravel()
        ki = Ki if np.ndim(Ki) == 0 else Ki.ravel()[k]
        ko = Ko if np.ndim(Ko) == 0 else Ko.ravel()[k]
        mu = (1e-9 / A) * np.broadcast_to(s, shape).ravel()[k]     # keeps a free ball's Hessian invertible
        X1[k], X2[k] = _place(st.X1.ravel()[k], st.X2.ravel()[k], A1.ravel()[k], A2.ravel()[k],
                              f1.ravel()[k], f2.ravel()[k], ki, ko, mu, _BALL_TOL * fn.ravel()[k],
                              ci0, co0, _BALL_CAP * A)
        X1, X2 = X1.reshape(shape), X2.reshape(shape)
    return np.stack([X1, X2], axis=-1) / A


def _place(x1, x2, a1, a2, f1, f2, Ki, Ko, mu, tol, ci0, co0, cap):
    """Newton minimisation of each ball's potential energy (see :func:`_start`) on flat arrays of
    balls; a ball leaves the active set when its force residual is below ``tol`` or its line
    search fails (a start needs no more).  Returns the ball centres X1, X2 [m]."""
    x1, x2 = x1.copy(), x2.copy()
    act = np.arange(x1.size)
    fabs = np.hypot(f1, f2)

    per_ball = np.ndim(Ki) != 0

    def sub(v, m):
        return v[m] if per_ball else v

    for _ in range(_BALL_MAXIT):
        X1, X2, A1, A2, h1, h2 = x1[act], x2[act], a1[act], a2[act], f1[act], f2[act]
        ki, ko, fa = sub(Ki, act), sub(Ko, act), fabs[act]
        p, q = A1 - X1, A2 - X2
        d_i, d_o = np.hypot(p, q), np.hypot(X1, X2)
        di, do = np.maximum(d_i - ci0, 0.0), np.maximum(d_o - co0, 0.0)
        sqi, sqo = np.sqrt(di), np.sqrt(do)
        Qi, Qo = ki * di * sqi, ko * do * sqo
        si, ci, so, co = p / d_i, q / d_i, X1 / d_o, X2 / d_o
        r1 = Qi * si - Qo * so + h1
        r2 = Qi * ci - Qo * co + h2
        go = np.hypot(r1, r2) > tol[act]
        if not go.any():
            break
        if not go.all():
            act = act[go]
            X1, X2, A1, A2, h1, h2, r1, r2 = X1[go], X2[go], A1[go], A2[go], h1[go], h2[go], r1[go], r2[go]
            Qi, Qo, d_i, d_o, si, ci, so, co = Qi[go], Qo[go], d_i[go], d_o[go], si[go], ci[go], so[go], co[go]
            di, do, sqi, sqo, ki, ko, fa = di[go], do[go], sqi[go], sqo[go], sub(ki, go), sub(ko, go), fa[go]
        # Hessian of U: dQ n nᵀ + (Q/d) e eᵀ per contact, e = (cos α, −sin α)
        ti, to = Qi / d_i, Qo / d_o
        kki, kko = 1.5 * ki * sqi, 1.5 * ko * sqo
        m = mu[act]
        h11 = kki * si * si + ti * ci * ci + kko * so * so + to * co * co + m
        h22 = kki * ci * ci + ti * si * si + kko * co * co + to * so * so + m
        h12 = (kki - ti) * si * ci + (kko - to) * so * co
        dt = h11 * h22 - h12 * h12
        d1, d2 = (h22 * r1 - h12 * r2) / dt, (h11 * r2 - h12 * r1) / dt
        c = np.minimum(1.0, cap / np.maximum(np.hypot(d1, d2), 1e-300))
        # an open contact closes to at most the approach that carries the ball's force |f|
        for gap, dd, K in ((d_i - ci0, -(si * d1 + ci * d2), ki), (d_o - co0, so * d1 + co * d2, ko)):
            shut = gap < 0
            if not shut.any():
                continue
            eta = (fa / K) ** (2.0 / 3.0)
            over = shut & (gap + c * dd > eta)
            if over.any():
                c = np.where(over, (eta - gap) / np.where(over, dd, 1.0), c)
        d1, d2 = d1 * c, d2 * c
        slope = r1 * d1 + r2 * d2                                   # −∇U·dX > 0
        U0 = 0.4 * (ki * di * di * sqi + ko * do * do * sqo)
        lam = np.ones(X1.shape)
        acc = np.zeros(X1.shape, bool)
        for _ in range(_BALL_HALVINGS):
            t1, t2 = X1 + lam * d1, X2 + lam * d2
            ui = np.maximum(np.hypot(A1 - t1, A2 - t2) - ci0, 0.0)
            uo = np.maximum(np.hypot(t1, t2) - co0, 0.0)
            dU = 0.4 * (ki * ui * ui * np.sqrt(ui) + ko * uo * uo * np.sqrt(uo)) - U0 - lam * (h1 * d1 + h2 * d2)
            acc |= dU <= -1e-4 * lam * slope
            if acc.all():
                break
            lam = np.where(acc, lam, 0.5 * lam)
        if acc.all():
            x1[act], x2[act] = X1 + lam * d1, X2 + lam * d2
            continue
        x1[act] = np.where(acc, X1 + lam * d1, X1)
        x2[act] = np.where(acc, X2 + lam * d2, X2)
        act = act[acc]
        if not act.size:
            break
    return x1, x2


def load_distribution_high_speed(brg: BallBearing, Fa=0.0, Fr=0.0, M=None, n_rpm=0.0, *,
                                 control: str = "outer", stiffness: str = "nominal",
                                 tol: float = 1e-10, maxiter: int = _MAXIT, film=None) -> LoadDistribution:
    r"""High-speed quasi-static load distribution (Jones 1960; Harris 2001 ch. 8).

    Same parameters as :func:`load_distribution_high_speed_full`; returns only the
    :class:`thermobear.loads.LoadDistribution` (centrifugal forces, gyroscopic moments,
    ball speeds and positions are in the ``_full`` variant).

    Examples
    --------
    At n = 0 it is the low-speed solution:

    >>> from thermobear.contact.geometry import bearing
    >>> from thermobear.loads.static import load_distribution
    >>> b = bearing("7210")
    >>> hs, ls = load_distribution_high_speed(b, Fa=450.0, Fr=300.0), load_distribution(b, Fa=450.0, Fr=300.0)
    >>> bool(np.allclose(hs.Q_o, ls.Q, rtol=1e-8, atol=1e-9 * 450) and np.allclose(hs.Q_i, hs.Q_o, rtol=1e-8))
    True
    """
    return load_distribution_high_speed_full(brg, Fa, Fr, M, n_rpm, control=control, stiffness=stiffness,
                                             tol=tol, maxiter=maxiter, film=film)[0]

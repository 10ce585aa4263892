"""Load ratings and rating life of ball bearings.

* :mod:`thermobear.rating.iso76`    — static load rating C0, static equivalent load P0, s0,
  contact pressure against the 4 200 MPa reference (ISO 76:2006);
* :mod:`thermobear.rating.iso281`   — dynamic load rating C, equivalent load P, L10, κ, e_C, C_u,
  a_ISO, L10m (ISO 281:2007);
* :mod:`thermobear.rating.iso16281` — reference rating life L10r from the ball loads of any load distribution
  (five degrees of freedom), the ISO/TS 16281:2008 conventions (:func:`iso16281_life`), a set's life;
* :mod:`thermobear.rating.life`     — :func:`rating_life`, all of it for one bearing and load case;
* :mod:`thermobear.rating.maker_speeds` — the makers' reference and limiting speeds of the catalogue bearings
  (``materials/maker_speeds.toml``).
"""
from thermobear.rating.life import RatingLife, rating_life, load_ratings, equivalent_loads  # noqa: F401
from thermobear.rating.iso16281 import iso16281_life, reference_life, system_life  # noqa: F401

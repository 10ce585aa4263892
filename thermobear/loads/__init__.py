"""Quasi-static load distribution of ball bearings with rigid rings, five degrees of freedom (axial, radial
along y and z, tilts in both planes): low-speed (static), high-speed, and with the lubricant film in the contact
law; one entry point, :func:`load_distribution`.  Bearings on one rigid shaft (duplex sets, two supports,
preload): :mod:`thermobear.loads.sets`, two of them in the high-speed form :mod:`thermobear.loads.shaftspeed`; loads
the contacts cannot carry: :mod:`thermobear.loads.overload`."""
from thermobear.loads.rings import LoadDistribution, STIFFNESS_MODES, TILT_ARMS  # noqa: F401
from thermobear.loads.static import (load_distribution_static, axial_contact_angle, needs_high_speed,  # noqa: F401
                                     ring_reaction)
from thermobear.loads.highspeed import (load_distribution_high_speed, load_distribution_high_speed_full,  # noqa: F401
                                        HighSpeedExtras, FilmInputs, HS_CONTROLS)
from thermobear.loads.film import film_load_distribution, film_contact_law, FilmLoadDistribution  # noqa: F401
from thermobear.loads.api import load_distribution, high_speed_cases, FORMS  # noqa: F401
from thermobear.loads.overload import (check_loads, check_contacts, contact_bounds, groove_angle,  # noqa: F401
                                       loads_text, refuse_overload)
from thermobear.loads.sets import (Support, ShaftLoads, bearing_set, shaft_on_two_supports, shaft_loads,  # noqa: F401
                                   warm_supports)
from thermobear.loads.shaftspeed import HighSpeedShaftLoads, shaft_loads_high_speed  # noqa: F401

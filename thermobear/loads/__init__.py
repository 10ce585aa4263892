"""Quasi-static load distribution: low-speed (static), high-speed, and with films in the contact law."""
from thermobear.loads.static import (LoadDistribution, load_distribution, needs_high_speed,  # noqa: F401
                                     axial_contact_angle, STIFFNESS_MODES)

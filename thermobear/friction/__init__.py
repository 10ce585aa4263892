"""Loss models of ball–race contacts, one module per loss family.

rolling   hydrodynamic rolling force (Biboulet–Houpert, Houpert; seeds 000, 001, 004)
sliding   local sliding, pivoting, hysteresis and the thrust-ball balance (seeds 000, 001, 004)
drag, skf see those modules
"""
from . import rolling, sliding  # noqa: F401

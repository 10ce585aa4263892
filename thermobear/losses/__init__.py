"""Power losses: one module per loss family, and the local model that composes them.

rolling_forms  the hydrodynamic rolling-force formulas (Biboulet–Houpert, Houpert; seeds 000, 001, 004)
rolling        their dispatcher, the regime selection and rolling_contacts (prepared contacts)
sliding        local sliding, pivoting, hysteresis and the thrust-ball balance (seeds 000, 001, 004)
drag           balls in the oil–air mixture (Pouly et al. 2010)
skf            SKF 2004 global model
local          per contact → per ball → bearing totals (composes the families above)
"""
from thermobear.losses.local import (LossResult, ContactSet, ContactArrays, bearing_losses,  # noqa: F401
                                     prepare_contacts, evaluate_losses, BREAKDOWN_KEYS, ROLLING_MODELS)

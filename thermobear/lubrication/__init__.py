"""Lubricant properties, air properties, film thickness and lubrication regime.

lubricant   ASTM D341 viscosity, API density, Gold pressure–viscosity, Cragoe thermal properties
air         dry air at 1 atm (CoolProp, tabulated)
nvm         Nijenbanning–Venner–Moes asymptotes and blend, Regime, the Moes map
film        Hamrock–Dowson films, NVM film, Λ, lubrication_regime; ehl_contacts (prepared contacts)
"""

"""Lubricant properties, air properties, film thickness and lubrication regime.

lubricant   the Lubricant: ASTM D341 viscosity, API density, Gold pressure–viscosity, Cragoe thermal properties
walther     the ASTM D341 (Walther) viscosity–temperature relation
air         dry air at 1 atm (CoolProp, tabulated)
nvm         Nijenbanning–Venner–Moes asymptotes and blend, Regime, the Moes map
film        Hamrock–Dowson films, NVM film, Λ, lubrication_regime; ehl_contacts (prepared contacts)
"""

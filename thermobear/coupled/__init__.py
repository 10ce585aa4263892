"""Losses coupled with the thermal network: fixed point, steady state, transient."""

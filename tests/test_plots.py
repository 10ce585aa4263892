"""Plots: every loss family of a breakdown has a colour of its own (churning, seal and cage were one grey)."""
from __future__ import annotations

import matplotlib.colors as mcolors

from thermobear.app.plots import FAMILY_COLORS
from thermobear.losses import BREAKDOWN_KEYS
from thermobear.losses.skf import SKF_BREAKDOWN_KEYS


def test_every_loss_family_has_its_own_colour():
    keys = set(BREAKDOWN_KEYS) | set(SKF_BREAKDOWN_KEYS)
    assert keys <= set(FAMILY_COLORS)
    rgb = {k: mcolors.to_rgb(FAMILY_COLORS[k]) for k in keys}
    assert len(set(rgb.values())) == len(keys)

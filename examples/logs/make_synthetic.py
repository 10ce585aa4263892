"""Make the SYNTHETIC heat-up log ``synthetic_heatup_7210.csv`` (not a measurement).

The scene ``synthetic_heatup_scene.toml`` (7210, Fa 1000 N, 3000 rpm, grease PG2, the bundled
one-node network) is run with a known conductance to ambient, bearing_to_ambient.G_W_K = 0.85 W/K; the bearing temperature every 30 s for 30 min gets Gaussian noise
of 0.3 K (seeded, reproducible).  ``thermobear calibrate`` must recover 0.85 W/K within its
reported uncertainty (tests/test_rig.py).

Run:  python examples/logs/make_synthetic.py
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from thermobear.scene.scene import load_scene
from thermobear.coupled import transient

HERE = Path(__file__).resolve().parent
PARAM = "bearing_to_ambient.G_W_K"
G_TRUE_W_K = 0.85     # the known parameter
NOISE_K = 0.3         # standard deviation of the added thermocouple noise [K]
SEED = 20240503


def make(path=HERE / "synthetic_heatup_7210.csv"):
    scene = load_scene(HERE / "synthetic_heatup_scene.toml")
    scene = scene.with_(network_parameters={PARAM: G_TRUE_W_K})
    t = np.arange(0.0, 1800.0 + 1e-9, 30.0)
    run = transient(scene, float(t[-1]), t_eval=t, rtol=1e-8, atol=1e-7)
    T = run.T_C["bearing"] + np.random.default_rng(SEED).normal(0.0, NOISE_K, t.size)
    lines = ["# SYNTHETIC heat-up log (not a measurement), made by examples/logs/make_synthetic.py",
             f"# scene synthetic_heatup_scene.toml with {PARAM} = {G_TRUE_W_K} W/K (the parameter to recover),",
             f"# Gaussian noise {NOISE_K} K (seed {SEED}); start at the ambient {scene.T_ambient_C:g} C",
             "t_s,T_bearing_C"]
    lines += [f"{ti:.0f},{Ti:.3f}" for ti, Ti in zip(t, T)]
    Path(path).write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


if __name__ == "__main__":
    print(f"wrote {make()}")

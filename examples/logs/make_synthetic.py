"""Make the SYNTHETIC heat-up log ``synthetic_heatup_7210.csv`` (not a measurement).

The scene ``synthetic_heatup_scene.toml`` (7210, Fa 1000 N, 3000 rpm, grease PG2, the bundled one-node
network) is run by the current code with a known conductance to ambient, bearing_to_ambient.G_W_K =
0.85 W/K, in a room that is not at a constant temperature:

* the room (the network's ``ambient`` node, a logged boundary) follows a slow drift and an air-conditioning
  cycle, ``T_room(t) = 22 °C + 1.0 K · t / 1800 s + 0.4 K · sin(2π t / 1200 s)``, imposed on the run at every
  second (linear between 1 s samples);
* both channels are logged every 30 s for 30 min, each with independent Gaussian noise (numpy
  ``default_rng(SEED)``, the bearing's drawn first): 0.3 K on the bearing thermocouple, 0.05 K on the room
  sensor; values rounded to 1 mK.

The free bearing node starts at the room temperature at t = 0 (22 °C).  ``thermobear calibrate`` on the
shipped log (the room channel imposed on ``ambient`` as a boundary, linear between the logged rows) must
recover 0.85 W/K within two standard uncertainties: tests/test_rig.py checks the shipped file against a
regeneration and the fit on it.

Run:  python examples/logs/make_synthetic.py
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from thermobear.coupled import transient
from thermobear.scene.scene import load_scene

HERE = Path(__file__).resolve().parent
PARAM = "bearing_to_ambient.G_W_K"
G_TRUE_W_K = 0.85      # the known parameter
NOISE_K = 0.3          # standard deviation of the bearing thermocouple's noise [K]
ROOM_NOISE_K = 0.05    # standard deviation of the room sensor's noise [K]
SEED = 20240503
T_END_S, DT_LOG_S = 1800.0, 30.0


def room_C(t_s):
    """The true room temperature [°C] at times t_s [s]."""
    t = np.asarray(t_s, float)
    return 22.0 + 1.0 * t / 1800.0 + 0.4 * np.sin(2.0 * np.pi * t / 1200.0)


def make(path=HERE / "synthetic_heatup_7210.csv"):
    """Write the log to ``path`` and return the path."""
    scene = load_scene(HERE / "synthetic_heatup_scene.toml")
    scene = scene.with_(network_parameters={PARAM: G_TRUE_W_K})
    t = np.arange(0.0, T_END_S + 1e-9, DT_LOG_S)
    fine = np.arange(0.0, T_END_S + 1e-9, 1.0)
    run = transient(scene, T_END_S, t_eval=t, T0_C=float(room_C(0.0)), rtol=1e-8, atol=1e-7,
                    boundary=(fine, {"ambient": room_C(fine)}))
    rng = np.random.default_rng(SEED)
    T = run.T_C["bearing"] + rng.normal(0.0, NOISE_K, t.size)
    room = room_C(t) + rng.normal(0.0, ROOM_NOISE_K, t.size)
    lines = ["# SYNTHETIC heat-up log (not a measurement), made by examples/logs/make_synthetic.py with the current code",
             f"# scene synthetic_heatup_scene.toml with {PARAM} = {G_TRUE_W_K} W/K (the parameter to recover)",
             "# room (ambient node, imposed): 22 C + 1.0 K t/1800 s + 0.4 K sin(2 pi t/1200 s), given every 1 s",
             f"# noise: Gaussian, bearing {NOISE_K} K, room {ROOM_NOISE_K} K, numpy default_rng({SEED}), bearing drawn first",
             "# start: the bearing at the room temperature at t = 0 (22 C); values rounded to 1 mK",
             "t_s,T_bearing_C,T_room_C"]
    lines += [f"{ti:.0f},{Ti:.3f},{Ta:.3f}" for ti, Ti, Ta in zip(t, T, room)]
    Path(path).write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


if __name__ == "__main__":
    print(f"wrote {make()}")

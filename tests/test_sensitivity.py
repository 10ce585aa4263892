"""The inputs' ranking (thermobear.coupled.sensitivity): a regression the draws do not determine — too few
distinct family draws per coefficient, collinear or rank-deficient draws — is withheld with the named
caveat UnreliableRegression and the inputs ranked by rank correlation; a determined one is kept as it was."""
from __future__ import annotations

import numpy as np
import pytest

from thermobear.coupled import sensitivity as sens
from thermobear.coupled.sensitivity import ranking


class _In:
    def __init__(self, address, level="point"):
        self.address, self.level = address, level


def _family_design(groups, n_family, n_point, n, seed):
    """Draws of ``n_family`` inputs per family (``groups`` families, a Latin-hypercube-like spread each)
    and ``n_point`` inputs per sample; each sample in one family."""
    rng = np.random.default_rng(seed)
    Xg = np.column_stack([rng.permutation((np.arange(groups) + rng.random(groups)) / groups) for _ in range(n_family)])
    group = rng.permutation(np.arange(n) % groups)
    X = np.column_stack([Xg[group], rng.random((n, n_point))])
    ins = [_In(f"builder.f{k}", "family") for k in range(n_family)] + [_In(f"p{k}") for k in range(n_point)]
    return ins, X, group


def test_one_residual_degree_of_freedom_per_family_is_withheld_with_a_named_caveat():
    """The engineer's spindle: 16 family-level inputs on 18 families (one residual degree of freedom),
    7 per-sample inputs, 100 samples; the output depends on f0 and p0 and on each family's own noise
    (what the linear model does not hold).  The fit through the family means gives coefficients of
    either sign beyond 1; it is withheld: no SRC, no slope, no R², the inputs ranked by |rank
    correlation|, the caveat naming the counts and the rule."""
    ins, X, group = _family_design(18, 16, 7, 100, seed=3)
    rng = np.random.default_rng(4)
    y = X[:, 0] + 0.5 * X[:, 16] + 0.6 * rng.standard_normal(18)[group] + 0.01 * rng.standard_normal(100)
    r = ranking(ins, X, {"P_W": y})["P_W"]
    assert not any(e["src"] is not None and abs(e["src"]) > 1.0 for e in r["inputs"])   # was SRC +2.42, rho +0.43
    c = r["caveat"]
    assert c["name"] == "UnreliableRegression"
    assert "too_few_draws" in c["reasons"] and "collinear" in c["reasons"]
    assert c["levels"]["family"] == {"inputs": 16, "coefficients": 17, "draws": 18, "needed": 34}
    assert c["max_vif"] > 10 and c["max_vif_input"].startswith("builder.f")
    assert "18 distinct draws" in c["message"] and "SRCs withheld" in c["message"] and "\n" not in c["message"]
    assert c["rho_draws"] == 18 and c["rho_zero"] == pytest.approx(1.96 / np.sqrt(17))
    assert r["ranked_by"] == "spearman" and r["r2"] is None
    assert all(e["src"] is None and e["slope"] is None for e in r["inputs"])
    rho = [abs(e["spearman"]) for e in r["inputs"]]
    assert rho == sorted(rho, reverse=True)
    assert r["inputs"][0]["address"] in ("builder.f0", "p0")


def test_a_determined_regression_is_unchanged():
    """Seed 004's shape: 3 family-level inputs on 8 families, 40 per-sample inputs, 200 samples; a linear
    output.  The regression stands (no caveat), ranked by SRC with the known slopes."""
    ins, X, _ = _family_design(8, 3, 40, 200, seed=5)
    y = 2.0 * X[:, 0] - 1.0 * X[:, 3] + 0.1 * X[:, 10]
    r = ranking(ins, X, {"y": y})["y"]
    assert r["caveat"] is None and r["ranked_by"] == "src" and r["r2"] == pytest.approx(1.0)
    assert [e["address"] for e in r["inputs"][:3]] == ["builder.f0", "p0", "p7"]
    assert r["inputs"][0]["slope"] == pytest.approx(2.0) and r["inputs"][1]["slope"] == pytest.approx(-1.0)


def test_collinear_and_rank_deficient_draws_name_their_input():
    rng = np.random.default_rng(6)
    a = rng.random(200)
    X = np.column_stack([a, a + 0.01 * rng.random(200), rng.random(200)])
    c = sens.regression_check(["point"] * 3, X, ["a", "b", "c"])
    assert c["reasons"] == ["collinear"] and c["max_vif_input"] in ("a", "b") and c["max_vif"] > 10
    r = ranking([_In("a"), _In("b"), _In("c")], X, {"y": a})["y"]
    assert r["caveat"]["reasons"] == ["collinear"] and r["ranked_by"] == "spearman"
    X[:, 1] = 2.0 * a + 1.0                                   # an exact combination: nothing determined
    c = sens.regression_check(["point"] * 3, X, ["a", "b", "c"])
    assert c["reasons"] == ["rank_deficient"] and c["max_vif"] is None and "rank 2 of 3" in c["message"]


def test_too_few_samples_for_the_point_level_fit():
    """Fewer samples than two per coefficient (the old fallback): the same caveat, counting them."""
    rng = np.random.default_rng(7)
    X = rng.random((8, 5))
    r = ranking([_In(f"x{k}") for k in range(5)], X, {"y": X[:, 0]})["y"]
    assert r["caveat"]["reasons"] == ["too_few_draws"] and r["caveat"]["levels"]["point"]["needed"] == 12
    assert r["ranked_by"] == "spearman" and r["inputs"][0]["address"] == "x0" and r["inputs"][0]["src"] is None

"""Sampled studies: distributions, designs, statistics and sensitivities against independent
answers (scipy, closed forms), and the study end to end on a short model."""

from __future__ import annotations

import json
import math

import numpy as np
import pandas as pd
import pytest
from runs import EXAMPLES
from scipy import stats
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app
from jointwear.model import ModelError
from jointwear.studies.sample.design import correlation_matrix, unit_points
from jointwear.studies.sample.distributions import read_distribution
from jointwear.studies.sample.plan import make_sample_plan
from jointwear.studies.sample.sensitivity import rank_correlations, sobol_indices
from jointwear.studies.sample.statistics import statistics

POINTS = np.array([0.001, 0.025, 0.3, 0.5, 0.8, 0.975, 0.999])


# Distributions --------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "scipy_distribution", "unit"),
    [
        ("uniform(9.9 mm, 10.1 mm)", stats.uniform(loc=9.9e-3, scale=0.2e-3), 1e-3),
        ("normal(10 mm, 0.01 mm)", stats.norm(loc=10e-3, scale=1e-5), 1e-3),
        ("truncnormal(0.1, 0.03, 0.0, 0.2)", stats.truncnorm(-0.1 / 0.03, 0.1 / 0.03, 0.1, 0.03),
         1.0),
        ("lognormal(8e-14 1/Pa, 1.15)", stats.lognorm(s=1.15, scale=8e-14), 1.0),
        ("loguniform(2.5e-14 1/Pa, 2.5e-13 1/Pa)", stats.loguniform(2.5e-14, 2.5e-13), 1.0),
        ("triangular(1, 3, 4)", stats.triang(2 / 3, loc=1, scale=3), 1.0),
    ],
)  # fmt: skip
def test_drawn_values_are_scipys_quantiles_in_the_given_unit(text, scipy_distribution, unit):
    drawn = read_distribution("a.b", text).values(POINTS)
    numbers = [float(value.split()[0]) * unit for value in drawn]
    np.testing.assert_allclose(numbers, scipy_distribution.ppf(POINTS), rtol=1e-12)


def test_a_list_is_drawn_with_equal_chances():
    choice = read_distribution("solver.integrator", "[abm, dopri5, 'radau']")
    drawn = choice.values(np.linspace(0, 1, 3000, endpoint=False))
    assert {v: drawn.count(v) for v in set(drawn)} == {"abm": 1000, "dopri5": 1000, "'radau'": 1000}


@pytest.mark.parametrize(
    ("text", "says"),
    [
        ("normal(1 mm, 1 s)", "differ in unit"),
        ("normal(1)", "normal(mean, sd)"),
        ("gauss(1, 2)", "expected one of uniform(low, high)"),
        ("lognormal(-1, 1)", "positive median"),
        ("lognormal(1 mm, 1 mm)", "sigma is a plain number"),
        ("uniform(2, 1)", "low must be below high"),
        ("normal(1, 0)", "must be positive"),
        ("triangular(1, 5, 3)", "low <= mode <= high"),
        ("[1, 1]", "repeats a value"),
        ("[]", "an empty list"),
        ("normal(x, 1)", "cannot read 'x'"),
        ("normal(inf, 1)", "finite"),
    ],
)
def test_a_bad_distribution_is_refused_naming_the_path(text, says):
    with pytest.raises(ModelError) as caught:
        read_distribution("joints.j.clearance.friction_coefficient", text)
    (line,) = caught.value.problems
    assert line.startswith("--dist joints.j.clearance.friction_coefficient:")
    assert says in line


# Designs ----------------------------------------------------------------------------------


def test_a_latin_hypercube_has_one_point_in_every_slice_of_every_input():
    points, base = unit_points(5, 40, "lhs", seed=3)
    assert points.shape == (40, 5) and base.all()
    for column in points.T:
        assert sorted(np.floor(column * 40).astype(int)) == list(range(40))


def test_the_same_seed_draws_the_same_points_and_another_seed_others():
    for method in ("random", "lhs", "sobol", "saltelli"):
        first, _ = unit_points(3, 16, method, seed=7)
        again, _ = unit_points(3, 16, method, seed=7)
        other, _ = unit_points(3, 16, method, seed=8)
        assert np.array_equal(first, again) and not np.array_equal(first, other), method


def test_saltelli_blocks_mix_a_and_b_one_input_at_a_time():
    """Rows A, A with input i from B (i = 1..d), B: the base rows are A and B."""
    d = 4
    points, base = unit_points(d, 8, "saltelli", seed=1)
    assert points.shape == (8 * (d + 2), d)
    for block in points.reshape(8, d + 2, d):
        a, mixed, b = block[0], block[1:-1], block[-1]
        for i, row in enumerate(mixed):
            expected = a.copy()
            expected[i] = b[i]
            np.testing.assert_array_equal(row, expected)
    assert base.reshape(8, d + 2)[:, [0, -1]].all() and not base.reshape(8, d + 2)[:, 1:-1].any()


def test_correlated_inputs_have_the_asked_correlation_of_normal_scores():
    matrix = correlation_matrix(["a", "b", "c"], {("a", "b"): 0.8, ("b", "c"): -0.5})
    points, _ = unit_points(3, 20_000, "random", seed=2, correlation=matrix)
    scores = stats.norm.ppf(points)
    found = np.corrcoef(scores.T)
    # the sample correlation's standard error is (1 - rho^2)/sqrt(n) < 0.01 here
    np.testing.assert_allclose(found, matrix, atol=0.03)
    assert np.all((points > 0) & (points < 1))


def test_contradicting_correlations_are_refused():
    with pytest.raises(ModelError, match="contradict"):
        correlation_matrix(["a", "b", "c"], {("a", "b"): 0.9, ("b", "c"): 0.9, ("a", "c"): -0.9})
    with pytest.raises(ModelError, match="has no distribution"):
        correlation_matrix(["a", "b"], {("a", "z"): 0.5})


# Statistics -------------------------------------------------------------------------------


def test_statistics_are_numpys_and_scipys_and_their_intervals_hold_the_classical_ones():
    """A normal sample of 400: the statistics are those of numpy, and the bootstrap
    intervals agree with the classical intervals (t for the mean, chi-square for the
    standard deviation, binomial order statistics for the median) to a few per cent of the
    intervals' widths, the bootstrap's own scatter at 2000 resamples and the difference of
    the methods at n = 400."""
    rng = np.random.default_rng(11)
    x = rng.normal(5.0, 2.0, 400)
    table = pd.DataFrame({"j.x": x})
    row = statistics(table, ["j.x"], resamples=4000, seed=1).iloc[0]
    n = len(x)
    assert row["n"] == n
    assert row["mean"] == pytest.approx(np.mean(x), rel=1e-14)
    assert row["std"] == pytest.approx(stats.tstd(x), rel=1e-14)
    for key, q in (("p5", 0.05), ("p50", 0.5), ("p95", 0.95)):
        assert row[key] == pytest.approx(np.quantile(x, q), rel=1e-14)

    t_low, t_high = stats.t.interval(0.95, n - 1, loc=np.mean(x), scale=stats.sem(x))
    width = t_high - t_low
    assert abs(row["mean_low"] - t_low) < 0.05 * width
    assert abs(row["mean_high"] - t_high) < 0.05 * width
    s = np.std(x, ddof=1)
    chi_low = s * math.sqrt((n - 1) / stats.chi2.ppf(0.975, n - 1))
    chi_high = s * math.sqrt((n - 1) / stats.chi2.ppf(0.025, n - 1))
    width = chi_high - chi_low
    assert abs(row["std_low"] - chi_low) < 0.1 * width
    assert abs(row["std_high"] - chi_high) < 0.1 * width
    ordered = np.sort(x)  # ranks j, k with P(X(j) <= median <= X(k)) ~ 0.95: binomial(n, 1/2)
    j, k = int(stats.binom.ppf(0.025, n, 0.5)), int(stats.binom.ppf(0.975, n, 0.5)) + 1
    width = ordered[k - 1] - ordered[j - 1]
    assert abs(row["p50_low"] - ordered[j - 1]) < 0.25 * width
    assert abs(row["p50_high"] - ordered[k - 1]) < 0.25 * width


def test_statistics_leave_out_failed_cases_and_give_no_interval_without_spread():
    table = pd.DataFrame({"j.x": [1.0, np.nan, 3.0, 2.0, np.inf], "j.y": [2.0] * 5})
    rows = statistics(table, ["j.x", "j.y"]).set_index("output")
    assert rows.loc["j.x", "n"] == 3 and rows.loc["j.x", "mean"] == 2.0
    assert np.isnan(rows.loc["j.x", "mean_low"])  # 3 values: too few for an interval
    assert rows.loc["j.y", "std"] == 0.0 and rows.loc["j.y", "p95_low"] == 2.0


# Sensitivity ------------------------------------------------------------------------------

ISHIGAMI_A, ISHIGAMI_B = 7.0, 0.1


def _ishigami_indices() -> dict[str, tuple[float, float]]:
    """First-order and total indices of Ishigami and Homma's function, closed form
    (T. Ishigami and T. Homma, 1990; e.g. Saltelli et al., Global Sensitivity Analysis:
    The Primer, 2008): V1 = (1 + b pi^4 / 5)^2 / 2, V2 = a^2 / 8, V13 = b^2 pi^8 (1/18 -
    1/50), V = a^2 / 8 + b pi^4 / 5 + b^2 pi^8 / 18 + 1/2."""
    a, b, pi = ISHIGAMI_A, ISHIGAMI_B, math.pi
    v = a**2 / 8 + b * pi**4 / 5 + b**2 * pi**8 / 18 + 0.5
    v1, v2, v13 = (1 + b * pi**4 / 5) ** 2 / 2, a**2 / 8, b**2 * pi**8 * (1 / 18 - 1 / 50)
    return {"x1": (v1 / v, (v1 + v13) / v), "x2": (v2 / v, v2 / v), "x3": (0.0, v13 / v)}


def test_sobol_indices_of_the_ishigami_function_are_its_closed_forms():
    """Through the study's own path: distributions -> Saltelli design -> table -> indices.
    At 4096 base points the estimators' standard errors are about 0.015 (SALib's 95 %
    intervals here are +-0.03): the indices agree to 0.02, and each closed form lies in its
    interval widened by half (the errors found are 0.001 at most)."""
    inputs = {f"x{i}": read_distribution(f"x{i}", f"uniform({-math.pi}, {math.pi})")
              for i in (1, 2, 3)}  # fmt: skip
    points, _ = unit_points(3, 4096, "saltelli", seed=5)
    drawn = {name: d.values(points[:, i]) for i, (name, d) in enumerate(inputs.items())}
    table = pd.DataFrame({name: np.array(values, dtype=float) for name, values in drawn.items()})
    x1, x2, x3 = (table[f"x{i}"] for i in (1, 2, 3))
    table["f.y"] = np.sin(x1) + ISHIGAMI_A * np.sin(x2) ** 2 + ISHIGAMI_B * x3**4 * np.sin(x1)
    found = sobol_indices(table, list(inputs), ["f.y"], seed=2).set_index("input")
    for name, (s1, st) in _ishigami_indices().items():
        for key, exact in (("S1", s1), ("ST", st)):
            value, low, high = (found.loc[name, f"{key}{end}"] for end in ("", "_low", "_high"))
            assert value == pytest.approx(exact, abs=0.02), (name, key)
            half = (high - low) / 2
            assert low - half / 2 <= exact <= high + half / 2, (name, key)


def test_rank_correlations_are_scipys_and_their_intervals_cover_the_true_value():
    """For a bivariate normal with correlation r the population Spearman's rho is
    6/pi asin(r/2) (Kendall and Stuart). Over 400 samples of 60, the 95 % interval should
    hold it in 95 % of them: between 92 % and 98 % (3 binomial standard deviations)."""
    r = 0.6
    truth = 6 / math.pi * math.asin(r / 2)
    rng = np.random.default_rng(4)
    covered = 0
    for _ in range(400):
        x, y = rng.multivariate_normal([0, 0], [[1, r], [r, 1]], 60).T
        row = rank_correlations(pd.DataFrame({"x": x, "j.y": y}), ["x"], ["j.y"]).iloc[0]
        assert row["rho"] == pytest.approx(stats.spearmanr(x, y).statistic, abs=1e-14)
        covered += row["rho_low"] <= truth <= row["rho_high"]
    assert 0.92 <= covered / 400 <= 0.98


def test_partial_rank_correlations_are_those_of_the_residuals_and_see_through_confounding():
    """PRCC of x_j: the correlation of the ranks of x_j and y, each less its least-squares
    fit on the other inputs' ranks (Marino et al. 2008), here by numpy's lstsq. y depends on
    x1 only; x2 follows x1: Spearman's rho credits x2 (0.93), the partial one does not."""
    from scipy.stats import rankdata

    rng = np.random.default_rng(0)
    n = 200
    x1, noise, x3 = rng.random((3, n))
    x2 = 0.7 * x1 + 0.3 * noise
    y = np.exp(3 * x1) + 0.05 * rng.normal(size=n)
    table = pd.DataFrame({"x1": x1, "x2": x2, "x3": x3, "j.y": y})
    found = rank_correlations(table, ["x1", "x2", "x3"], ["j.y"]).set_index("input")
    ranks = rankdata(table.to_numpy(), axis=0)
    for j, name in enumerate(["x1", "x2", "x3"]):
        others = np.column_stack([np.ones(n), np.delete(ranks[:, :3], j, axis=1)])
        residual_x = ranks[:, j] - others @ np.linalg.lstsq(others, ranks[:, j], rcond=None)[0]
        residual_y = ranks[:, 3] - others @ np.linalg.lstsq(others, ranks[:, 3], rcond=None)[0]
        expected = np.corrcoef(residual_x, residual_y)[0, 1]
        assert found.loc[name, "prcc"] == pytest.approx(expected, abs=1e-12)
    assert found.loc["x2", "rho"] > 0.9
    assert found.loc["x2", "prcc_low"] < 0 < found.loc["x2", "prcc_high"]
    assert found.loc["x1", "prcc_low"] > 0.99


def test_too_few_cases_for_partial_correlations_leave_them_out():
    rng = np.random.default_rng(1)
    table = pd.DataFrame(rng.random((6, 4)), columns=["a", "b", "c", "j.y"])
    found = rank_correlations(table, ["a", "b", "c"], ["j.y"])
    assert found["rho"].notna().all() and found["prcc"].isna().all()  # 6 cases, 3 inputs


# The study end to end ---------------------------------------------------------------------

SLIDER_CRANK = EXAMPLES / "slider_crank_clearance.toml"
RADIUS = "joints.rod_slider.clearance.bearing_radius"
FRICTION = "joints.rod_slider.clearance.friction_coefficient"
SHORT = ["solver.t_end=0.004"]


@pytest.fixture(scope="module")
def study(tmp_path_factory):
    out = tmp_path_factory.mktemp("sample") / "study"
    distributions = {RADIUS: "uniform(9.55 mm, 9.7 mm)", FRICTION: "[0.05, 0.1]"}
    results = jw.sample(SLIDER_CRANK, out, distributions=distributions, n=6, seed=3,
                        overrides=SHORT, workers=1)  # fmt: skip
    return out, distributions, results


def test_a_study_runs_the_drawn_values_and_tabulates_them(study):
    out, distributions, results = study
    table = results.table
    assert list(table["case"]) == [f"case00{i}" for i in range(1, 7)]
    assert (table["status"] == "success").all()
    points, _ = unit_points(2, 6, "lhs", seed=3)
    expected = read_distribution(RADIUS, distributions[RADIUS]).frozen.ppf(points[:, 0])
    np.testing.assert_allclose(table[RADIUS], expected, rtol=1e-12)  # SI, as drawn
    assert set(table[FRICTION]) <= {0.05, 0.1}
    for case, radius in zip(table["case"], table[RADIUS], strict=True):
        model = json.loads((out / "cases" / case / "model.json").read_text())
        joint = next(j for j in model["joints"] if j["name"] == "rod_slider")
        assert joint["clearance"]["bearing_radius"] == pytest.approx(radius, rel=1e-12)
    saved = pd.read_csv(out / "statistics.csv").set_index("output")
    force = "rod_slider.max_contact_force_n"
    assert saved.loc[force, "mean"] == pytest.approx(table[force].mean(), rel=1e-11)
    plan = json.loads((out / "sample.json").read_text())
    assert plan["method"] == "lhs" and plan["n"] == 6 and plan["seed"] == 3
    assert {p.name for p in results.figures} == {
        "distributions.png", "convergence.png", "scatter.png", "sensitivity.png"
    }  # fmt: skip


def test_running_the_study_again_skips_its_cases_and_redraws(study):
    out, distributions, first = study
    again = jw.sample(SLIDER_CRANK, out, distributions=distributions, n=6, seed=3,
                      overrides=SHORT, workers=1, figures=False)  # fmt: skip
    assert sorted(again.skipped) == sorted(first.table["case"])
    pd.testing.assert_frame_equal(again.statistics, first.statistics)
    result = CliRunner().invoke(app, ["plot", str(out)])
    assert result.exit_code == 0, result.output
    assert "scatter.png" in result.output


def test_the_command_line_prints_the_key_outputs_and_refuses_bad_input(tmp_path):
    study_file = tmp_path / "study.toml"
    study_file.write_text(
        f'n = 5\nmethod = "random"\n[distributions]\n"{FRICTION}" = "uniform(0.05, 0.15)"\n'
        f'[set]\n"solver.t_end" = 0.004\n'
    )
    out = tmp_path / "cli"
    result = CliRunner().invoke(app, ["sample", str(SLIDER_CRANK), "--out", str(out), "--file",
                                      str(study_file), "--workers", "1"],
                                env={"COLUMNS": "200"})  # fmt: skip
    assert result.exit_code == 0, result.output
    assert "5 cases: 5 success" in result.output
    assert "rod_slider: max contact force [kN]" in result.output
    assert len(pd.read_csv(out / "sample.csv")) == 5

    options = ["--n", "4", "--method", "saltelli", "--dist", f"{FRICTION}=gauss(1, 2)"]
    bad = CliRunner().invoke(app, ["sample", str(SLIDER_CRANK), "--out", str(tmp_path / "x"),
                                   *options, "--correlate", "a,b=0.5"])  # fmt: skip
    assert bad.exit_code == 2
    assert "--dist joints.rod_slider.clearance.friction_coefficient:" in bad.stderr
    missing = CliRunner().invoke(app, ["sample", str(SLIDER_CRANK), "--out", str(tmp_path / "y"),
                                       "--dist", f"{FRICTION}=uniform(0.05, 0.15)"])  # fmt: skip
    assert missing.exit_code == 2 and "--n:" in missing.stderr


def test_study_options_are_checked_before_anything_runs(tmp_path):
    base = {"distributions": {FRICTION: "uniform(0.05, 0.15)"}, "n": 5}
    cases = [
        ({"method": "grid"}, "--method: got 'grid'"),
        ({"n": 1}, "--n: got 1"),
        ({"n": 4000, "method": "saltelli"}, "saltelli runs n x 3 cases"),
        ({"seed": 0.0}, "--seed: got 0.0"),
        ({"seed": True}, "--seed: got True"),
        ({"correlations": {(FRICTION, RADIUS): 0.5}, "method": "saltelli"}, "independent"),
        ({"overrides": [f"{FRICTION}=0.1"]}, "both set"),
        ({"max_change": "1%"}, "only for life runs"),
        ({"distributions": {}}, "nothing is drawn"),
        ({"distributions": {RADIUS: "uniform(1 mm, 2 mm)"}}, "case case001 (and 4 other cases)"),
        ({"cycles": 2, "overrides": ["drivers.motor.function.speed=0"]}, "periodic driver"),
    ]  # fmt: skip
    for change, says in cases:
        with pytest.raises(ModelError) as caught:
            jw.sample(SLIDER_CRANK, tmp_path / "never", **{**base, **change})
        assert any(says in line for line in caught.value.problems), (change, caught.value)
    assert not (tmp_path / "never").exists()


def test_numpy_integers_are_whole_numbers(tmp_path):
    results = jw.sample(SLIDER_CRANK, tmp_path / "np", distributions={FRICTION: "[0.05, 0.1]"},
                        n=np.int64(5), seed=np.int64(2), overrides=SHORT, workers=1,
                        figures=False)  # fmt: skip
    assert len(results.table) == 5
    assert json.loads((tmp_path / "np" / "sample.json").read_text())["seed"] == 2


def test_incomplete_cases_are_left_out_and_saltelli_base_rows_are_in_the_table(tmp_path):
    """A case that stops at its step limit has figures only up to there: they are in the
    table, but not in the statistics or the figures. Saltelli's base rows are marked."""
    out = tmp_path / "mixed"
    distributions = {"solver.max_steps": "[30, 100000]", FRICTION: "uniform(0.05, 0.15)"}
    results = jw.sample(SLIDER_CRANK, out, distributions=distributions, n=4, method="saltelli",
                        overrides=SHORT, workers=1)  # fmt: skip
    table = pd.read_csv(out / "sample.csv")
    assert len(table) == 16 and table["base"].sum() == 8
    complete = table[table["base"] & (table["status"] == "success")]
    stopped = table["status"] == "max_steps"
    assert stopped.any() and len(complete) < 8
    force = "rod_slider.max_contact_force_n"
    assert table.loc[stopped, force].notna().all()  # their figures up to the stop ...
    row = results.statistics.set_index("output").loc[force]
    assert row["cases"] == row["n"] == len(complete)  # ... are not outcomes
    assert row["mean"] == pytest.approx(complete[force].mean(), rel=1e-12)
    assert force not in set(results.sensitivity["output"])  # Sobol' needs every case
    assert set(results.failed) == set(table.loc[stopped, "case"])


def test_a_perfect_rank_order_has_no_interval():
    table = pd.DataFrame({"x": [1.0, 2.0, 3.0, 4.0, 5.0], "j.y": [2.0, 4.0, 5.0, 7.0, 9.0]})
    row = rank_correlations(table, ["x"], ["j.y"]).iloc[0]
    assert row["rho"] == pytest.approx(1.0, abs=1e-15)
    assert np.isnan(row["rho_low"]) and np.isnan(row["rho_high"])


def test_a_study_file_of_the_wrong_types_is_refused_key_by_key(tmp_path):
    path = tmp_path / "study.toml"
    path.write_text('correlations = 5\nset = 5\ndistributions = "x"\nn = true\n')
    with pytest.raises(ModelError) as caught:
        make_sample_plan([], path)
    assert [line.split(": ")[1] for line in caught.value.problems] == [
        "distributions", "set", "correlations", "n"
    ]  # fmt: skip


def test_a_study_file_and_options_merge(tmp_path):
    path = tmp_path / "study.toml"
    path.write_text(
        'n = 8\nseed = 4\ncorrelations = [["a.b", "c.d", 0.5]]\n'
        '[distributions]\n"a.b" = "normal(1, 0.1)"\n[distributions.c]\nd = [1, 2]\n'
    )
    plan = make_sample_plan(["e.f=uniform(0, 1)"], path, ["solver.t_end=0.1"], ["a.b,e.f=0.2"])
    assert plan.distributions == {"a.b": "normal(1, 0.1)", "c.d": [1, 2], "e.f": "uniform(0, 1)"}
    assert plan.correlations == {("a.b", "c.d"): 0.5, ("a.b", "e.f"): 0.2}
    assert (plan.n, plan.seed, plan.method) == (8, 4, None)
    with pytest.raises(ModelError, match="also in"):
        make_sample_plan(["a.b=uniform(0, 1)"], path)
    path.write_text("n = 8\nsamples = 3\n")
    with pytest.raises(ModelError, match="unknown key 'samples'"):
        make_sample_plan([], path)

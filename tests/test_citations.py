"""Citations: every law, formulation and integrator has its papers; the API and the command."""

from pathlib import Path

import pytest
from typer.testing import CliRunner

import jointwear as jw
from jointwear.citations import (
    FLORES2009,
    FORMULATION_CITATIONS,
    INTEGRATOR_CITATIONS,
    LAW_CITATIONS,
    REFERENCES,
    citation_keys,
)
from jointwear.cli import app
from jointwear.model.clearance import FAMILIES, WEAR_DISTRIBUTIONS
from jointwear.model.sections import FORMULATIONS, INTEGRATORS

ROOT = Path(__file__).parents[1]
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
FOURBAR = ROOT / "examples" / "flores2009_fourbar.toml"
LUBRICATED = ROOT / "examples" / "flores2009_fourbar_lubricated.toml"
CLEARANCE = "joints.coupler_follower.clearance"
NOTHING_TO_CITE = "none"  # a law that is the absence of one (no damping, a dry joint)


def _registries():
    """(model key, names it accepts) for every choice the model file offers."""
    yield from ((family.key, tuple(family.by_name)) for family in FAMILIES.values())
    yield "wear_distribution", tuple(WEAR_DISTRIBUTIONS)


def test_every_law_in_the_registries_has_a_citation():
    for law_key, names in _registries():
        table = LAW_CITATIONS[law_key]
        for name in names:
            assert name in table, f"{law_key} '{name}' has no entry in citations.LAW_CITATIONS"
            if name != NOTHING_TO_CITE:
                assert table[name], f"{law_key} '{name}' cites nothing"
        assert set(table) == set(names), f"{law_key}: citations for laws that do not exist"


def test_every_formulation_and_integrator_has_a_citation():
    assert set(FORMULATION_CITATIONS) == set(FORMULATIONS)
    assert set(INTEGRATOR_CITATIONS) == set(INTEGRATORS)
    assert all(FORMULATION_CITATIONS.values()) and all(INTEGRATOR_CITATIONS.values())


def test_every_key_cited_is_in_the_reference_table():
    cited = {
        key
        for table in (*LAW_CITATIONS.values(), FORMULATION_CITATIONS, INTEGRATOR_CITATIONS)
        for keys in table.values()
        for key in keys
    }
    assert cited <= set(REFERENCES)
    assert all(text.strip() for text in REFERENCES.values())


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_flores_2009_comes_first_for_every_example(path):
    texts = jw.citations_for(jw.load_model(path))
    assert texts[0] == REFERENCES[FLORES2009]
    assert "10.1016/j.mechmachtheory.2008.08.003" in texts[0]
    assert len(texts) == len(set(texts))


def test_the_lubricated_example_cites_the_bearing_model():
    model = jw.load_model(LUBRICATED)
    assert model.joints_of("revolute")[0].clearance.lubrication == "short_bearing"
    keys = citation_keys(model)
    assert "flores2009lubricated" in keys and "pinkus1961" in keys
    assert "flores2009lubricated" not in citation_keys(jw.load_model(FOURBAR))


def test_the_citations_follow_the_chosen_laws_and_solver():
    # model_copy skips validation: Reye's law would need shear_strength, not wear_coefficient
    base = jw.load_model(FOURBAR)
    joint = base.joints_of("revolute")[0]
    clearance = joint.clearance.model_copy(
        update={"normal_law": "liu", "damping": "hunt_crossley", "friction_law": "stick_slip",
                "wear_law": "reye"}
    )  # fmt: skip
    solver = base.solver.model_copy(
        update={"formulation": "augmented_lagrangian", "integrator": "dopri5"}
    )
    joints = tuple(j.model_copy(update={"clearance": clearance}) if j is joint else j
                   for j in base.joints)  # fmt: skip
    model = base.model_copy(update={"joints": joints, "solver": solver})
    keys = citation_keys(model)
    for key in ("liu2007", "hunt1975", "karnopp1985", "reye1860", "bayo1988", "bayo1996",
                "dormand1980"):  # fmt: skip
        assert key in keys
    for key in ("hertz1882", "lankarani1990", "ambrosio2002", "archard1953", "baumgarte1972",
                "shampine1975"):  # fmt: skip
        assert key not in keys


def test_print_citations(capsys):
    jw.print_citations()
    assert capsys.readouterr().out == f"[1] {REFERENCES[FLORES2009]}\n"
    jw.print_citations(LUBRICATED)
    lines = capsys.readouterr().out.splitlines()
    assert lines == [f"[{i}] {text}" for i, text in enumerate(jw.citations_for(LUBRICATED), 1)]


def test_the_command_reads_a_model_file_and_a_results_folder(tmp_path):
    model = jw.load_model(LUBRICATED)
    (tmp_path / "model.json").write_text(model.model_dump_json(indent=2))  # as Results.save
    expected = [f"[{i}] {text}" for i, text in enumerate(jw.citations_for(model), 1)]
    for target in (LUBRICATED, tmp_path):
        result = CliRunner().invoke(app, ["citations", str(target)], env={"COLUMNS": "60"})
        assert result.exit_code == 0, result.output
        assert result.stdout.splitlines() == expected  # one reference a line, never wrapped


def test_the_command_refuses_a_folder_without_a_model_in_one_line(tmp_path):
    result = CliRunner().invoke(app, ["citations", str(tmp_path)])
    assert result.exit_code == 2
    assert len(result.stderr.strip().splitlines()) == 1
    assert "no model.json" in result.stderr

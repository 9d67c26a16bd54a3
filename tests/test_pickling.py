"""Models travel pickled: to the figure helpers, to sweep processes and to Dask workers."""

import pickle
import typing

from pydantic import BaseModel
from runs import EXAMPLES

import jointwear as jw
from jointwear.model import Model


def _classes_in(annotation: object, seen: set[type]) -> None:
    """Every pydantic class an annotation can hold, into ``seen`` (recursively)."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        if annotation in seen:
            return
        seen.add(annotation)
        for field in annotation.model_fields.values():
            _classes_in(field.annotation, seen)
        return
    for argument in typing.get_args(annotation):
        _classes_in(argument, seen)


def test_every_class_a_model_can_hold_pickles_by_reference():
    classes: set[type] = set()
    _classes_in(Model, classes)
    assert len(classes) > 20  # the walk reached the sections and the functions
    for cls in classes:
        assert pickle.loads(pickle.dumps(cls)) is cls, cls.__qualname__


FUNCTIONS = """
[[forces]]
type = "point_force"
body = "slider"
point = "pin"
force = [{ type = "harmonic", amplitude = "10 N", angular_frequency = "100 rad/s" },
         { type = "polynomial", coefficients = [1.0, 2.0] }]

[[forces]]
type = "torque"
body = "rod"
torque = { type = "harmonic", amplitude = "0.1 N*m", angular_frequency = "50 rad/s" }
"""


def test_a_model_with_every_function_type_round_trips(tmp_path):
    path = tmp_path / "model.toml"
    path.write_text((EXAMPLES / "slider_crank.toml").read_text() + FUNCTIONS)
    model = jw.load_model(path)
    for changes in (
        {},
        {"drivers": [{"name": "motor", "type": "angle", "body": "crank", "function": {
            "type": "harmonic", "amplitude": "10 deg", "angular_frequency": "10 rad/s"}}]},
        {"drivers": [{"name": "motor", "type": "angle", "body": "crank", "function": {
            "type": "polynomial", "coefficients": [0.0, 1.0]}}]},
    ):  # fmt: skip
        varied = model.with_values(changes) if changes else model
        assert pickle.loads(pickle.dumps(varied)) == varied


def test_results_of_a_model_with_every_function_type_pickle(tmp_path):
    # what a drawing carries to the figure helpers: a helper given what does not pickle
    # draws nothing, and the figures are drawn in the command's process, one by one
    path = tmp_path / "model.toml"
    path.write_text((EXAMPLES / "slider_crank_clearance.toml").read_text() + FUNCTIONS)
    results = jw.simulate(jw.load_model(path, overrides=["solver.t_end=0.002"]))
    assert results.status == "success"
    again = pickle.loads(pickle.dumps(results))
    assert again.model == results.model
    assert again.timeseries.equals(results.timeseries)

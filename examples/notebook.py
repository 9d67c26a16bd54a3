"""jointwear in a notebook: the paper's four-bar from Python (cells for Jupyter or VS Code)."""

# %% [markdown]
# # jointwear in a notebook
#
# The paper's four-bar (P. Flores, Mechanism and Machine Theory 44 (2009) 1211-1222) from
# Python: load it, change values with units, simulate, read the steady state and the tables,
# plot, export, and list the papers behind the laws used. Open it in Jupyter or VS Code (the
# `# %%` lines are cells), or run it as a script; the tests run it
# (tests/test_notebook_example.py).

# %%
import os
from pathlib import Path

import pint

import jointwear as jw

OUT = Path(os.environ.get("JOINTWEAR_NOTEBOOK_OUT", "results/notebook"))
OUT.mkdir(parents=True, exist_ok=True)
u = pint.UnitRegistry()

# %% [markdown]
# ## A model, changed in Python
# Values are SI numbers, strings with units or pint Quantities; the checks and messages
# are those of a model file.

# %%
model = jw.load_model("examples/flores2009_fourbar.toml").with_values(
    {
        "solver.t_end": u.Quantity(200, "ms"),  # five crank turns
        "joints.coupler_follower.clearance.friction_coefficient": 0.05,
    }
)
try:
    model.with_values({"bodies.crank.mass": u.Quantity(2, "m")})
except jw.ModelError as error:
    print(error)  # bodies[0].mass: '2.0 meter' has units of length; expected a mass, ...

# %% [markdown]
# ## Simulate, and read the steady state
# The summary's joint figures leave out the first crank turn (the start-up impact of the
# centred journal); `whole_run` keeps them all, and `cycles` has them turn by turn.

# %%
results = jw.simulate(model)
print(results)
joint = results.summary["clearance_joints"]["coupler_follower"]
print(
    f"steady-state peak force {joint['max_contact_force_n'] / 1e3:.1f} kN, "
    f"whole run {joint['whole_run']['max_contact_force_n'] / 1e3:.1f} kN"
)
cycles = results.to_dataframe("cycles")
print(cycles[["cycle", "steady", "max_contact_force_n", "impacts", "worn_volume_m3"]])

# %% [markdown]
# ## The tribologist's time series, plotted with units

# %%
pressure = results.to_dataframe()[["time", "coupler_follower_p_max", "coupler_follower_pv"]]
print(pressure.describe().loc[["mean", "max"]])
print(results.units()["coupler_follower_pv"])
figure = results.plot("coupler_follower_p_max", "coupler_follower_p_mean")
figure.savefig(OUT / "pressure.png")

# %% [markdown]
# ## Files for others: the results folder, netCDF and MATLAB

# %%
results.save(OUT / "fourbar")
results.export(OUT / "fourbar.nc")  # xarray.open_dataset, h5py, MATLAB ncread
results.export(OUT / "fourbar.mat")  # scipy.io.loadmat, MATLAB load

# %% [markdown]
# ## The papers behind this run

# %%
jw.print_citations(model)

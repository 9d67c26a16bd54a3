"""The impedance table of a finite journal bearing: built before a run, cached per L / D.

Method. The table holds the film force for a given motion: the impedance method (Childs,
Moes and van Leeuwen 1977), not Booker's (1965) mobility method, its inverse (the motion for a
given load). The joint element knows the motion (the state) and needs the force, which is the
impedance direction; a mobility table would have to be inverted at every step.

Cavitation. The Reynolds (Swift-Stieber) condition, P >= 0 as a complementarity problem
(``reynolds``), not a mass-conserving Jakobsson-Floberg-Olsson one (Elrod-Adams): an impedance
table is a function of the instantaneous state (eps, direction of V) only, while the JFO
film's cavitated content is a state of its own that the dynamics would have to carry and
transport around the film. Raimondi and Boyd's (1958) steady tables use the Reynolds
condition too.

Inlet. The film has P = 0 along the thickest film (``reynolds``), Raimondi and Boyd's oil
inlet: a condition on the state alone, like the pi-film of the short and long bearings, and
the one whose steady forces the published tables give. The thickest film is undefined at
eps = 0: there the force for V pointing away from e_r is that of a film cut open at its
middle, so a journal squeezed straight through the bearing centre meets a force that jumps
(``docs/theory.md``).

Table. G(s, chi) = q^(3/2) K(cos chi, sin chi / sqrt(q)), q = 1 - eps^2, over
s = -ln(1 - eps) from 0 to ln(1e4) (1 - eps = 1e-4), and over chi = theta + STRETCH sin theta
at uniform theta in [-pi, pi): the nodes crowd towards chi = pi, where the journal leaves the
thin film and its force falls by orders of magnitude over a few degrees of chi (layout,
coordinates and interpolation: ``jointwear.kernels.laws.impedance``). Only theta in [0, pi]
is solved: the mirror a -> -a maps V = (v_r, v_t) to (v_r, -v_t) and K to (K_r, -K_t).

Cache. In memory per process, and on disk in ``$JOINTWEAR_CACHE_DIR``, else
``$XDG_CACHE_HOME/jointwear``, else ``~/.cache/jointwear``, one ``.npy`` file per L / D whose
name carries ``SOLVER_VERSION`` (bump it when the solver or the table changes). The file is
written whole or not at all (a temporary file renamed into place); a file that does not load
or does not fit is rebuilt, and a folder that cannot be written is passed over.

References
----------
D. Childs, H. Moes, H. van Leeuwen, "Journal bearing impedance descriptions for rotordynamic
applications", J. Lubr. Technol. 99 (1977) 198-210.
J.F. Booker, "Dynamically loaded journal bearings: mobility method of solution", J. Basic
Eng. 87 (1965) 537-546.
B. Jakobsson, L. Floberg, "The finite journal bearing, considering vaporization", Trans.
Chalmers Univ. Technol. 190 (1957); H.G. Elrod, "A cavitation algorithm", J. Lubr. Technol.
103 (1981) 350-354.
A.A. Raimondi, J. Boyd, "A solution for the finite journal bearing and its application to
analysis and design", ASLE Trans. 1 (1958) 159-209.
"""

import contextlib
import functools
import math
import os
import tempfile
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..kernels.laws.impedance import (
    AT_LAYOUT,
    AT_N_CHI,
    AT_N_S,
    AT_RATIO,
    AT_S_MAX,
    AT_STRETCH,
    HEADER,
    LAYOUT,
)
from ..model.errors import ModelError
from ..model.laws.lubrication import MAX_FILM_RATIO
from .reynolds import N_ANGLE, N_AXIAL, film_grid, solve_film

SOLVER_VERSION = 1  # in the cache file's name: bump when the solver or the table changes
N_S = 49  # nodes in s = -ln(1 - eps), 0 .. S_MAX (h = 0.19)
N_CHI = 96  # nodes around the circle (even)
STRETCH = 0.9  # chi = theta + STRETCH sin theta at uniform theta: 10x finer at chi = pi
S_MAX = math.log(1e4)  # the last node: 1 - eps = 1e-4


def impedance_table(width_over_diameter: float) -> NDArray[np.float64]:
    """The impedance table of a bearing with L / D ``width_over_diameter``, for the kernel.

    Built on the first call for an L / D (about 2 s), then taken from memory or from the
    disk cache (module docstring). Each call returns its own copy (a float64 array, writeable
    as numba's kernels take them); the layout is ``kernels.laws.impedance``'s.

    Raises
    ------
    ModelError
        If L / D is not a finite number > 0.
    """
    try:
        ratio = float(width_over_diameter)
    except (TypeError, ValueError):
        ratio = math.nan
    if not (math.isfinite(ratio) and 0.0 < ratio <= MAX_FILM_RATIO):
        raise ModelError(
            [
                f"width / diameter: {width_over_diameter!r} is not allowed; the finite "
                f"bearing needs a width-to-diameter ratio 0 < L / D <= {MAX_FILM_RATIO:g}"
            ]
        )
    return _cached_table(float(f"{ratio:.12g}")).copy()  # 12 digits: one table, one file


def build_table(
    width_over_diameter: float,
    n_s: int = N_S,
    n_chi: int = N_CHI,
    s_max: float = S_MAX,
    stretch: float = STRETCH,
    n_angle: int = N_ANGLE,
    n_axial: int = N_AXIAL,
) -> NDArray[np.float64]:
    """Solve the film over the table's nodes and lay the table out for the kernel.

    Parameters
    ----------
    width_over_diameter
        L / D > 0 [-].
    n_s, n_chi, s_max
        Nodes in s (>= 3), around the circle (even, >= 8), and the last s [-].
    stretch
        beta in chi = theta + beta sin theta, 0 <= beta < 1, the nodes uniform in theta.
    n_angle, n_axial
        The film's cells (``reynolds.film_grid``).
    """
    half = n_chi // 2
    g = np.empty((2, n_s, n_chi))
    start = [None] * (half + 1)
    for k, s in enumerate(np.linspace(0.0, s_max, n_s)):
        eps = -math.expm1(-s)
        root = math.sqrt(1.0 - eps * eps)
        grid = film_grid(eps, width_over_diameter, n_angle, n_axial)
        for j, theta in enumerate(np.linspace(0.0, np.pi, half + 1)):
            chi = theta + stretch * math.sin(theta)
            guess = start[j] if start[j] is not None else start[j - 1] if j else None
            solution = solve_film(grid, math.cos(chi), math.sin(chi) / root, guess)
            start[j] = solution.cavitated  # for this chi at the next eps
            column = (half + j) % n_chi  # theta = -pi + 2 pi column / n_chi
            g[:, k, column] = np.multiply(solution.force, root**3)
    # the mirror image a -> -a: G(-chi) = (G_r, -G_t)(chi)
    g[0, :, half - 1 : 0 : -1] = g[0, :, half + 1 :]
    g[1, :, half - 1 : 0 : -1] = -g[1, :, half + 1 :]
    header = np.zeros(HEADER)
    header[[AT_LAYOUT, AT_N_S, AT_N_CHI, AT_S_MAX, AT_RATIO, AT_STRETCH]] = (
        LAYOUT,
        n_s,
        n_chi,
        s_max,
        width_over_diameter,
        stretch,
    )
    return np.concatenate([header, _with_ghosts(g[0]).ravel(), _with_ghosts(g[1]).ravel()])


def _with_ghosts(values: NDArray[np.float64]) -> NDArray[np.float64]:
    """(n_s, n_chi) values with a row before and after: the quadratic extrapolation."""
    low = 3.0 * values[0] - 3.0 * values[1] + values[2]
    high = 3.0 * values[-1] - 3.0 * values[-2] + values[-3]
    return np.vstack([low, values, high])


def cache_folder() -> Path:
    """Where the tables are kept: ``$JOINTWEAR_CACHE_DIR``, else the user's cache folder."""
    chosen = os.environ.get("JOINTWEAR_CACHE_DIR")
    if chosen:
        return Path(chosen)
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "jointwear"


def cache_file(width_over_diameter: float) -> Path:
    """The cache file of an L / D (rounded to 12 significant digits by ``impedance_table``)."""
    return cache_folder() / f"finite_bearing_v{SOLVER_VERSION}_ld{width_over_diameter:.12g}.npy"


@functools.lru_cache(maxsize=32)
def _cached_table(ratio: float) -> NDArray[np.float64]:
    path = cache_file(ratio)
    table = _load(path, ratio)
    if table is None:
        table = build_table(ratio)
        _save(path, table)
    table.flags.writeable = False
    return table


def _load(path: Path, ratio: float) -> NDArray[np.float64] | None:
    """The table in ``path`` if it is one for ``ratio`` of this layout, else None."""
    try:
        table = np.load(path, allow_pickle=False)
    except (OSError, ValueError, EOFError):
        return None
    size = HEADER + 2 * (N_S + 2) * N_CHI
    fits = (
        table.dtype == np.float64
        and table.shape == (size,)
        and np.isfinite(table).all()
        and tuple(table[:HEADER]) == (LAYOUT, N_S, N_CHI, S_MAX, ratio, STRETCH)
    )
    return table if fits else None


def _save(path: Path, table: NDArray[np.float64]) -> None:
    """Write ``table`` to ``path`` whole or not at all; a folder that refuses is passed over."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(dir=path.parent, suffix=".tmp")
    except OSError:
        return
    with contextlib.suppress(OSError):
        with os.fdopen(handle, "wb") as file:
            np.save(file, table, allow_pickle=False)
        os.replace(temporary, path)
    with contextlib.suppress(OSError):
        os.unlink(temporary)  # left only if the write or the rename failed

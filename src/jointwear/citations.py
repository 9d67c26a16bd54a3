"""The papers behind a model: what to cite when publishing results made with jointwear.

``citations_for(model)`` lists the references of the method (Flores 2009, always first),
of the formulation and integrator in the model's ``[solver]``, and of the laws each
clearance joint chooses (elastic law and its stiffness formula, damping, friction, wear,
wear distribution, lubrication), each once, in that order. ``print_citations(model)``
prints them, as ``pybamm.print_citations()`` does for a PyBaMM model. A law's references
are in its record (``model.laws``); this module keeps the bibliography and the entries of
the method, the formulations and the integrators, keyed by the names the model file uses
(``model.sections.FORMULATIONS`` and ``INTEGRATORS``); tests/test_citations.py walks those
registries, so a new law or solver without a citation fails there.

Only the DOI of Flores (2009) is given: it is printed on the copy of the paper the project
works from; the others could not be checked here and are left out rather than guessed.
"""

from __future__ import annotations

import json
from os import PathLike
from pathlib import Path
from typing import TYPE_CHECKING

from .joints import KINDS
from .model.laws import EVERY

if TYPE_CHECKING:
    from .model import Model

FLORES2009 = "flores2009"

REFERENCES: dict[str, str] = {
    FLORES2009: (
        'P. Flores, "Modeling and simulation of wear in revolute clearance joints in '
        'multibody systems", Mechanism and Machine Theory 44(6) (2009) 1211-1222, '
        "doi:10.1016/j.mechmachtheory.2008.08.003"
    ),
    "archard1953": (
        'J.F. Archard, "Contact and rubbing of flat surfaces", Journal of Applied Physics 24 '
        "(1953) 981-988"
    ),
    "reye1860": ('T. Reye, "Zur Theorie der Zapfenreibung", Der Civilingenieur 4 (1860) 235-255'),
    "hertz1882": (
        'H. Hertz, "Über die Berührung fester elastischer Körper", Journal für die reine und '
        "angewandte Mathematik 92 (1882) 156-171"
    ),
    "flores2008book": (
        "P. Flores, J. Ambrósio, J.C.P. Claro, H.M. Lankarani, Kinematics and Dynamics of "
        "Multibody Systems with Imperfect Joints: Models and Case Studies, Springer, Berlin "
        "(2008)"
    ),
    "johnson1985": "K.L. Johnson, Contact Mechanics, Cambridge University Press (1985)",
    "pereira2011": (
        'C.M. Pereira, A.L. Ramalho, J.A. Ambrósio, "A critical overview of internal and '
        'external cylinder contact force models", Nonlinear Dynamics 63 (2011) 681-697'
    ),
    "liu2007": (
        'C.S. Liu, K. Zhang, R. Yang, "The FEM analysis and approximate model for cylindrical '
        'joints with clearances", Mechanism and Machine Theory 42 (2007) 183-197'
    ),
    "mukras2010tribology": (
        'S.M. Mukras, N.H. Kim, N.A. Mauntler, T.L. Schmitz, W.G. Sawyer, "Comparison '
        "between elastic foundation and contact force models in wear analysis of planar "
        'multibody system", Journal of Tribology 132 (2010) 031604'
    ),
    "lankarani1990": (
        'H.M. Lankarani, P.E. Nikravesh, "A contact force model with hysteresis damping for '
        'impact analysis of multibody systems", Journal of Mechanical Design 112 (1990) '
        "369-376"
    ),
    "hunt1975": (
        'K.H. Hunt, F.R.E. Crossley, "Coefficient of restitution interpreted as damping in '
        'vibroimpact", Journal of Applied Mechanics 42 (1975) 440-445'
    ),
    "flores2011": (
        'P. Flores, M. Machado, M.T. Silva, J.M. Martins, "On the continuous contact force '
        'models for soft materials in multibody dynamics", Multibody System Dynamics 25 '
        "(2011) 357-375"
    ),
    "coulomb1785": (
        'C.A. Coulomb, "Théorie des machines simples", Mémoires de mathématique et de '
        "physique de l'Académie Royale des Sciences 10 (1785) 161-331"
    ),
    "ambrosio2002": (
        'J.A.C. Ambrósio, "Impact of rigid and flexible multibody systems: deformation '
        'description and contact models", in W. Schiehlen, M. Valášek (eds.), Virtual '
        "Nonlinear Multibody Systems, NATO Advanced Study Institute, vol. II (2002) 15-33"
    ),
    "karnopp1985": (
        'D. Karnopp, "Computer simulation of stick-slip friction in mechanical dynamic '
        'systems", Journal of Dynamic Systems, Measurement, and Control 107 (1985) 100-103'
    ),
    "flores2009lubricated": (
        'P. Flores, J. Ambrósio, J.C.P. Claro, H.M. Lankarani, C.S. Koshy, "Lubricated '
        'revolute joints in rigid multibody systems", Nonlinear Dynamics 56 (2009) 277-295'
    ),
    "pinkus1961": (
        "O. Pinkus, B. Sternlicht, Theory of Hydrodynamic Lubrication, McGraw-Hill, New York (1961)"
    ),
    "hamrock2004": (
        "B.J. Hamrock, S.R. Schmid, B.O. Jacobson, Fundamentals of Fluid Film Lubrication, "
        "2nd ed., Marcel Dekker, New York (2004)"
    ),
    "childs1977": (
        'D. Childs, H. Moes, H. van Leeuwen, "Journal bearing impedance descriptions for '
        'rotordynamic applications", Journal of Lubrication Technology 99 (1977) 198-210'
    ),
    "raimondi1958": (
        'A.A. Raimondi, J. Boyd, "A solution for the finite journal bearing and its '
        'application to analysis and design", ASLE Transactions 1 (1958) 159-209'
    ),
    "greenwood1970": (
        'J.A. Greenwood, J.H. Tripp, "The contact of two nominally flat rough surfaces", '
        "Proceedings of the Institution of Mechanical Engineers 185 (1970-71) 625-633"
    ),
    "hu1994": (
        'Y. Hu, H.S. Cheng, T. Arai, Y. Kobayashi, S. Aoyama, "Numerical simulation of piston '
        'ring in mixed lubrication: a nonaxisymmetrical analysis", Journal of Tribology 116 '
        "(1994) 470-478"
    ),
    "patir1978": (
        'N. Patir, H.S. Cheng, "An average flow model for determining effects of '
        'three-dimensional roughness on partial hydrodynamic lubrication", Journal of '
        "Lubrication Technology 100 (1978) 12-17"
    ),
    "baumgarte1972": (
        'J. Baumgarte, "Stabilization of constraints and integrals of motion in dynamical '
        'systems", Computer Methods in Applied Mechanics and Engineering 1 (1972) 1-16'
    ),
    "nikravesh1988": (
        "P.E. Nikravesh, Computer-Aided Analysis of Mechanical Systems, Prentice-Hall, "
        "Englewood Cliffs, New Jersey (1988)"
    ),
    "bayo1988": (
        'E. Bayo, J. García de Jalón, M.A. Serna, "A modified Lagrangian formulation for the '
        'dynamic analysis of constrained mechanical systems", Computer Methods in Applied '
        "Mechanics and Engineering 71 (1988) 183-195"
    ),
    "garciadejalon1994": (
        "J. García de Jalón, E. Bayo, Kinematic and Dynamic Simulation of Multibody Systems: "
        "The Real-Time Challenge, Springer, New York (1994)"
    ),
    "bayo1996": (
        'E. Bayo, R. Ledesma, "Augmented Lagrangian and mass-orthogonal projection methods '
        'for constrained multibody dynamics", Nonlinear Dynamics 9 (1996) 113-130'
    ),
    "shampine1975": (
        "L.F. Shampine, M.K. Gordon, Computer Solution of Ordinary Differential Equations: "
        "The Initial Value Problem, Freeman, San Francisco (1975)"
    ),
    "dormand1980": (
        'J.R. Dormand, P.J. Prince, "A family of embedded Runge-Kutta formulae", Journal of '
        "Computational and Applied Mathematics 6 (1980) 19-26"
    ),
}
REFERENCES |= {key: text for kind in KINDS for key, text in kind.references.items()}

# Per clearance-table key, per law: its references, read from the law records.
LAW_CITATIONS: dict[str, dict[str, tuple[str, ...]]] = {
    family.key: {law.name: law.citations for law in family.laws} for family in EVERY
}
FORMULATION_CITATIONS: dict[str, tuple[str, ...]] = {
    "baumgarte": ("baumgarte1972", "nikravesh1988"),
    "augmented_lagrangian": ("bayo1988", "garciadejalon1994", "bayo1996"),
}
INTEGRATOR_CITATIONS: dict[str, tuple[str, ...]] = {
    "abm": ("shampine1975",),
    "dopri5": ("dormand1980",),
}


def citation_keys(model: Model) -> list[str]:
    """Keys of ``REFERENCES`` behind ``model``, each once, Flores (2009) first."""
    keys = [
        FLORES2009,
        *FORMULATION_CITATIONS[model.solver.formulation],
        *INTEGRATOR_CITATIONS[model.solver.integrator],
    ]
    for kind in KINDS:
        for joint in kind.joints(model):
            keys += [*kind.citations, *joint.clearance.law_citations()]
    return list(dict.fromkeys(keys))


def citations_for(model: Model | str | PathLike) -> list[str]:
    """The references behind a model's method, solver and laws, as full citation texts.

    Parameters
    ----------
    model
        A :class:`~jointwear.Model`, a model file, or a results folder (a run's or a life
        run's: it holds ``model.json``).

    Returns
    -------
    list of str
        Flores (2009) first, then the formulation's and the integrator's references, then
        per clearance joint those of its laws; each reference once.

    Raises
    ------
    ModelError
        If a path given is not a valid model file or results folder.
    """
    if isinstance(model, str | PathLike):
        model = _read_model(Path(model))
    return [REFERENCES[key] for key in citation_keys(model)]


def print_citations(model: Model | str | PathLike | None = None) -> None:
    """Print the references to cite, one a line: those of ``model``, or Flores (2009) alone.

    Parameters
    ----------
    model
        As for :func:`citations_for`; None prints the paper jointwear implements.
    """
    texts = [REFERENCES[FLORES2009]] if model is None else citations_for(model)
    for number, text in enumerate(texts, start=1):
        print(f"[{number}] {text}")


def _read_model(path: Path) -> Model:
    """The model of a model file, or of a results folder's ``model.json``."""
    from .model import ModelError, load_model, parse_model

    if not path.is_dir():
        return load_model(path)
    saved = path / "model.json"
    try:
        data = json.loads(saved.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise ModelError(
            [
                f"{path}: no model.json in this folder; give a model file, or the folder of a "
                "run or a life run (a sweep's cases are in its cases/ folder)"
            ]
        ) from None
    except (OSError, UnicodeDecodeError, ValueError) as error:
        raise ModelError([f"{saved}: cannot be read ({error})"]) from None
    return parse_model(data)

"""Records of the friction laws of a contact (kernels: ``kernels.laws.friction``)."""

from .record import Family, Kernel, Key, Law

_FORCE = ("v_t", "f_n", "c_f")


def _pack_coulomb(values: dict) -> tuple[float, float, float]:
    return (values["regularisation_speed"], 0.0, 0.0)


def _pack_ambrosio(values: dict) -> tuple[float, float, float]:
    v0, v1 = values["no_friction_speed"], values["full_friction_speed"]
    if v1 <= v0:
        raise ValueError("full_friction_speed must be larger than no_friction_speed")
    return (v0, v1, 0.0)


def _pack_stick_slip(values: dict) -> tuple[float, float, float]:
    if values.get("static_friction_coefficient") is None:
        raise ValueError("needs static_friction_coefficient")
    keys = ("static_friction_coefficient", "stiction_speed", "transition_speed")
    return tuple(float(values[key]) for key in keys)


FRICTION = Family(
    "friction_law", "friction",
    (
        Law(
            "coulomb", 0, "c_f F_N, linear through zero below the regularisation speed",
            ("coulomb1785",),
            keys=(Key("regularisation_speed", "m/s", 1e-4, positive=True),),
            pack=_pack_coulomb,
            kernels=(
                Kernel("friction:coulomb", (*_FORCE, "p0")),
                Kernel("friction:coulomb_sliding", ("v_t",)),
            ),
        ),
        Law(
            "ambrosio", 1,
            "c_f c_d(v_T) F_N, Ambrosio's dynamic correction (Flores 2009, Eq. 19)",
            ("ambrosio2002",),
            keys=(
                Key("no_friction_speed", "m/s", 1e-4),
                Key("full_friction_speed", "m/s", 1e-2, positive=True),
            ),
            pack=_pack_ambrosio,
            kernels=(
                Kernel("friction:ambrosio", (*_FORCE, "p0", "p1")),
                Kernel("friction:ambrosio_sliding", ("v_t", "p0")),
            ),
        ),
        Law(
            "stick_slip", 2, "velocity-based Karnopp-type stick-slip (Karnopp 1985)",
            ("karnopp1985",),
            keys=(
                Key("static_friction_coefficient", "", None),
                Key("stiction_speed", "m/s", 1e-4, positive=True),
                Key("transition_speed", "m/s", 1e-2, positive=True),
            ),
            pack=_pack_stick_slip,
            kernels=(
                Kernel("friction:stick_slip", (*_FORCE, "p0", "p1", "p2")),
                Kernel("friction:stick_slip_sliding", ("v_t", "p1")),
            ),
        ),
    ),
    default="ambrosio",
    dispatchers=("friction:tangential_force", "friction:slip_speed"),
)  # fmt: skip

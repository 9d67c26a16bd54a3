"""What the step loop is compiled for: a kind's law set (``kernels.laws.lawset``).

Models that differ only in laws compiled for every model share one law set (so one compiled
loop and its cache); a law on demand, or laws registered from Python, make another.
"""

import numpy as np
from numba import typeof

from jointwear.kernels.elements import journal
from jointwear.kernels.laws.lawset import USER_CODE, LawSet
from jointwear.kernels.laws.user import kind_laws


def journal_law_set(**codes: int) -> LawSet:
    """The law set of one journal row with the given codes (the rest 0)."""
    ints = np.zeros((1, journal.N_INTS), dtype=np.int64)
    for family, code in codes.items():
        ints[0, journal.LAW_COLUMNS[family][0]] = code
    return kind_laws(ints, journal.LAW_COLUMNS, None).used


def test_laws_compiled_for_every_model_do_not_make_another_law_set():
    dry = journal_law_set()
    assert journal_law_set(damping=2, friction_law=2, wear_law=1, normal_law=1) == dry
    assert typeof(journal_law_set(normal_law=2)) == typeof(dry)


def test_a_law_on_demand_makes_another_law_set():
    dry = journal_law_set()
    lubricated = journal_law_set(lubrication=1)
    assert lubricated != dry
    assert journal_law_set(lubrication=2) != lubricated  # each film its own
    assert journal_law_set(normal_law=3) != dry  # the elastic foundation
    assert typeof(lubricated).uses("lubrication", 1)
    assert not typeof(dry).uses("lubrication", 1)
    assert not typeof(dry).compiles("lubrication", 3)
    assert typeof(dry).compiles("normal_law", 1)  # Johnson's, compiled for every model


def test_laws_registered_from_python_make_one_law_set_whatever_their_codes():
    first = journal_law_set(friction_law=USER_CODE + 3)
    assert first == journal_law_set(friction_law=USER_CODE + 7)
    assert first != journal_law_set()
    assert typeof(first).with_user_laws("friction_law")
    assert not typeof(first).with_user_laws("normal_law")


def test_a_law_set_returned_from_compiled_code_is_the_same():
    """A table passed by value (JOINTWEAR_PLAIN_NUMBA) comes back with its law set."""
    from numba import njit

    laws = kind_laws(np.zeros((2, journal.N_INTS), dtype=np.int64), journal.LAW_COLUMNS, None)
    laws = laws._replace(used=journal_law_set(lubrication=3, friction_law=USER_CODE))
    back = njit(lambda table: table)(laws)
    assert back.used == laws.used
    np.testing.assert_array_equal(back.address, laws.address)


def test_a_law_sets_type_survives_pickling_for_the_cache_index():
    import pickle

    law_set = typeof(journal_law_set(lubrication=3, normal_law=USER_CODE))
    assert pickle.loads(pickle.dumps(law_set)) == law_set

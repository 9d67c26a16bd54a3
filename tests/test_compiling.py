"""The notice that numba is compiling: said once, with a count of the functions done."""

from numba import njit

from jointwear.cli.compiling import compile_notice
from jointwear.cli.progress import CompileNotice


def test_notice_once_and_counts_each_function():
    starts, reports = [], []

    @njit
    def inner(x):
        return x + 1.0

    @njit
    def outer(x):
        return inner(x) * 2.0

    with compile_notice(lambda: starts.append(True), lambda done, total: reports.append(done)):
        assert outer(1.0) == 4.0
        assert outer(2.0) == 6.0  # compiled already: no event
    assert starts == [True]
    assert reports == [1, 2]  # inner, then outer


def test_no_notice_without_compiling():
    @njit
    def f(x):
        return x

    f(1.0)
    starts = []
    with compile_notice(lambda: starts.append(True), lambda done, total: None):
        f(2.0)
    assert starts == []


def test_the_notice_says_what_compiles_and_when_it_recurs(capsys):
    CompileNotice().started()
    line = capsys.readouterr().err
    assert line.startswith("compiling the kernels for this run's integrator and formulation")
    assert "new combination" in line  # not only after an install: any cache miss compiles
    assert "later runs load them from the cache" in line

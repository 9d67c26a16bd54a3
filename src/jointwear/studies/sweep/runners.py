"""Running the cases of a sweep (or a life run's band): here, in local processes, or on Dask.

Each case runs through :func:`run_case`, which never raises: a failure comes back as an
outcome with its status and error. The three runners yield ``(task, outcome)`` pairs as cases
finish, and stop early when the caller's stop flag is set (Ctrl-C or SIGTERM): cases not yet
started are dropped, running local cases are told to stop (they end ``interrupted`` with what
they computed saved), and the outcomes of cases that were already running are still yielded.
"""

from __future__ import annotations

import json
import multiprocessing
import os
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from contextlib import suppress
from dataclasses import dataclass, field
from importlib import import_module
from pathlib import Path

from ...engine.status import ERROR, INTERRUPTED, SUCCESS
from ...io import make_folder, remove, write_text
from ...model.errors import ModelError

CASE_FILE = "case.json"  # in each case folder: its settings and outcome, written last
POLL_S = 0.3  # how often a runner looks at the stop flag while cases run [s]
CONNECT_TIMEOUT_S = 10  # to reach a Dask scheduler [s]
DASK_MISSING = (
    "--scheduler {address}: sweeps on a cluster need Dask distributed, which is not "
    "installed: pip install 'jointwear[dask]'"
)
WORKER_MODULE = (
    "jointwear.engine.run_file"  # what a case imports (simulate, the kernels): before workers start
)


@dataclass(frozen=True)
class CaseTask:
    """Everything a worker needs to run one case (plain data, so it pickles anywhere).

    Attributes
    ----------
    case
        The case's name (its folder's name).
    model_path
        Absolute path of the model file.
    folder
        Absolute path of the case's results folder.
    overrides
        All ``path=value`` overrides of the case: the sweep's, then the case's own.
    cycles
        ``None`` for a normal run, else the cycle count of a long-life wear run.
    record
        Settings written to ``case.json`` with the outcome (overrides, cycles, the resolved
        model), by which a later run of the sweep knows the case is done.
    laws
        The laws registered from Python that the case's model chooses: a worker registers
        them before it loads the model (``engine.user_laws.install``). They pickle with
        their compiled functions (numba pickles a function by value when it was defined in
        the script or notebook, by reference when imported from a module).
    life_options
        Further keywords of a long-life wear run (``life``): a study's for its cases, or a
        life run's for its band companions (``studies.life.companions``).
    """

    case: str
    model_path: str
    folder: str
    overrides: tuple[str, ...]
    cycles: int | None
    record: dict
    laws: tuple = ()
    life_options: dict = field(default_factory=dict)


Outcome = dict  # status, error, wall_s [s], summary (the run's summary.json, or {})
Stop = list[bool]  # stop[0] becomes True when the sweep should stop (interrupts.stop_requests)
Tick = Callable[[], None] | None  # called at every poll while cases run (progress of their own)


def run_case(task: CaseTask) -> Outcome:
    """Run one case into its folder and record it in ``case.json``; never raises.

    Returns
    -------
    dict
        ``status`` (the run's, or ``error`` for an exception), ``error`` (empty if the status
        is success), ``wall_s`` [s] and ``summary``.
    """
    folder = Path(task.folder)
    start = time.perf_counter()
    try:
        make_folder(folder)
        remove(folder / CASE_FILE)  # until rewritten, the case is not done
        if task.laws:
            from ...engine.user_laws import install

            install(task.laws)
        summary = _simulate(task)
        status = summary.get("status", SUCCESS)
        error = "" if status == SUCCESS else summary.get("message", status)
    except ModelError as problem:
        summary, status, error = {}, ERROR, "; ".join(problem.problems)
    except KeyboardInterrupt:  # during the case's set-up: nothing of it computed yet
        summary, status, error = {}, INTERRUPTED, "interrupted before the case's first step"
    except Exception as problem:  # a case's failure must not stop the sweep
        summary, status, error = {}, ERROR, f"{type(problem).__name__}: {problem}"
    outcome = {
        "status": status,
        "error": " ".join(error.split()),  # one line
        "wall_s": time.perf_counter() - start,
        "summary": summary,
    }
    with suppress(OSError):
        write_text(folder / CASE_FILE, json.dumps({**task.record, **outcome}, indent=2))
    return outcome


def _simulate(task: CaseTask) -> dict:
    if task.cycles is None:
        from ...engine.run_file import run

        results = run(
            task.model_path, task.folder, overrides=task.overrides, figures=False, ideal=False
        )
        return results.summary
    from ..life.study import life  # long-life wear runs; imported only when asked for

    options = {"workers": 1, **task.life_options}  # a case's band in series: cases fill the cores
    return life(
        task.model_path, task.folder, cycles=task.cycles, overrides=task.overrides, **options
    ).summary


def read_record(folder: Path) -> dict | None:
    """The ``case.json`` of a case folder, or None if there is none readable."""
    try:
        return json.loads((folder / CASE_FILE).read_text())
    except (OSError, ValueError):
        return None


# Runners -----------------------------------------------------------------------------------


def run_serial(tasks: Sequence[CaseTask], stop: Stop) -> Iterator[tuple[CaseTask, Outcome]]:
    """Run the cases one after the other in this process.

    A Ctrl-C during a case ends that case ``interrupted`` (``simulate`` handles it), and
    the sweep then stops.
    """
    for task in tasks:
        if stop[0]:
            return
        outcome = run_case(task)
        yield task, outcome
        if outcome["status"] == INTERRUPTED:
            stop[0] = True


def run_local(
    tasks: Sequence[CaseTask], workers: int, stop: Stop, tick: Tick = None
) -> Iterator[tuple[CaseTask, Outcome]]:
    """Run the cases in ``workers`` local processes; ``tick()`` at every poll while they run.

    Workers ignore SIGINT and SIGTERM except while they simulate, so that a Ctrl-C at the
    terminal (which reaches every process of the group) stops their runs cleanly; on a stop
    request the parent also sends them SIGINT, for a SIGTERM or a signal sent to the parent
    alone. If a worker dies (killed, out of memory), its case and those not yet finished are
    recorded as errors and the other workers are killed: the pool cannot go on.

    The workers start at this call (before the caller starts any thread, such as a progress
    bar's, for they may be forked); the cases' outcomes come as the returned iterator is read.
    """
    method = _start_method()
    context = multiprocessing.get_context(method)
    if method == "fork":
        import_module(WORKER_MODULE)  # the workers fork from this process with it imported
    elif method == "forkserver":
        context.set_forkserver_preload([WORKER_MODULE])  # imported once, not per worker
    pids = context.SimpleQueue()
    pool = ProcessPoolExecutor(
        max_workers=workers, mp_context=context, initializer=_start_worker, initargs=(pids,)
    )
    running: dict[Future, CaseTask] = {pool.submit(run_case, task): task for task in tasks}
    return _collect(pool, running, pids, stop, tick)


def _collect(
    pool: ProcessPoolExecutor,
    running: dict[Future, CaseTask],
    pids: object,
    stop: Stop,
    tick: Tick,
) -> Iterator[tuple[CaseTask, Outcome]]:
    """The outcomes of ``run_local``'s cases as they finish; the pool is shut down at the end."""
    with pool:
        workers_pids: set[int] = set()
        stopping = broken = False
        while running:
            done, _ = wait(running, timeout=POLL_S, return_when=FIRST_COMPLETED)
            if tick is not None:
                tick()
            for future in done:
                task = running.pop(future)
                if future.cancelled():
                    continue
                broken = broken or isinstance(future.exception(), BrokenProcessPool)
                yield task, _result(future)
            while not pids.empty():
                workers_pids.add(pids.get())
            if stop[0]:
                if not stopping:
                    stopping = True
                    for future in running:
                        future.cancel()
                    running = {f: t for f, t in running.items() if not f.cancelled()}
                _signal(workers_pids, signal.SIGINT)  # at every poll: a run that starts stops
        if broken:  # the others may still run a case: the pool would wait for them
            _signal(workers_pids, signal.SIGKILL)


def _signal(pids: set[int], signum: int) -> None:
    for pid in pids:
        with suppress(ProcessLookupError, PermissionError):
            os.kill(pid, signum)


def _start_method() -> str:
    """``fork`` where it is safe and cheap, else ``forkserver`` or ``spawn``.

    A forked worker starts at once with jointwear imported (a fresh interpreter takes about
    1.5 s to import it, as long as a 5-turn case runs). Forking is safe only while this
    process runs no other Python thread (one might hold a lock the child would wait on for
    ever; the native threads of OpenBLAS and pyarrow's allocator are fork-aware), and on
    Linux only (macOS frameworks refuse it). The pool forks all its workers on the first
    submitted case, before it starts its own thread.
    """
    if sys.platform == "linux" and threading.active_count() == 1:
        return "fork"
    return "forkserver" if "forkserver" in multiprocessing.get_all_start_methods() else "spawn"


def _start_worker(pids: object) -> None:
    for signum in (signal.SIGINT, signal.SIGTERM):  # simulate() handles them while it runs
        signal.signal(signum, signal.SIG_IGN)
    sys.stdout, sys.stderr = sys.__stdout__, sys.__stderr__  # not the parent's progress bar
    pids.put(os.getpid())


def _result(future: Future) -> Outcome:
    try:
        return future.result()
    except Exception as problem:  # the worker died (killed, out of memory, ...)
        return {
            "status": ERROR,
            "error": " ".join(f"{type(problem).__name__}: {problem}".split()),
            "wall_s": float("nan"),
            "summary": {},
        }


def run_dask(
    tasks: Sequence[CaseTask], address: str, stop: Stop, tick: Tick = None
) -> Iterator[tuple[CaseTask, Outcome]]:
    """Run the cases on the Dask cluster whose scheduler is at ``address``; ``tick`` as local.

    The workers must see the model file and the sweep folder at the same paths (a shared
    file system). On a stop request the cases not yet finished are cancelled; cases already
    running on a worker finish there, and a later run of the sweep skips them. The cases are
    submitted at this call; their outcomes come as the returned iterator is read.

    Raises
    ------
    ModelError
        If Dask distributed is not installed, or the scheduler cannot be reached.
    """
    try:  # only for sweeps on a cluster: the optional extra jointwear[dask]
        from dask.distributed import Client, as_completed
    except ImportError:
        raise ModelError([DASK_MISSING.format(address=address)]) from None
    try:
        client = Client(address, timeout=CONNECT_TIMEOUT_S, set_as_default=False)
    except (OSError, ValueError, TypeError) as problem:
        raise ModelError(
            [
                f"--scheduler {address}: cannot connect ({problem}); give the address of a "
                "running Dask scheduler, e.g. tcp://127.0.0.1:8786"
            ]
        ) from None
    stamp = time.time_ns()  # a later run of the sweep submits new tasks, not cached ones
    futures = {
        client.submit(run_case, task, key=f"jointwear-{task.case}-{stamp}"): task for task in tasks
    }
    return _collect_dask(client, futures, as_completed(futures, loop=client.loop), stop, tick)


def _collect_dask(
    client: object, futures: dict, finished: object, stop: Stop, tick: Tick
) -> Iterator[tuple[CaseTask, Outcome]]:
    """The outcomes of ``run_dask``'s cases as they finish; the client is closed at the end."""
    with client:
        while not finished.is_empty():
            if tick is not None:
                tick()
            if stop[0]:
                client.cancel([f for f in futures if not f.done()])
                return
            if not finished.has_ready():
                time.sleep(POLL_S)
                continue
            for future in finished.next_batch(block=False):
                yield futures[future], _result(future)

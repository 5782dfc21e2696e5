"""Thread pools of the linear algebra: one BLAS thread inside contactlib.

contactlib's public entry points (:func:`contactlib.solve`,
:func:`contactlib.sweep`, :func:`contactlib.history` and the functions of
:mod:`contactlib.pipeline` but ``check``, which calls no BLAS, hence the
command line and the workflow) run
their numerics inside :func:`single_blas_thread`, which limits every BLAS /
LAPACK / OpenMP pool loaded in the process (OpenBLAS, MKL, BLIS, libgomp:
whatever :mod:`threadpoolctl` finds) to one thread, and restores the caller's
limits on return. Why always one, measured on the development machine (2
cores, OpenBLAS 0.3.30 as shipped with scipy; ``scipy.linalg.lu_factor`` of a
random diagonally dominant matrix, other processes on both cores, load
average about 6):

* **Bits.** The LU factors (``getrf``) of one matrix differ in the last bits
  between one and two OpenBLAS threads for every n >= 256 tried (largest
  absolute difference 1e-13 at n = 256 to 9e-13 at n = 2048; the blocked
  updates are summed in a thread-dependent order); a matrix product
  (``gemm``, n x 64) gave identical bits. Without the limit, k of a sweep
  (sphere, nu = 0.3, five stick ratios) moved by up to 4e-8 relative at
  n = 256, and the same ``contactlib history`` command wrote different
  bytes. Results must not depend on the load or the thread settings, so
  factorizations run on one thread.
* **Time.** With both cores busy no size gained from a second thread:
  n = 256: 0.6 ms (1 thread) against 280 ms (2 threads); n = 512: 6 ms /
  340 ms; n = 1024: 45 ms / 410 ms; n = 2048: 0.32 s / 0.77 s (a second
  BLAS thread waits for a core that another process holds). With the
  second core idle (load average 1.7) the crossover is near n = 1024:
  0.6 / 0.6 ms at 256, 3.4 / 3.2 ms at 512, 21 / 17 ms at 1024, 157 /
  103 ms at 2048; a gain of at most 1.5x where the bits differ. With one core kept busy, ``contactlib history
  --geometry sphere --nu 0.3 --friction 0.2 --load-path 0,1,0 --steps 200``
  took 3.0 - 4.3 s before this limit and 2.0 - 2.2 s with it; ``contactlib
  solve --geometry sphere --nu 0.3 --friction 0.2 --n 1024`` 13.8 s and
  8.5 s. The systems contactlib factorizes have at most about 1.6 n = 6600
  unknowns (n <= 4096); the rest of its BLAS work is matrix-vector products,
  bound by memory rather than by cores.

So there is no size above which a user's thread count could be honoured
without changing the bits, and the gain it would bring on an idle machine
is small against the loss on a busy one. Parallelism
that keeps the bits is across independent cases instead: the workflow's
history rule runs the friction coefficients of one scene in parallel
processes, as many as Snakemake's ``threads`` grants (:func:`map_cases`;
elsewhere ``$CONTACTLIB_THREADS``, default 1, see :func:`requested`).

Run ``python -m contactlib.threads`` to repeat the measurement on your
machine (it prints the LU times and whether the factors agree, n = 256 ...
2048).
"""

from __future__ import annotations

import functools
import os
import threading
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from typing import Any, TypeVar

__all__ = ["single_blas_thread", "blas_single_threaded", "requested", "map_cases", "ENV"]

ENV = "CONTACTLIB_THREADS"
"""Environment variable: worker processes for independent cases (default 1)."""

F = TypeVar("F", bound=Callable)


_state = threading.local()


@contextmanager
def single_blas_thread() -> Iterator[None]:
    """Limit every BLAS/LAPACK/OpenMP pool to one thread inside the block.

    The outermost use looks the loaded libraries up (about 2 ms) and restores
    the caller's settings on exit; nested uses (a sweep calling solve) cost
    nothing.
    """
    if getattr(_state, "depth", 0):
        _state.depth += 1
        try:
            yield
        finally:
            _state.depth -= 1
        return
    # threadpoolctl limits only the pools loaded now: load scipy's own OpenBLAS
    # first (free where contactlib's solvers are imported; a scipy imported
    # later inside the block ran on the default threads, with other bits)
    import scipy.linalg  # noqa: F401
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=1):
        _state.depth = 1
        try:
            yield
        finally:
            _state.depth = 0


def blas_single_threaded(func: F) -> F:
    """Decorator: run ``func`` inside :func:`single_blas_thread`."""

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        with single_blas_thread():
            return func(*args, **kwargs)

    return wrapper  # type: ignore[return-value]


def requested(threads: int | None = None) -> int:
    """Worker processes for independent cases: ``threads``, else $CONTACTLIB_THREADS, else 1.

    Parameters
    ----------
    threads : int, optional
        An explicit count (e.g. Snakemake's ``threads`` of a job); wins over
        the environment.

    Returns
    -------
    int
        At least 1.

    Raises
    ------
    ValueError
        If the count (argument or environment variable) is not a positive
        integer; the message names the value.
    """
    source, value = ("threads", threads) if threads is not None else (ENV, os.environ.get(ENV))
    if value is None or value == "":
        return 1
    text = str(value).strip()
    if isinstance(value, bool) or not text.isdigit() or int(text) < 1:
        raise ValueError(f"{source} must be a positive integer, got {value!r}")
    return int(text)


def map_cases(func: Callable[[Any], Any], items: Sequence[Any],
              workers: int | None = None) -> list[Any]:
    """``[func(item) for item in items]``, over up to ``workers`` processes.

    Independent cases (e.g. the friction coefficients of one history scene)
    in parallel without changing a bit of any result: each case runs whole
    in one process, on one BLAS thread, exactly as it would alone. Workers
    are forked from the caller where the platform allows it, so they start
    with its imports done (a fresh interpreter would pay about 1 s of
    imports); the order of the results is that of ``items``.

    Parameters
    ----------
    func : callable
        Called once per item; it and its results must be picklable (a
        module-level function). Its side effects (files, printing) happen
        in the worker.
    items : sequence
        The cases.
    workers : int, optional
        Processes to use; default :func:`requested` ($CONTACTLIB_THREADS,
        else 1). One runs the cases in this process, without a pool.

    Returns
    -------
    list
        ``func(item)`` for each item, in order. The first exception a case
        raises is raised here.
    """
    workers = min(requested(workers), len(items))
    if workers <= 1:
        return [func(item) for item in items]
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    methods = multiprocessing.get_all_start_methods()
    context = multiprocessing.get_context("fork" if "fork" in methods else None)
    with ProcessPoolExecutor(max_workers=workers, mp_context=context) as pool:
        return list(pool.map(func, items))


def _measure(sizes: tuple[int, ...] = (256, 512, 1024, 2048), repeat: int = 5) -> None:
    """Print LU times at one and two BLAS threads and whether the factors agree."""
    import time

    import numpy as np
    from scipy import linalg
    from threadpoolctl import threadpool_limits

    rng = np.random.default_rng(0)
    for n in sizes:
        a = rng.standard_normal((n, n)) + n * np.eye(n)
        best, factors = {}, {}
        for count in (1, 2):
            with threadpool_limits(limits=count, user_api="blas"):
                factors[count] = linalg.lu_factor(a, check_finite=False)[0]
                times = []
                for _ in range(repeat):
                    t0 = time.perf_counter()
                    linalg.lu_factor(a, check_finite=False)
                    times.append(time.perf_counter() - t0)
            best[count] = min(times)
        same = np.array_equal(factors[1], factors[2])
        print(f"n = {n:5d}: LU {best[1] * 1e3:8.1f} ms at 1 thread, {best[2] * 1e3:8.1f} ms at 2;"
              f" factors {'identical' if same else 'differ'}"
              f" (max abs difference {np.max(np.abs(factors[1] - factors[2])):.1e})", flush=True)


if __name__ == "__main__":
    print(f"{os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f}")
    _measure()

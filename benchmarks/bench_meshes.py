"""What the caller-owned store of graded meshes saves in a sweep, measured in one run.

    python benchmarks/bench_meshes.py [--n N] [--cases K] [--repeat R]

A sweep with error estimates (:func:`contactlib.stages.solve_cases`, sphere,
nu = 0.3, K stick ratios in [0.05, 0.95], default n = 256) asks for each
graded mesh several times: the fine mesh for its operators and its solve,
the nested n/2 and n/4 meshes for the estimate. The sweep's
:class:`~contactlib.discretization.operators.StickBlocks` carries a
:class:`~contactlib.discretization.elements.MeshStore` that builds each distinct mesh once
(there is no process-wide cache). This runs the same sweep R times (default
2) each way, alternating: with the store as it is, and with a store that
builds every requested mesh again; it prints the mesh requests, the meshes
built, the time of one mesh (built alone), the best sweep time of each way
and their ratio (no store / store). The two ways give the same numbers; the
script checks that k agrees to the last bit.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from contactlib import stages
from contactlib.discretization.elements import MeshStore, graded_mesh
from contactlib.model import contact
from contactlib.discretization.operators import StickBlocks


class _Rebuild(MeshStore):
    """A store that keeps nothing: every request builds its mesh."""

    def get(self, key, compute):
        self.misses += 1
        return compute()


def _sweep(store_class, n: int, ratios: list[float]) -> tuple[float, list, MeshStore]:
    made: list[StickBlocks] = []

    class Blocks(StickBlocks):
        def __init__(self, size: int = 64) -> None:
            super().__init__(size)
            self.meshes = store_class()
            made.append(self)

    original = stages.StickBlocks
    stages.StickBlocks = Blocks
    try:
        t = time.perf_counter()
        recs = stages.solve_cases(contact("sphere", 0.3), "default", n, ratios)
        elapsed = time.perf_counter() - t
    finally:
        stages.StickBlocks = original
    return elapsed, [r.k for r in recs], made[-1].meshes


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=256)
    parser.add_argument("--cases", type=int, default=10)
    parser.add_argument("--repeat", type=int, default=2)
    args = parser.parse_args()
    ratios = [float(c) for c in np.linspace(0.05, 0.95, args.cases)]
    t = time.perf_counter()
    for c in ratios:
        graded_mesh(args.n, c)
    one = (time.perf_counter() - t) / len(ratios)
    kept, rebuilt = [], []
    for _ in range(args.repeat):
        t_kept, k_kept, store = _sweep(MeshStore, args.n, ratios)
        t_rebuilt, k_rebuilt, fresh = _sweep(_Rebuild, args.n, ratios)
        assert k_kept == k_rebuilt, "the store changed a number"
        kept.append(t_kept)
        rebuilt.append(t_rebuilt)
    print(f"sweep: sphere, nu = 0.3, n = {args.n}, {args.cases} stick ratios, error estimates")
    print(f"mesh requests {fresh.misses}, meshes built with the store {store.misses} "
          f"(answered from it: {store.hits})")
    print(f"one graded mesh (n = {args.n}, built alone): {1e3 * one:.1f} ms")
    print(f"sweep with the store:   {min(kept):.2f} s (best of {args.repeat})")
    print(f"sweep rebuilding meshes: {min(rebuilt):.2f} s (best of {args.repeat})")
    print(f"ratio no store / store: {min(rebuilt) / min(kept):.3f}")


if __name__ == "__main__":
    main()

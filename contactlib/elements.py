"""Meshes of the half-contact 0 <= xi <= 1 (rings or strips)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Mesh", "graded_mesh", "uniform_mesh"]


@dataclass(frozen=True)
class Mesh:
    """Element nodes and the index of the stick-slip node.

    Attributes
    ----------
    nodes : ndarray, shape (N + 1,)
        0 = nodes[0] < ... < nodes[N] = 1 (units of a).
    stick_index : int
        M with nodes[M] = c (0 when frictionless, N at full adhesion).
    """

    nodes: np.ndarray
    stick_index: int

    @property
    def n(self) -> int:
        return self.nodes.size - 1


def _toward_end(t: np.ndarray, power: float) -> np.ndarray:
    """Map [0,1] -> [0,1], elements shrinking like power-law toward t = 1."""
    return 1.0 - (1.0 - t) ** power


def _toward_both(t: np.ndarray, power: float) -> np.ndarray:
    """Map [0,1] -> [0,1], elements shrinking toward both ends."""
    left = 0.5 * (2.0 * t) ** power
    right = 1.0 - 0.5 * (2.0 * (1.0 - t)) ** power
    return np.where(t <= 0.5, left, right)


def graded_mesh(n: int, stick_ratio: float, power: float = 2.0,
                min_stick: int = 4) -> Mesh:
    """Mesh with a node at c, graded toward c (from both sides) and toward a.

    Parameters
    ----------
    n : int
        Number of elements.
    stick_ratio : float
        c/a in [0, 1].
    power : float
        Grading exponent (1 = uniform). Element size at c and at a ~ 1/n^power.
    min_stick : int
        Minimum number of elements in each zone when 0 < c < 1.
    """
    c = float(stick_ratio)
    if c <= 0.0 or c >= 1.0:
        t = np.linspace(0.0, 1.0, n + 1)
        nodes = _toward_end(t, power)
        nodes[0], nodes[-1] = 0.0, 1.0
        return Mesh(nodes, 0 if c <= 0.0 else n)
    frac = 0.25 + 0.5 * c  # share of elements in the stick zone
    if n % 16 == 0:  # nested family: the share is fixed in sixteenths, so refining
        # by 2 halves every element and convergence is smooth
        m = (n // 16) * int(np.clip(round(16 * frac), 1, 15))
    else:
        m = int(round(n * frac))
    m = int(np.clip(m, min_stick, n - min_stick))
    stick = c * _toward_end(np.linspace(0.0, 1.0, m + 1), power)
    slip = c + (1.0 - c) * _toward_both(np.linspace(0.0, 1.0, n - m + 1), power)
    nodes = np.concatenate([stick[:-1], slip])
    nodes[0], nodes[m], nodes[-1] = 0.0, c, 1.0
    return Mesh(nodes, m)


def uniform_mesh(n: int, stick_index: int) -> Mesh:
    """n equal elements (the paper's rings), stick-slip node at m/n."""
    return Mesh(np.linspace(0.0, 1.0, n + 1), stick_index)

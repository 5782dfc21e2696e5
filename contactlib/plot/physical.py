"""A physical history in SI units: its figure and its table (workflow scenes of kind physical).

:func:`physical_history_figure` draws a
:class:`~contactlib.physical.PhysicalHistory` in the units of its input: the
contact and stick radii (µm) against the force (N) along the path, and the
pressure and shear (MPa) against the radius (µm) at the largest force.
:func:`physical_table` gives its numbers a path point and a cycle as rows of
:func:`contactlib.io.write_table`. As for every figure of :mod:`contactlib.plot`,
the figure is built with :class:`matplotlib.figure.Figure` inside the contactlib
style, its layout settled and frozen, and nothing here touches the disk.

Examples
--------
>>> from contactlib.physical import physical_history
>>> from contactlib.plot.physical import physical_table
>>> res = physical_history("sphere", "5mm", "0N,100N,0N", "steel", "soda_lime_glass", 0.2,
...                        steps=10, n=60, error_estimate=False)
>>> rows = physical_table(res)
>>> [r["at"] for r in rows]
['point 0', 'point 1', 'point 2', 'cycle 1 (points 0-2)']
>>> round(rows[1]["force [N]"])
100
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from matplotlib.figure import Figure

from .base import finish, palette, style_context

__all__ = ["physical_history_figure", "physical_table"]

_UM, _MPA = 1e6, 1e-6


def physical_table(res: Any) -> list[dict[str, Any]]:
    """Rows of a physical history: each path point, then each cycle, in SI.

    Parameters
    ----------
    res : contactlib.physical.PhysicalHistory

    Returns
    -------
    list of dict
        Columns ``at`` (``point i`` or ``cycle m (points s-e)``), ``force [N]``,
        ``contact radius [m]``, ``stick radius [m]``, ``stick radius error [m]``,
        ``peak pressure [Pa]``, ``P/P_Hertz(a)``, ``frictional energy [J]``
        (cumulative at a point, of the cycle on a cycle row), ``frictional energy
        error [J]`` and ``viscous energy [J]`` (likewise); NaN where a column does
        not apply (no contact, a cycle row's state columns).
    """
    r = res.result
    nan = math.nan
    scale = float(getattr(r, "work_scale", nan)) * (float(res.frictional_energy[-1]) / float(
        r.frictional_work[-1]) if float(r.frictional_work[-1]) else nan)
    rows = []
    for i in range(len(res.load_path)):
        j = r.segment_end(i) if i else 0
        err = float(np.asarray(res.energy_error)[j]) * scale if i else 0.0
        rows.append({
            "at": f"point {i}", "force [N]": float(res.force[j]),
            "contact radius [m]": float(res.contact_radius[j]),
            "stick radius [m]": float(res.stick_radius[j]),
            "stick radius error [m]": float(res.stick_radius_error[j]),
            "peak pressure [Pa]": float(res.peak_pressure[j]),
            "P/P_Hertz(a)": res.load_ratio_hertz(j),
            "frictional energy [J]": float(res.frictional_energy[j]),
            "frictional energy error [J]": err,
            "viscous energy [J]": float(res.viscous_energy[j])})
    for m, (s, e) in enumerate(res.cycles):
        rows.append({
            "at": f"cycle {m + 1} (points {s}-{e})", "force [N]": nan,
            "contact radius [m]": nan, "stick radius [m]": nan,
            "stick radius error [m]": nan, "peak pressure [Pa]": nan, "P/P_Hertz(a)": nan,
            "frictional energy [J]": float(res.cycle_frictional_energy[m]),
            "frictional energy error [J]": float(res.cycle_energy_error[m]),
            "viscous energy [J]": float(res.cycle_viscous_energy[m])})
    return rows


def physical_history_figure(res: Any, title: str = "") -> Figure:
    """The radii along the path and the tractions at the largest force, in SI units.

    Left: the contact radius a and the stick radius c [µm] against the force P [N],
    step by step (the path's direction of travel in the order of the points).
    Right: the pressure p and the shear q [MPa] against r [µm] at the first step of
    the largest force. Lines carry a ``gid``: ``contact-radius``, ``stick-radius``,
    ``pressure``, ``shear``.

    Parameters
    ----------
    res : contactlib.physical.PhysicalHistory
    title : str
        Shown above the panels (e.g. the scene's name).

    Returns
    -------
    matplotlib.figure.Figure
    """
    with style_context():
        colours = palette()
        fig = Figure(figsize=(7.0, 3.2), layout="constrained")
        left, right = fig.subplots(1, 2)
        force = np.asarray(res.force, dtype=float)
        left.plot(force, np.asarray(res.contact_radius) * _UM, color=colours[0],
                  label="contact radius a", gid="contact-radius")
        left.plot(force, np.asarray(res.stick_radius) * _UM, color=colours[1],
                  linestyle="--", label="stick radius c", gid="stick-radius")
        left.set_xlabel("force P [N]")
        left.set_ylabel("radius [µm]")
        left.legend(loc="upper left", fontsize="small")
        peak = int(np.argmax(force))
        prof = res.profiles(peak)
        right.plot(prof["r"] * _UM, prof["pressure"] * _MPA, color=colours[0],
                   label="pressure p", gid="pressure")
        right.plot(prof["r"] * _UM, prof["shear"] * _MPA, color=colours[1], linestyle="--",
                   label="shear q", gid="shear")
        right.set_xlabel("r [µm]")
        right.set_ylabel("traction [MPa]")
        right.set_title(f"at P = {force[peak]:.4g} N", fontsize="small")
        right.legend(loc="upper right", fontsize="small")
        shape = (f"R = {res.radius * 1e3:.4g} mm" if getattr(res, "profile", "paraboloid")
                 == "paraboloid" else f"cone, half-angle {res.half_angle:g}°")
        fig.suptitle(f"{title + ': ' if title else ''}{res.geometry}, {shape}, "
                     f"{res.indenter} on {res.body}, k = {res.friction:g}", fontsize="small")
        return finish(fig)

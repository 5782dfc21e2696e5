"""A parsed namespace to the checked keyword arguments of one entry point.

One function a kind of run: :func:`validate_solve` (``solve``, ``sweep``),
:func:`validate_history`, :func:`validate_planned_history` (``history
--tolerance``), :func:`validate_fretting` (``history --tangential-path``) and
:func:`validate_physical` (physical units, :mod:`contactlib.physical`);
:func:`is_physical` tells whether the physical options are given. All of them
run before any numerics, so that bad input never starts a computation.
"""

from __future__ import annotations

import argparse
import re
from collections.abc import Callable
from typing import Any

from contactlib import validate
from contactlib.cli.inputs import (SolverLimitError, UsageError, checked, parse_base,
                                   parse_fraction, parse_friction, parse_history_n,
                                   parse_history_path, parse_indenter, parse_load_path,
                                   parse_max_error, parse_n, parse_nu, parse_relaxation,
                                   parse_slab_ratio, parse_steps, parse_stick_ratios,
                                   parse_substrate, parse_tolerance, parse_viscoelastic,
                                   path_source, profile_kwargs, required_value, to_float, to_int,
                                   to_list, usage)


def _method(args: argparse.Namespace) -> str | None:
    """``--method`` checked, or None when not given (the default, or planned)."""
    return None if args.method is None else checked(validate.method, args.method, args.method)


def validate_solve(args: argparse.Namespace) -> dict[str, Any]:
    """Turn raw option strings into checked keyword arguments of solve/sweep."""
    geometry = checked(validate.geometry, args.geometry, args.geometry)
    chosen = _method(args) or validate.DEFAULT_METHOD  # the method run without a tolerance
    n = None if args.n is None else parse_n(args.n, chosen)
    base = parse_base(args.base, coated=True)
    kwargs: dict[str, Any] = {
        "geometry": geometry,
        "nu": parse_nu(required_value(args.nu, "--nu")),
        "n": n,
        "method": chosen,
        "slab_ratio": parse_slab_ratio(args.slab_ratio, geometry, base),
        "energy": not args.no_energy,
        "max_error": parse_max_error(args.max_error),
    }
    if args.tolerance is not None:
        kwargs["tolerance"] = parse_tolerance(args.tolerance)
        if args.n is not None or args.method is not None:
            raise UsageError("--tolerance must be given without --n and --method (the plan "
                             f"picks them), got --tolerance {args.tolerance!r} with them")
        kwargs["method"] = None  # planned
    ratio, nu1 = parse_indenter(args.indenter_modulus, args.indenter_nu)
    if ratio != float("inf"):  # the rigid default is the library's: keywords only when elastic
        kwargs["indenter_modulus"], kwargs["indenter_nu"] = ratio, nu1
    if base != "smooth":  # likewise: the keyword only when not the default
        kwargs["base"] = base
    kwargs.update(parse_substrate(args, base, geometry, chosen))
    kwargs.update(profile_kwargs(args))  # likewise
    if args.command == "solve":
        if args.stick_ratio is not None:
            kwargs["stick_ratio"] = parse_fraction("--stick-ratio", args.stick_ratio)
        else:
            kwargs["friction"] = parse_friction(args.friction)
    else:
        kwargs["stick_ratios"] = parse_stick_ratios(args.stick_ratios,
                                                    validate.n(n, chosen))
    return kwargs


def validate_history(args: argparse.Namespace) -> dict[str, Any]:
    """Checked keyword arguments of :func:`contactlib.history`."""
    geometry = checked(validate.geometry, args.geometry, args.geometry)
    base = parse_base(args.base, coated=True)
    shaped = path_source(args) != "--load-path"
    kwargs = {
        "geometry": geometry,
        "nu": parse_nu(required_value(args.nu, "--nu")),
        "friction": parse_friction(args.friction),
        "load_path": (parse_history_path(args, physical=False) if shaped
                      else parse_load_path(args.load_path)),
        "steps": None if args.steps is None else parse_steps(args.steps),
        "n": None if args.n is None else parse_history_n(args.n),
        "slab_ratio": parse_slab_ratio(args.slab_ratio, geometry, base,
                                       validate.HISTORY_MESH_EXTENT),
        "max_error": parse_max_error(args.max_error),
    }
    ratio, nu1 = parse_indenter(args.indenter_modulus, args.indenter_nu)
    if ratio != float("inf"):  # as for solve/sweep: keywords only when elastic
        kwargs["indenter_modulus"], kwargs["indenter_nu"] = ratio, nu1
    if shaped and args.duration is not None:
        raise UsageError("--duration is not used with --load-shape or --load-table: the "
                         f"path gives its times, got --duration {args.duration!r}")
    if shaped and args.relaxation is not None:  # the shape's or table's own times
        kwargs["relaxation"] = [list(p) for p in parse_relaxation(args.relaxation)]
    elif args.relaxation is not None or args.duration is not None:  # a viscoelastic body
        kwargs.update(parse_viscoelastic(args.relaxation, args.duration,
                                         len(kwargs["load_path"]) - 1))
        if ratio != float("inf"):
            raise UsageError("--relaxation needs a rigid indenter (no --indenter-modulus)")
    if base != "smooth":
        kwargs["base"] = base
    kwargs.update(parse_substrate(args, base, geometry, "default"))
    kwargs.update(profile_kwargs(args))
    return kwargs


def validate_planned_history(args: argparse.Namespace) -> dict[str, Any]:
    """Checked keyword arguments of :func:`contactlib.history` with ``--tolerance`` (the
    plan picks n and steps: :mod:`contactlib.history_plan`)."""
    from contactlib.history_plan import MAX_TOLERANCE, MIN_TOLERANCE

    tol = checked(lambda v: validate.number("tolerance", v, MIN_TOLERANCE, MAX_TOLERANCE),
                 args.tolerance, to_float(args.tolerance))
    given = [o for o, v in (("--steps", args.steps), ("--n", args.n)) if v is not None]
    if args.max_error != f"{validate.PATH_DEFAULT_MAX_ERROR:g}":
        given.append("--max-error")
    if given:
        raise UsageError(f"--tolerance must be given without {', '.join(given)} (the plan "
                         f"picks n and steps, and T is the accuracy asked for), got "
                         f"--tolerance {args.tolerance!r} with them")
    kwargs = validate_history(argparse.Namespace(**{**vars(args), "steps": "1"}))
    kwargs.pop("max_error")
    kwargs.update(steps=None, n=None, tolerance=tol)
    return kwargs


def validate_fretting(args: argparse.Namespace) -> dict[str, Any]:
    """Checked keyword arguments of :func:`contactlib.fretting` (``--tangential-path``)."""
    from contactlib import fretting_api

    for option, given in (("--slab-ratio", args.slab_ratio not in (None, "0")),
                          ("--base", args.base != "smooth"),
                          ("--relaxation", args.relaxation is not None),
                          ("--duration", args.duration is not None),
                          ("--substrate-modulus", getattr(args, "substrate_modulus", None)
                           is not None),
                          ("--substrate-nu", getattr(args, "substrate_nu", None) is not None)):
        if given:
            raise UsageError(f"{option} must be given without --tangential-path: fretting "
                             "is solved for a half-plane (no layer, no viscoelasticity)")
    geometry = checked(validate.geometry, args.geometry, args.geometry)
    kwargs: dict[str, Any] = {
        "geometry": geometry,
        "nu": parse_nu(required_value(args.nu, "--nu")),
        "friction": parse_friction(args.friction),
        "load_path": parse_load_path(args.load_path),
        "tangential_path": to_list(args.tangential_path),
        "steps": fretting_api.defaults(geometry)[1] if args.steps is None
        else parse_steps(args.steps),
        "n": fretting_api.defaults(geometry)[0] if args.n is None else to_int(args.n),
        "max_error": parse_max_error(args.max_error),
    }
    if args.bulk_stress is not None:
        kwargs["bulk_stress"] = to_list(args.bulk_stress)
    if getattr(args, "tangential_displacement", False):
        kwargs["tangential_displacement"] = True
    ratio, nu1 = parse_indenter(args.indenter_modulus, args.indenter_nu)
    if ratio != float("inf"):
        kwargs["indenter_modulus"], kwargs["indenter_nu"] = ratio, nu1
    kwargs.update(profile_kwargs(args))
    try:
        fretting_api.check_input(kwargs["geometry"], kwargs["friction"], kwargs["load_path"],
                                 kwargs["tangential_path"], kwargs["steps"], kwargs["n"],
                                 kwargs.get("bulk_stress"), kwargs["max_error"],
                                 nu=kwargs["nu"], indenter_modulus=ratio, indenter_nu=nu1,
                                 tangential_displacement=kwargs.get("tangential_displacement",
                                                                    False))
    except validate.SolverLimit as exc:  # the sphere's coupled tangential load: status 3
        raise SolverLimitError(exc) from exc
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    return kwargs


_PHYSICAL = ("radius", "load", "indenter", "body", "length", "thickness", "times",
             "substrate")


_UNIT_RE = re.compile(r"^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*[A-Za-zµμ]+\s*$")


def path_has_units(text: str) -> bool:
    """A load path with a number and a unit anywhere (``0N,100N,0N``): forces, not levels
    (``0,x`` is a bad list of levels, not a force path)."""
    return any(_UNIT_RE.match(item) for item in text.split(","))


def is_physical(args: argparse.Namespace) -> bool:
    """True when any physical option is given, or a history's load path has units."""
    if any(getattr(args, name, None) is not None for name in _PHYSICAL):
        return True
    if args.command != "history":
        return False
    return any(text is not None and path_has_units(text)
               for text in (args.load_path, args.amplitude, args.mean))


def _physical_check(rule: Callable[..., Any], *args: Any) -> Any:
    """``rule(*args)`` of :mod:`contactlib.physical`, its errors as usage errors."""
    try:
        return rule(*args)
    except ValueError as exc:
        raise usage(exc) from None


def validate_physical(args: argparse.Namespace) -> dict[str, Any]:
    """Checked keyword arguments of :func:`contactlib.physical.physical_solve` or
    :func:`~contactlib.physical.physical_history` (the physical options replace --nu,
    --indenter-modulus, --indenter-nu and --slab-ratio)."""
    from contactlib import physical

    geometry = checked(validate.geometry, args.geometry, args.geometry)
    for option, given in (("--nu", args.nu is not None),
                          ("--indenter-modulus", args.indenter_modulus != "inf"),
                          ("--indenter-nu", args.indenter_nu is not None),
                          ("--slab-ratio", args.slab_ratio != "0"),
                          ("--substrate-modulus",
                           getattr(args, "substrate_modulus", None) is not None),
                          ("--substrate-nu", getattr(args, "substrate_nu", None) is not None),
                          ("--exponent", getattr(args, "exponent", None) is not None)):
        if given:
            raise UsageError(f"{option} is not used with physical units (--radius, --body, "
                             f"--indenter, --thickness give the problem), got {option} with "
                             "them")
    profile = getattr(args, "profile", "paraboloid")
    cone = profile == "cone"
    if profile != "paraboloid" and not cone:
        raise UsageError(f"--profile {profile} is not available with physical units: they "
                         "take the paraboloid (--radius) or the cone (--profile cone "
                         "--half-angle DEG); give the dimensionless problem (--nu) instead")
    if getattr(args, "half_angle", None) is not None and not cone:
        raise UsageError(f"--half-angle is for --profile cone, got --half-angle "
                         f"{args.half_angle!r} with --profile {profile}")
    if cone and args.radius is not None:
        raise UsageError(f"--radius is not used with --profile cone (--half-angle gives the "
                         f"cone), got --radius {args.radius!r}")
    radius = None if cone else _physical_check(
        physical.parse_quantity, required_value(args.radius, "--radius"), "length", "radius")
    body = _physical_check(physical.material, required_value(args.body, "--body"), "body")
    indenter = _physical_check(physical.material,
                               "rigid" if args.indenter is None else args.indenter, "indenter")
    kwargs: dict[str, Any] = {"geometry": geometry, "radius": radius, "indenter": indenter,
                              "body": body, "base": parse_base(args.base, coated=True),
                              "max_error": parse_max_error(args.max_error)}
    if cone:
        kwargs.update(profile="cone", half_angle=_physical_check(
            physical.parse_half_angle, required_value(args.half_angle, "--half-angle")))
    if geometry == "cylinder":
        kwargs["length"] = _physical_check(physical.parse_quantity,
                                           required_value(args.length, "--length"), "length",
                                           "length")
    elif args.length is not None:
        raise UsageError(f"--length is for a cylinder only, got --length {args.length!r} "
                         "with --geometry sphere")
    if args.thickness is not None:
        kwargs["thickness"] = _physical_check(physical.parse_quantity, args.thickness,
                                              "length", "thickness")
    if args.substrate is not None:
        kwargs["substrate"] = _physical_check(physical.material, args.substrate, "substrate")
    if args.command == "solve":
        kwargs["load"] = _physical_check(physical.parse_quantity,
                                         required_value(args.load, "--load"), "force", "load")
        method = _method(args)
        kwargs.update(method=method, n=None if args.n is None
                      else parse_n(args.n, method or validate.DEFAULT_METHOD),
                      energy=not args.no_energy)
        if args.tolerance is not None:
            kwargs["tolerance"] = parse_tolerance(args.tolerance)
        if args.stick_ratio is not None:
            kwargs["stick_ratio"] = parse_fraction("--stick-ratio", args.stick_ratio)
        else:
            kwargs["friction"] = parse_friction(args.friction)
        return kwargs
    shaped = path_source(args) != "--load-path"
    if shaped:
        forces: Any = parse_history_path(args, physical=True)
    elif not path_has_units(args.load_path):
        raise UsageError(f"--load-path must be forces with a unit (0N,100N,0N) with physical "
                         f"units, got {args.load_path!r}")
    elif any(not path_has_units(item) and item.strip() not in ("0",)
             for item in args.load_path.split(",")):
        raise UsageError(f"--load-path must give every force with its unit (0N,100N,0N), "
                         f"got {args.load_path!r}")
    else:
        forces = _physical_check(physical.parse_force_path, args.load_path)
    kwargs.update(load_path=forces, friction=parse_friction(args.friction),
                  steps=parse_steps(args.steps) if args.steps is not None
                  else physical.DEFAULT_HISTORY_STEPS,
                  n=None if args.n is None else parse_history_n(args.n))
    if args.duration is not None:
        raise UsageError(f"--duration is not used with physical units: give --times (s), got "
                         f"--duration {args.duration!r}")
    if shaped and args.times is not None:
        raise UsageError("--times is not used with --load-shape or --load-table: the path "
                         f"gives its times, got --times {args.times!r}")
    if not shaped and (args.relaxation is None) != (args.times is None):
        missing = "--times" if args.times is None else "--relaxation"
        raise UsageError(f"--relaxation and --times go together with physical units: "
                         f"{missing} is missing")
    if args.relaxation is not None:
        pairs: list[Any] = []
        for item in args.relaxation.split(","):
            parts = item.split(":")
            if len(parts) != 2:
                raise UsageError(f"--relaxation must be G1:TAU1[,G2:TAU2...], got "
                                 f"{args.relaxation!r}")
            tau = _physical_check(physical.parse_quantity, parts[1].strip(), "time",
                                  "relaxation")
            pairs.append([to_float(parts[0]), tau])
        kwargs["relaxation"] = checked(validate.relaxation, args.relaxation, pairs)
        if shaped:
            return kwargs

        def when(text: str) -> float:
            return physical.parse_quantity(text.strip(), "time", "times", positive=False)

        times = [_physical_check(when, t) for t in args.times.split(",")]
        if len(times) != len(forces) or any(b <= a for a, b in zip(times, times[1:])):
            raise UsageError(f"--times must give {len(forces)} increasing times, one a "
                             f"--load-path point, got {args.times!r}")
        kwargs["times"] = times
    return kwargs

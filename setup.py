"""Build of the compiled parts of contactlib: the fused disc and half-plane strip kernels,
two fused steps of building the nodal operators and the fused set-up of Newton's method.

Everything else is in pyproject.toml. The extensions are optional: where they cannot be
built (no C compiler), contactlib uses the numpy routes of :mod:`contactlib.kernels.disc`,
:mod:`contactlib.kernels.strip`, :func:`contactlib.discretization.influence.apply_difference` and
:func:`contactlib.discretization.operators.restrict_nested` and
:func:`contactlib.solvers.default_method.newton_on_k`,
which give the same bits, more slowly.
"""

from setuptools import Extension, setup

# IEEE operations as written: no fused multiply-adds, no reassociation (the same bits as
# the numpy routes)
FLAGS = ["-O3", "-ffp-contract=off", "-fno-fast-math"]

setup(ext_modules=[
    Extension(name, sources=[source], extra_compile_args=FLAGS, optional=True)
    for name, source in (("contactlib.kernels.disc_fused", "contactlib/kernels/disc_fused.c"),
                         ("contactlib.kernels.strip_fused", "contactlib/kernels/strip_fused.c"),
                         ("contactlib.discretization.operators_fused",
                          "contactlib/discretization/operators_fused.c"),
                         ("contactlib.solvers.solver_fused", "contactlib/solvers/solver_fused.c"))])

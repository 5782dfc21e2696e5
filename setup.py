"""Build of the one compiled part of contactlib: the fused disc kernels.

Everything else is in pyproject.toml. The extension is optional: where it cannot be built
(no C compiler), contactlib uses the numpy route of :mod:`contactlib.kernels.disc`, which
gives the same bits, about five times more slowly.
"""

from setuptools import Extension, setup

setup(ext_modules=[Extension(
    "contactlib.kernels.disc_fused",
    sources=["contactlib/kernels/disc_fused.c"],
    # IEEE operations as written: no fused multiply-adds, no reassociation (the same bits
    # as the numpy route)
    extra_compile_args=["-O3", "-ffp-contract=off", "-fno-fast-math"],
    optional=True,
)])

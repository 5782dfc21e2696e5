"""The solvers: a checked `Contact` and its operators in, discrete solutions out.

One solver family a module (docs/architecture.md): the self-similar methods
(`default_method`, `extrapolated_method`, `paper_method`), the incremental history solver
(`history_solver`) and the tangential-load solvers (`fretting_solver`: the cylinder,
`fretting_sphere`: the sphere). They do no I/O and no plotting. Nothing is re-exported:
use a solver through its module path, ``contactlib.solvers.default_method.X``.
"""

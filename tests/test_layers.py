"""The import rules of docs/architecture.md: data flows one way through the layers.

Read from the source (``ast``), so function-local imports count too.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import contactlib

PACKAGE = Path(contactlib.__file__).resolve().parent

# model, operators, solver, checks/energy, result: they return data
NUMERICS = ("model/__init__", "model/geometry", "model/theory", "model/problem",
            "model/profiles", "model/indenter", "model/body", "model/materials",
            "model/load_paths", "kernels/disc", "kernels/strip", "discretization/__init__",
            "discretization/elements", "discretization/influence", "discretization/operators",
            "solvers/__init__", "solvers/default_method", "solvers/extrapolated_method",
            "solvers/paper_method", "solvers/history_solver", "stages", "accuracy",
            "checks", "energy", "result", "api", "history_api", "convergence",
            "discrete", "kernels/layer", "kernels/thin_layer", "kernels/layer_transfer",
            "layer_study", "solvers/fretting_solver", "solvers/fretting_sphere",
            "fretting_api", "estimates", "coating_study", "stresses/__init__", "stresses/inputs",
            "stresses/halfplane", "stresses/quadrature", "stresses/pieces", "stresses/surface",
            "stresses/halfspace", "stresses/layer", "stresses/dispatch", "stresses/measures",
            "stresses/solution", "stresses/datasets", "stresses/estimate", "stresses/history",
            "stresses/fretting", "stresses/tangential", "stresses/grid")
# what the numerics never import: files and conventions (io), figures, workflow
FORBIDDEN_IN_NUMERICS = ("contactlib.io", "contactlib.plot", "matplotlib", "snakemake",
                         "contactlib.pipeline", "contactlib.scene", "contactlib.cli")
# private names imported across modules that the validation module of issue 13 removes;
# nothing may be added here
KNOWN_PRIVATE_IMPORTS: set[tuple[str, str, str]] = set()  # none left


def _module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE).with_suffix("").parts
    return ".".join(["contactlib", *parts]).removesuffix(".__init__")


def _imports(path: Path) -> list[tuple[str, list[str]]]:
    """(imported module, names) of every import in the file, relative ones resolved."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    here = _module_name(path).split(".")
    if path.name != "__init__.py":
        here = here[:-1]  # the package the module lives in
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [(alias.name, []) for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = here[:len(here) - node.level + 1] if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            names = [alias.name for alias in node.names]
            found.append((module, names))
            found += [(f"{module}.{n}", []) for n in names]  # `from contactlib import io`
    return found


def _source(name: str) -> Path:
    return PACKAGE / f"{name}.py"


@pytest.mark.parametrize("name", NUMERICS)
def test_numerics_import_neither_io_nor_plotting(name):
    for module, _ in _imports(_source(name)):
        for banned in FORBIDDEN_IN_NUMERICS:
            assert not (module == banned or module.startswith(banned + ".")), (
                f"contactlib/{name}.py imports {module}: the numerics return data, "
                f"io and plot turn it into files and figures")


def test_io_does_not_import_plotting():
    for path in (PACKAGE / "io").glob("*.py"):
        for module, _ in _imports(path):
            assert not module.startswith("contactlib.plot"), (path.name, module)


@pytest.mark.parametrize("path", sorted(PACKAGE.rglob("*.py")), ids=lambda p: p.name)
def test_no_module_imports_private_names_of_another(path):
    own = _module_name(path).removeprefix("contactlib.")
    for module, names in _imports(path):
        if not module.startswith("contactlib"):
            continue
        for name in names:
            if name.startswith("_") and not name.startswith("__"):
                assert (own, module, name) in KNOWN_PRIVATE_IMPORTS, (
                    f"{path.relative_to(PACKAGE.parent)} imports the private name {name} "
                    f"of {module}")


@pytest.mark.parametrize("path", sorted(PACKAGE.rglob("*.py")), ids=lambda p: p.name)
def test_no_module_reaches_into_another_modules_private_names(path):
    """``stages._record(...)`` is the same reach as importing ``_record``: refused too."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    modules = set()  # local names bound to modules of the package
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and (node.level or (node.module or "").startswith(
                "contactlib")):
            modules |= {alias.asname or alias.name for alias in node.names
                        if (PACKAGE / f"{alias.name}.py").exists()
                        or (PACKAGE / alias.name).is_dir()}
        elif isinstance(node, ast.Import):
            modules |= {alias.asname for alias in node.names
                        if alias.asname and alias.name.startswith("contactlib.")}
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) \
                and node.value.id in modules and node.attr.startswith("_") \
                and not node.attr.startswith("__"):
            raise AssertionError(f"{path.relative_to(PACKAGE.parent)}:{node.lineno} uses the "
                                 f"private name {node.value.id}.{node.attr}")


def test_no_public_function_hides_a_module():
    for name in contactlib.__all__:
        assert not _source(name).exists() and not (PACKAGE / name).is_dir(), (
            f"contactlib.{name} is both a public name and a module")


def test_plot_modules_build_on_the_public_base_only():
    for path in (PACKAGE / "plot").glob("*.py"):
        for module, names in _imports(path):
            if module.startswith("contactlib.plot"):
                assert all(not n.startswith("_") for n in names), (path.name, module, names)


# ----------------------------------------------------------------------------- layer order
# docs/architecture.md, "The layers": every module's layer, in import order. A module
# imports only its own layer and those before it; a new module must be placed here.
LAYER_ORDER = ("validation", "model", "operators", "leaf numerics", "solver", "entry points",
               "io", "plot", "workflow")
LAYER_MODULES = {
    "validation": ("validate", "threads"),
    "model": ("model", "kernels"),
    "operators": ("discretization",),
    "leaf numerics": ("checks", "energy", "estimates"),
    "solver": ("discrete", "solvers", "solvers.default_method", "solvers.extrapolated_method",
               "solvers.paper_method", "solvers.history_solver", "stages", "accuracy",
               "solvers.fretting_solver", "solvers.fretting_sphere", "solvers.solver_fused",
               "result"),
    "entry points": ("api", "history_api", "history_plan", "fretting_api", "convergence",
                     "layer_study", "coating_study", "physical", "physical_fretting",
                     "stress_study", "stresses", "stresses.inputs", "stresses.halfplane",
                     "stresses.quadrature", "stresses.pieces", "stresses.surface",
                     "stresses.halfspace", "stresses.layer", "stresses.dispatch",
                     "stresses.measures", "stresses.solution", "stresses.datasets",
                     "stresses.estimate", "stresses.history", "stresses.fretting",
                     "stresses.tangential", "stresses.grid"),
    "io": ("io", "io.conventions", "io.checksums", "io.atomic", "io.inputs", "io.datasets",
           "io.fretting", "io.physical", "io.files", "io.records"),
    "plot": ("plot",),
    "workflow": ("scene", "pipeline", "summary", "cli.inputs", "cli.parser", "cli.arguments",
                 "cli.report", "cli.remedies", "cli.run", "cli", "__main__", ""),
}
_RANK = {name: LAYER_ORDER.index(layer) for layer, names in LAYER_MODULES.items()
         for name in names}


def _layer_rank(module: str) -> int | None:
    """Rank of a module (``contactlib.kernels.disc`` -> its package ``kernels``'s)."""
    name = module.removeprefix("contactlib").lstrip(".")
    while name not in _RANK:
        if not name:
            return None
        name = name.rpartition(".")[0]
    return _RANK[name]


def _runtime_imports(path: Path) -> list[str]:
    """The package modules a file imports at run time (``if TYPE_CHECKING:`` blocks left
    out; ``from contactlib import io`` counts as ``contactlib.io``)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    typing_only = {id(sub) for node in ast.walk(tree)
                   if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test)
                   for sub in ast.walk(node)}
    here = _module_name(path).split(".")
    if path.name != "__init__.py":
        here = here[:-1]
    found = []
    for node in ast.walk(tree):
        if id(node) in typing_only:
            continue
        if isinstance(node, ast.Import):
            found += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = here[:len(here) - node.level + 1] if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            found.append(module)
            if module in ("contactlib", "contactlib.kernels"):  # modules imported by name
                found += [f"{module}.{alias.name}" for alias in node.names
                          if alias.name != "__version__"]
    return [m for m in found if m.startswith("contactlib.")
            and m not in ("contactlib.kernels",)]


ALL_MODULES = sorted(PACKAGE.rglob("*.py"))


@pytest.mark.parametrize("path", ALL_MODULES, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_every_module_has_a_layer(path):
    assert _layer_rank(_module_name(path)) is not None, (
        f"{path.relative_to(PACKAGE.parent)} is in no layer: place it in LAYER_MODULES "
        f"and in docs/architecture.md")


@pytest.mark.parametrize("path", ALL_MODULES, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_imports_go_to_earlier_layers_only(path):
    mine = _layer_rank(_module_name(path))
    for module in _runtime_imports(path):
        theirs = _layer_rank(module)
        assert theirs is not None and theirs <= mine, (
            f"{path.relative_to(PACKAGE.parent)} ({LAYER_ORDER[mine]}) imports {module} "
            f"({LAYER_ORDER[theirs] if theirs is not None else 'no layer'}): a layer imports "
            f"only itself and the layers before it (docs/architecture.md)")


def test_kernels_are_closed_forms_only():
    """docs/architecture.md: ``contactlib/kernels/`` imports nothing else of contactlib."""
    for path in (PACKAGE / "kernels").glob("*.py"):
        for module in _runtime_imports(path):
            assert module.startswith("contactlib.kernels."), (path.name, module)


def test_the_layers_page_names_every_layer():
    text = (PACKAGE.parent / "docs" / "architecture.md").read_text(encoding="utf-8")
    assert " ─► ".join(LAYER_ORDER) in text


def test_no_module_imports_itself_through_others():
    """No import cycle, function-local imports included (issue 36: the last one,
    kernels/layer <-> kernels/thin_layer, went when their shared transfer functions
    moved to kernels/layer_transfer)."""
    graph = {_module_name(p): {m for m in _runtime_imports(p) if m != _module_name(p)}
             for p in ALL_MODULES}
    done: set[str] = set()

    def visit(module: str, path: list[str]) -> None:
        if module in path:
            cycle = path[path.index(module):] + [module]
            raise AssertionError("import cycle: " + " -> ".join(cycle))
        if module in done:
            return
        for nxt in sorted(graph.get(module, ())):
            visit(nxt, path + [module])
        done.add(module)

    for module in sorted(graph):
        visit(module, [])

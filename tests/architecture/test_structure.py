"""The structure the architecture promises, checked on the source: no import cycles between modules nor
between packages, small modules, the engine below everything, matplotlib only in the report, heavy libraries
never at start-up."""

from __future__ import annotations

import ast
from pathlib import Path

SRC = Path(__file__).resolve().parents[2] / "src" / "machdyn"
ENGINE = "machdyn.linkage"


def _module_name(path: Path) -> str:
    parts = path.relative_to(SRC.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {_module_name(p): p for p in SRC.rglob("*.py")}


def _targets(node: ast.ImportFrom | ast.Import, package: str) -> set[str]:
    """The machdyn modules an import statement loads: ``from .pkg import mod`` is the module ``pkg.mod`` (its
    package is already being imported), ``from .mod import name`` the module ``mod``."""
    if isinstance(node, ast.Import):
        return {a.name for a in node.names if a.name.startswith("machdyn")}
    if node.level:
        base = package.split(".")
        base = base[: len(base) - (node.level - 1)]
        target = ".".join(base + ([node.module] if node.module else []))
    else:
        target = node.module or ""
    if not target.startswith("machdyn"):
        return set()
    modules = {f"{target}.{a.name}" for a in node.names if f"{target}.{a.name}" in MODULES}
    names = [a for a in node.names if f"{target}.{a.name}" not in MODULES]
    return modules | ({target} if names else set())


def _import_nodes(path: Path):
    """(import node, made at module level?) of every import outside ``if TYPE_CHECKING:`` blocks."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    skip: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            skip.update(id(n) for n in ast.walk(node))
    top = {id(n) for n in tree.body}
    for node in ast.walk(tree):
        if isinstance(node, ast.Import | ast.ImportFrom) and id(node) not in skip:
            yield node, id(node) in top


def _package(name: str, path: Path) -> str:
    return name if path.name == "__init__.py" else name.rsplit(".", 1)[0]


def _imports(path: Path) -> set[str]:
    """The machdyn modules a module imports, at any level (inside functions too), except for type checking."""
    name = _module_name(path)
    return {t for node, _ in _import_nodes(path) for t in _targets(node, _package(name, path))}


def _with_packages(target: str, importer: str) -> set[str]:
    """A module and the packages whose ``__init__`` runs before it, except the importer's own (already running)."""
    parts = target.split(".")
    found = {".".join(parts[:i]) for i in range(2, len(parts) + 1)}
    return {m for m in found if m == target or not importer.startswith(m + ".")}


def _graph() -> dict[str, set[str]]:
    return {name: {m for t in _imports(path) for m in _with_packages(t, name) if m in MODULES and m != name}
            for name, path in MODULES.items()}


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components of more than one module (Tarjan), ignoring a package's own __init__."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out: list[list[str]] = []
    counter = [0]

    def visit(v: str) -> None:
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in graph:
        if v not in index:
            visit(v)
    return out


def test_no_import_cycles():
    """Counting the imports made inside functions: no module reaches itself, packages included."""
    assert _cycles(_graph()) == []


def _unit(module: str) -> str:
    """The package a module belongs to: its first part under machdyn (a subpackage or a top-level module)."""
    return module.split(".")[1]


def _package_graph() -> dict[str, set[str]]:
    """Package -> the packages it imports, counting every import: inside functions and for type checking too
    (a package cycle is a design fault even where Python happens to resolve it). The root package only
    re-exports, lazily, and is left out."""
    graph: dict[str, set[str]] = {}
    for name, path in MODULES.items():
        if name == "machdyn":
            continue
        unit = _unit(name)
        tree = ast.parse(path.read_text(encoding="utf-8"))
        nodes = [n for n in ast.walk(tree) if isinstance(n, ast.Import | ast.ImportFrom)]
        targets = {t for node in nodes for t in _targets(node, _package(name, path)) if t != "machdyn"}
        graph.setdefault(unit, set()).update(_unit(t) for t in targets if _unit(t) != unit)
    return graph


def test_no_import_cycles_between_packages():
    """No package reaches itself through the imports of its modules (``cams`` -> ``dynamics`` -> ``cams``)."""
    graph = _package_graph()
    assert {u for targets in graph.values() for u in targets} <= set(graph)
    assert _cycles(graph) == []


def test_the_package_graph_counts_every_import():
    """The package graph sees an import made inside a function (the command line loads the studies only when a
    run needs them), and the cycle finder finds a cycle of packages."""
    graph = _package_graph()
    assert len(graph) >= 20 and "studies" in graph["cli"] and "linkage" in graph["studies"]
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]


def test_modules_are_small():
    big = {_module_name(p): n for p in SRC.rglob("*.py") if (n := len(p.read_text().splitlines())) > 600}
    assert big == {}


def test_the_engine_imports_nothing_above_it():
    allowed = ("machdyn.linkage", "machdyn.errors", "machdyn.units", "machdyn.constants")
    for path in (SRC / "linkage").rglob("*.py"):
        above = {m for m in _imports(path) if not m.startswith(allowed) and m != "machdyn"}
        assert above == set(), (path.name, above)


def test_only_the_command_line_reaches_the_studio_and_only_the_studio_the_web():
    """The studio is a front end: no analysis imports it, and the web framework and server are imported by its
    modules alone (the command line imports the studio inside its command, so start-up loads neither)."""
    web = ("starlette", "uvicorn", "tomlkit", "httpx")
    for name, path in MODULES.items():
        if name.startswith("machdyn.studio"):
            continue
        for node, top in _import_nodes(path):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else [node.module or ""]
            assert not any(n.split(".")[0] in web for n in names if not getattr(node, "level", 0)), name
            studio = {t for t in _targets(node, _package(name, path)) if t.startswith("machdyn.studio")}
            if name == "machdyn.cli":
                assert studio <= {"machdyn.studio.server"} and not (studio and top), name
            else:
                assert not studio, name


def test_only_the_report_imports_matplotlib():
    for path in SRC.rglob("*.py"):
        if "report" in path.relative_to(SRC).parts:
            continue
        text = path.read_text(encoding="utf-8")
        assert "import matplotlib" not in text and "from matplotlib" not in text, path


#: The libraries, by exact module name, that a module may import inside a function: optional or heavy ones that
#: only some runs need (numba compiles, Dask distributes, pymoo searches several objectives, scipy solves,
#: matplotlib draws, pandas and pyarrow write tables). Everything else is imported at the top of a module.
LAZY_LIBRARIES = frozenset({
    "numba", "dask", "distributed", "distributed.comm", "distributed.comm.core", "distributed.scheduler",
    "pymoo.algorithms.moo.nsga2", "pymoo.core.callback", "pymoo.core.problem", "pymoo.indicators.hv",
    "pymoo.optimize", "scipy.integrate", "scipy.interpolate", "scipy.linalg", "scipy.optimize", "scipy.signal",
    "scipy.special", "scipy.stats", "matplotlib.figure", "matplotlib.pyplot", "matplotlib.ticker", "pandas", "pyarrow",
    "pyarrow.parquet",
})
#: machdyn's own modules that load one of those libraries when imported: the report (matplotlib, pandas),
#: loaded inside the function that writes one so that ``machdyn check`` never draws.
LAZY_MODULES = frozenset({"machdyn.report", "machdyn.report.tables"})
#: Modules that defer their imports for start-up: the command line (``machdyn --version`` loads neither numpy
#: nor the analyses) and the package's lazy re-exports.
START_UP = frozenset({"machdyn", "machdyn.cli"})
HEAVY = ("numba", "dask", "distributed", "pymoo", "scipy", "matplotlib", "pandas", "pyarrow")


def _loads_heavy_library(module: str, seen: set[str]) -> bool:
    """Whether importing ``module`` imports a heavy library, through its module-level imports."""
    if module in seen:
        return False
    seen.add(module)
    path = MODULES[module]
    for node, top in _import_nodes(path):
        if not top:
            continue
        names = [a.name for a in node.names] if isinstance(node, ast.Import) else [node.module or ""]
        if node.__class__ is ast.ImportFrom and node.level == 0 and names[0].split(".")[0] in HEAVY:
            return True
        if isinstance(node, ast.Import) and any(n.split(".")[0] in HEAVY for n in names):
            return True
        inner = {m for t in _targets(node, _package(module, path)) for m in _with_packages(t, module)}
        if any(_loads_heavy_library(m, seen) for m in inner if m in MODULES):
            return True
    return False


def test_imports_inside_functions_only_for_heavy_libraries():
    found: dict[str, set[str]] = {}
    for name, path in MODULES.items():
        if name in START_UP:
            continue
        for node, top in _import_nodes(path):
            if top:
                continue
            if isinstance(node, ast.Import):
                targets = {a.name for a in node.names}
            elif node.level == 0 and not (node.module or "").startswith("machdyn"):
                targets = {node.module or ""}
            else:
                targets = _targets(node, _package(name, path))
            for target in targets - LAZY_LIBRARIES - LAZY_MODULES:
                found.setdefault(name, set()).add(target)
    assert found == {}, "import these at the top of the module (or list a heavy library by name)"


def test_lazily_loaded_modules_do_load_a_heavy_library():
    assert {m for m in LAZY_MODULES if not _loads_heavy_library(m, set())} == set()

"""The structure the architecture promises, checked on the source: no import cycles between modules, small
modules, the engine below everything, matplotlib only in the report, heavy libraries never at start-up."""

from __future__ import annotations

import ast
from pathlib import Path

SRC = Path(__file__).resolve().parents[2] / "src" / "machdyn"
ENGINE = "machdyn.linkage"


def _module_name(path: Path) -> str:
    parts = path.relative_to(SRC.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


#: Modules that are loaded inside a function on purpose: the compiled engine, which needs numba and is imported
#: only when asked for; the dispatch to it from the NumPy engine is not a dependency of substance.
OPTIONAL_BACKENDS = ("machdyn.linkage.fused",)


def _imports(path: Path) -> set[str]:
    """The machdyn modules a module imports, at any level (inside functions too), except for type checking and
    the lazy loading of an optional backend."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    package = _module_name(path) if path.name == "__init__.py" else _module_name(path).rsplit(".", 1)[0]
    found: set[str] = set()
    skip: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            skip.update(id(n) for n in ast.walk(node))
    top = {id(n) for n in tree.body}
    for node in ast.walk(tree):
        if id(node) in skip:
            continue
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.startswith("machdyn"))
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                base = base[: len(base) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if id(node) not in top and target.startswith(OPTIONAL_BACKENDS):
                continue
            if target.startswith("machdyn"):
                found.add(target)
                found.update(f"{target}.{a.name}" for a in node.names)
    return found


def _graph() -> dict[str, set[str]]:
    modules = {_module_name(p): p for p in SRC.rglob("*.py")}
    graph = {}
    for name, path in modules.items():
        graph[name] = {m for m in _imports(path) if m in modules and m != name}
    return graph


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
    graph = _graph()
    # A package's __init__ re-exports its modules; a module importing a sibling through the package is the
    # same edge, so edges into a package's own __init__ from inside it are not cycles of substance.
    for name in graph:
        graph[name] = {m for m in graph[name] if not (name.startswith(m + ".") and (SRC.parent / Path(
            *m.split("."))).is_dir())}
    assert _cycles(graph) == []


def test_modules_are_small():
    big = {_module_name(p): n for p in SRC.rglob("*.py") if (n := len(p.read_text().splitlines())) > 600}
    assert big == {}


def test_the_engine_imports_nothing_above_it():
    allowed = ("machdyn.linkage", "machdyn.errors", "machdyn.units", "machdyn.constants")
    for path in (SRC / "linkage").rglob("*.py"):
        above = {m for m in _imports(path) if not m.startswith(allowed) and m != "machdyn"}
        assert above == set(), (path.name, above)


def test_only_the_report_imports_matplotlib():
    for path in SRC.rglob("*.py"):
        if "report" in path.relative_to(SRC).parts:
            continue
        text = path.read_text(encoding="utf-8")
        assert "import matplotlib" not in text and "from matplotlib" not in text, path

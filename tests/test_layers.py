"""The package's layers: no import cycle between eyesim's top-level parts, nor between modules.

A static scan with `ast` of every `import eyesim.X` / `from eyesim.X import ...` in the package,
lazy imports inside functions included, grouped by top-level part (a subpackage such as
`eyesim.robot`, or a root module such as `eyesim.paths`). The part graph must have no cycle, and
each part may import only parts on a lower layer of LAYERS (docs/architecture.md, "Layers").
Inside a part, the module graph must have no cycle either (imports under `if TYPE_CHECKING:` aside:
they never run). The modules of a part kind's folder (`eyesim.parts.<kind>`) count by their role.
"""

import ast
import re
from collections import defaultdict
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "src" / "eyesim"  # the source, as the repository holds it

# Lowest first. A part may import the parts of lower layers, and those before it on its own layer.
LAYERS = [
    ["paths", "platform", "protocol"],
    ["scene"],
    ["physics"],
    ["robot"],
    ["net", "world", "calls"],
    ["viewer"],
    ["core"],
    ["programs", "record", "web"],
    ["testing", "grade", "app"],
]
ENTRY_POINTS = {"__init__", "__main__"}  # the public API and `python -m eyesim` sit above everything
# A part kind's folder (eyesim/parts/<kind>/) cuts across the layers: each of its modules sits on the
# layer of its role, and its packages (docstrings only) on the lowest.
PART_FOLDERS = "parts"
ROLES = {"declaration": "scene", "component": "robot", "calls": "calls"}


def part_of(module: str) -> str | None:
    """`eyesim.robot.build` -> `robot`; None for a module outside eyesim, the bare package, or a name
    the package root defines (`from eyesim import __version__`)."""
    names = module.split(".")
    if names[0] != "eyesim" or len(names) < 2:
        return None
    if names[1] == PART_FOLDERS:
        return ROLES.get(names[3]) if len(names) > 3 else "scene"
    if not ((PACKAGE / f"{names[1]}.py").exists() or (PACKAGE / names[1] / "__init__.py").exists()):
        return None
    return names[1]


def imported_modules(node: ast.AST, module: str, is_package: bool) -> list[str]:
    if isinstance(node, ast.Import):
        return [alias.name for alias in node.names]
    if isinstance(node, ast.ImportFrom):
        if node.level:
            base = module.split(".")
            base = base[: len(base) - node.level + (1 if is_package else 0)]
            target = ".".join(base + ([node.module] if node.module else []))
        else:
            target = node.module or ""
        if target == "eyesim":  # `from eyesim import robot` imports the subpackage
            return [f"eyesim.{alias.name}" for alias in node.names]
        return [target]
    return []


def part_imports() -> dict[tuple[str, str], list[str]]:
    """(importing part, imported part) -> the places, as 'file:line imports module'."""
    edges: dict[tuple[str, str], list[str]] = defaultdict(list)
    for path in sorted(PACKAGE.rglob("*.py")):
        relative = path.relative_to(PACKAGE.parent)
        is_package = path.name == "__init__.py"
        module = ".".join(relative.with_suffix("").parts)
        if is_package:
            module = module.removesuffix(".__init__")
        source = part_of(module) or "__init__"
        if path.parent == PACKAGE and path.stem in ENTRY_POINTS:
            source = path.stem
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            for target in imported_modules(node, module, is_package):
                imported = part_of(target)
                if imported and imported != source:
                    edges[(source, imported)].append(f"{relative}:{node.lineno} imports {target}")
    return edges


def module_name(path: Path) -> str:
    names = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    return ".".join(names[:-1] if names[-1] == "__init__" else names)


def for_type_checkers(tree: ast.AST) -> set[int]:
    """The nodes under `if TYPE_CHECKING:` (ids)."""
    return {
        id(inner)
        for node in ast.walk(tree)
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test)
        for inner in ast.walk(node)
    }


def module_imports() -> dict[tuple[str, str], list[str]]:
    """(importing module, imported module) -> the places; `from package import name` counts as an
    import of the submodule when `name` is one, else of the package."""
    paths = {module_name(path): path for path in sorted(PACKAGE.rglob("*.py"))}
    edges: dict[tuple[str, str], list[str]] = defaultdict(list)
    for module, path in paths.items():
        tree = ast.parse(path.read_text(), str(path))
        skipped = for_type_checkers(tree)
        for node in ast.walk(tree):
            if id(node) in skipped:
                continue
            names = [alias.name for alias in node.names] if isinstance(node, ast.ImportFrom) else [""]
            for target in imported_modules(node, module, path.name == "__init__.py"):
                for name in names:
                    imported = f"{target}.{name}" if f"{target}.{name}" in paths else target
                    if imported in paths and imported != module:
                        edges[(module, imported)].append(f"{path.relative_to(PACKAGE.parent)}:{node.lineno}")
    return edges


def cycles(edges) -> list[list[str]]:
    graph = defaultdict(set)
    for a, b in edges:
        graph[a].add(b)
    found, seen = [], set()

    def visit(part, trail):
        if part in trail:
            found.append(trail[trail.index(part) :] + [part])
            return
        if part in seen:
            return
        for nxt in sorted(graph[part]):
            visit(nxt, trail + [part])
        seen.add(part)

    for part in sorted(graph):
        visit(part, [])
    return found


def describe(edges, pairs) -> str:
    return "\n".join(f"{a} -> {b}:\n    " + "\n    ".join(edges[(a, b)]) for a, b in pairs)


def test_no_import_cycle_between_parts():
    edges = part_imports()
    found = cycles(edges)
    pairs = sorted({(c[i], c[i + 1]) for c in found for i in range(len(c) - 1)})
    assert not found, "import cycles: " + "; ".join(" -> ".join(c) for c in found) + "\n" + describe(edges, pairs)


def test_no_import_cycle_between_modules():
    edges = module_imports()
    found = cycles(edges)
    pairs = sorted({(c[i], c[i + 1]) for c in found for i in range(len(c) - 1)})
    assert not found, "import cycles: " + "; ".join(" -> ".join(c) for c in found) + "\n" + describe(edges, pairs)


def test_the_module_scan_finds_a_cycle_and_ignores_type_checking_imports():
    """The check above can fail: a cycle of two modules is found; an import for type checkers is not one."""
    edges = {("a", "b"): ["a.py:1"], ("b", "a"): ["b.py:3"], ("b", "c"): ["b.py:4"]}
    assert cycles(edges) == [["a", "b", "a"]]
    tree = ast.parse("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from eyesim.core import engine\n")
    imports = [node for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)]
    assert [id(node) in for_type_checkers(tree) for node in imports] == [False, True]


def test_every_part_has_a_layer():
    layered = {part for layer in LAYERS for part in layer}
    parts = (
        {
            p.stem if p.suffix == ".py" else p.name
            for p in PACKAGE.iterdir()
            if (p.suffix == ".py" or (p / "__init__.py").exists())
        }
        - ENTRY_POINTS
        - {PART_FOLDERS}
    )
    assert parts == layered, (
        f"parts without a layer: {sorted(parts - layered)}; layers without a part: {sorted(layered - parts)}"
    )


def test_parts_import_only_lower_layers():
    rank = {part: (i, layer.index(part)) for i, layer in enumerate(LAYERS) for part in layer}
    upward = sorted(
        (a, b)
        for a, b in part_imports()
        if a not in ENTRY_POINTS
        and b in rank
        and a in rank
        and rank[b][0] >= rank[a][0]
        and not (rank[b][0] == rank[a][0] and rank[b][1] < rank[a][1])
    )
    assert not upward, "imports of a part on the same or a higher layer:\n" + describe(part_imports(), upward)


def test_the_scan_sees_lazy_and_relative_imports():
    """The scan is what the layer checks rest on: imports inside functions count too."""
    tree = ast.parse("def f():\n    from eyesim.web import server\n    import eyesim.core.engine\n")
    found = [t for node in ast.walk(tree) for t in imported_modules(node, "eyesim.robot.build", False)]
    assert found == ["eyesim.web", "eyesim.core.engine"]
    relative = ast.parse("from ..scene import loader\n").body[0]
    assert imported_modules(relative, "eyesim.robot.build", False) == ["eyesim.scene"]


def test_every_module_of_a_part_folder_has_a_role():
    """A declaration is read with the robot files, below the physics; a component is the robot's;
    the RoBIOS handlers (calls) sit with the other handlers, above the robot."""
    modules = {path.stem for path in (PACKAGE / PART_FOLDERS).glob("*/*.py")} - {"__init__"}
    assert modules and modules <= set(ROLES), f"modules of no known role: {sorted(modules - set(ROLES))}"
    assert part_of("eyesim.parts.bumper.declaration") == "scene"
    assert part_of("eyesim.parts.bumper.component") == "robot"
    assert part_of("eyesim.parts.psd.calls") == "calls"


# The modules that show the robots' parts (viewer, recorder, plots, editors, settings) learn about
# them only through the components' hooks (robot/component.py), so a new part kind shows up there
# without an edit: they import no module of a part kind.
SHOWING = [
    "eyesim.viewer.messages",
    "eyesim.record.sampling",
    "eyesim.record.signals",
    "eyesim.record.mcap_recorder",
    "eyesim.web.robot_editor",
    "eyesim.web.program_control",
]
COMPONENT_REFERENCE = re.compile(r"^(eyesim(?:\.\w+)+):\w+$")  # a declaration names its components so


def part_kind_modules() -> set[str]:
    """The part kinds' declarations (scene/parts/<kind>.py, parts/<kind>/) and the component modules
    they name ("module:create")."""
    declarations = [p for p in (PACKAGE / "scene" / "parts").glob("*.py") if p.stem != "__init__"]
    folders = list((PACKAGE / PART_FOLDERS).glob("*/*.py"))
    modules = {module_name(path) for path in declarations + folders}
    for path in declarations + folders:
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                found = COMPONENT_REFERENCE.match(node.value)
                if found:
                    modules.add(found.group(1))
    return modules


def test_what_shows_the_parts_names_no_part_kind():
    kinds = part_kind_modules()
    assert {"eyesim.parts.psd.component", "eyesim.parts.lidar.component", "eyesim.parts.psd.declaration"} <= kinds
    assert {"eyesim.parts.bumper.component", "eyesim.parts.bumper.declaration"} <= kinds
    paths = {module_name(path) for path in PACKAGE.rglob("*.py")}
    assert set(SHOWING) <= paths, f"not modules (any more?): {sorted(set(SHOWING) - paths)}"
    named = {
        f"{module} imports {target} ({', '.join(places)})"
        for (module, target), places in module_imports().items()
        if module in SHOWING and target in kinds
    }
    assert not named, "these name a part kind instead of asking the components' hooks:\n" + "\n".join(sorted(named))

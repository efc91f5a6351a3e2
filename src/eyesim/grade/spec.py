"""Grading specs: TOML read, checked against grading.schema.json and against the scenes it names,
with every problem reported as `spec.toml:LINE: what is wrong` (docs/grading.md)."""

from __future__ import annotations

import contextlib
import hashlib
import json
import re
import sys
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING

from eyesim.grade.toml_lines import key_lines, line_of

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    # mypy checks as Python 3.10 ([tool.mypy]) from an environment of a later Python, without tomli
    import tomli as tomllib  # type: ignore[import-not-found]

if TYPE_CHECKING:
    from eyesim.scene import Scene

SCHEMA_PATH = Path(__file__).resolve().parent / "grading.schema.json"
DEFAULT_LIMITS = {"time": 60.0, "wall_clock": 120.0, "cpu": 60.0, "memory_mb": 1024}
INPUT_KINDS = ("key", "touch", "irtv", "serial", "digital", "analog")
TARGETS = ("point", "marker", "object")


class SpecError(Exception):
    """Everything wrong with a spec, one `file:line: message` per problem."""

    def __init__(self, problems: list[str]):
        super().__init__("\n".join(problems))
        self.problems = problems


@dataclass(frozen=True)
class ProgramSpec:
    name: str
    sources: tuple[str, ...]
    language: str = "c"
    flags: tuple[str, ...] = ("-O2",)


@dataclass
class CaseSpec:
    name: str
    scene: Scene  # loaded once here and shipped to the workers
    scene_path: str
    time: float
    wall_clock: float
    cpu: float
    memory_mb: int
    weight: float = 1.0
    end_with_programs: bool = True
    robots: list[dict] = field(default_factory=list)
    inputs: list[dict] = field(default_factory=list)
    checks: list[dict] = field(default_factory=list)


@dataclass
class GradingSpec:
    path: Path
    title: str
    programs: dict[str, ProgramSpec]
    cases: list[CaseSpec]
    python_checks: dict[str, str]  # file as written in the spec -> its source text
    digest: str  # of the spec and every file it uses: results of another spec are never reused

    def case(self, name: str) -> CaseSpec:
        return next(c for c in self.cases if c.name == name)


@lru_cache(maxsize=1)
def schema() -> dict:
    return json.loads(SCHEMA_PATH.read_text())


def load_spec(path: str | Path) -> GradingSpec:
    """Read and check a spec; raises SpecError listing every problem found."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise SpecError([f"{path}: cannot read the grading spec: {error.strerror}"]) from None
    except UnicodeDecodeError:
        raise SpecError([f"{path}: the grading spec is not UTF-8 text"]) from None
    try:
        document = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        message = str(error)
        match = re.search(r"\(at line (\d+), column (\d+)\)", message)
        where = f"{path}:{match[1]}:{match[2]}" if match else str(path)
        raise SpecError([f"{where}: not valid TOML: {re.sub(r' [(]at line.*', '', message)}"]) from None
    return _Checker(path, text, document).spec()


def _table(value) -> dict:
    return value if isinstance(value, dict) else {}


@contextlib.contextmanager
def _passed_over():
    """A part of the spec the schema found malformed: checking it further stops here quietly."""
    try:
        yield
    except (KeyError, TypeError, ValueError, AttributeError, IndexError):
        pass


def _path_text(path) -> str:
    text = ""
    for part in path:
        text += f"[{part}]" if isinstance(part, int) else (f".{part}" if text else str(part))
    return text


class _Checker:
    def __init__(self, path: Path, text: str, document: dict):
        self.path = path
        self.text = text
        self.document = document
        self.lines = key_lines(text)
        self.problems: list[str] = []

    def problem(self, where: tuple, message: str) -> None:
        line = line_of(self.lines, where)
        location = f"{self.path}:{line}" if line else str(self.path)
        self.problems.append(f"{location}: {_path_text(where) + ': ' if where else ''}{message}")

    def spec(self) -> GradingSpec:
        import jsonschema

        from eyesim.scene.json_format import local_refs

        validator = jsonschema.Draft202012Validator(local_refs(schema()))
        for error in sorted(validator.iter_errors(self.document), key=lambda e: [str(p) for p in e.absolute_path]):
            self.problem(tuple(error.absolute_path), self._schema_message(error))
        # On with the scene checks even after schema errors, so one pass reports everything; what
        # the schema found malformed is passed over (it is reported already).
        doc = self.document
        limits = dict(DEFAULT_LIMITS, **_table(doc.get("limits")))
        programs = {}
        for name, p in _table(doc.get("programs")).items():
            with _passed_over():
                programs[name] = ProgramSpec(
                    name,
                    tuple(p["sources"]),
                    p.get("language", "c"),
                    tuple(p.get("flags", ["-O2"] if p.get("language", "c") != "python" else [])),
                )
        python_checks: dict[str, str] = {}
        cases: list[CaseSpec] = []
        names: set[str] = set()
        raw_cases = doc.get("cases")
        for index, raw in enumerate(raw_cases if isinstance(raw_cases, list) else []):
            with _passed_over():
                cases.append(self._case(("cases", index), raw, names, limits, programs, python_checks))
        if self.problems:
            raise SpecError(self.problems)
        from eyesim import __version__

        digest = hashlib.sha256(f"eyesim {__version__}\n{self.text}".encode())
        for name in sorted(python_checks):
            digest.update(python_checks[name].encode())
        for case in cases:
            digest.update(repr(case.scene).encode())  # the scene as loaded, with its robot and world files
        return GradingSpec(
            self.path, doc.get("title", self.path.stem), programs, cases, python_checks, digest.hexdigest()[:16]
        )

    def _case(self, where: tuple, raw: dict, names: set, limits: dict, programs: dict, python_checks: dict) -> CaseSpec:
        if raw["name"] in names:
            self.problem(where + ("name",), f"a second case named {raw['name']!r}")
        names.add(raw["name"])
        scene = self._scene(where + ("scene",), raw["scene"])
        case = CaseSpec(
            raw["name"],
            scene,
            raw["scene"],
            raw.get("time", limits["time"]),
            raw.get("wall_clock", limits["wall_clock"]),
            limits["cpu"],
            limits["memory_mb"],
            raw.get("weight", 1.0),
            raw.get("end_with_programs", True),
            raw.get("robots", []),
            raw.get("inputs", []),
            raw["checks"],
        )
        if scene is not None:
            self._settings(case, raw)
            self._robots(where, case, programs)
            self._inputs(where, case)
            self._checks(where, case, python_checks)
        return case

    @staticmethod
    def _schema_message(error) -> str:
        if error.validator == "additionalProperties":
            unknown = re.findall(r"'([^']+)'", error.message.split("(")[-1]) or [error.message]
            allowed = ", ".join(sorted(error.schema.get("properties", {})))
            return f"unknown key {', '.join(repr(u) for u in unknown)} (known: {allowed})"
        if error.validator == "enum" and error.absolute_path and error.absolute_path[-1] == "kind":
            return f"unknown check kind {error.instance!r} (known: {', '.join(error.validator_value)})"
        if error.validator == "enum":
            return f"{error.instance!r} is not one of {', '.join(map(repr, error.validator_value))}"
        if error.validator == "required":
            return error.message.replace("is a required property", "is missing")
        return error.message

    # -- checks against the scene ------------------------------------------------------------
    def _scene(self, where: tuple, name: str):
        from eyesim.scene import SceneError, builtins, load_scene

        candidate = self.path.parent / name
        source = candidate if candidate.exists() else builtins.scene_path(name)
        if source is None:
            self.problem(where, f"scene {name!r} not found (looked for {candidate})")
            return None
        try:
            return load_scene(source)
        except SceneError as error:
            self.problem(
                where, f"scene {name!r} does not load:\n    " + "\n    ".join(str(d) for d in error.diagnostics)
            )
        except OSError as error:
            self.problem(where, f"cannot read scene {name!r}: {error.strerror}")
        return None

    def _settings(self, case: CaseSpec, raw: dict) -> None:
        import dataclasses

        changes = {key: raw[key] for key in ("seed", "psd_noise") if key in raw}
        if changes:
            case.scene = dataclasses.replace(case.scene, settings=dataclasses.replace(case.scene.settings, **changes))

    def _robot(self, where: tuple, case: CaseSpec, selector) -> int | None:
        robots = case.scene.robots
        if isinstance(selector, int):
            if 1 <= selector <= len(robots):
                return selector
        else:
            for number, placement in enumerate(robots, start=1):
                if placement.type_name.lower() == selector.lower():
                    return number
        listed = ", ".join(f"{n} ({p.type_name})" for n, p in enumerate(robots, start=1)) or "none"
        self.problem(where, f"no robot {selector!r} in scene {case.scene_path!r}; robots: {listed}")
        return None

    def _robots(self, where: tuple, case: CaseSpec, programs: dict) -> None:
        taken = set()
        for index, entry in enumerate(case.robots):
            at = where + ("robots", index)
            number = self._robot(at + ("robot",), case, entry["robot"])
            if number in taken:
                self.problem(at + ("robot",), f"robot {entry['robot']!r} is given two programs")
            taken.add(number)
            entry["robot"] = number
            if entry["program"] not in programs:
                self.problem(
                    at + ("program",),
                    f"no program {entry['program']!r} in [programs] (programs: {', '.join(programs)})",
                )

    def _inputs(self, where: tuple, case: CaseSpec) -> None:
        from eyesim.robot.components.irtv import code_of
        from eyesim.robot.components.lcd import HEIGHT, WIDTH

        for index, entry in enumerate(case.inputs):
            at = where + ("inputs", index)
            entry["robot"] = self._robot(at + ("robot",), case, entry["robot"])
            kinds = [k for k in INPUT_KINDS if k in entry]
            if len(kinds) != 1:
                self.problem(
                    at,
                    f"an input needs exactly one of {', '.join(INPUT_KINDS)}"
                    + (f"; it has {', '.join(kinds)}" if kinds else ""),
                )
                continue
            if "interface" in entry and kinds != ["serial"]:
                self.problem(at + ("interface",), "'interface' goes with a serial input")
            if "touch" in entry:
                x, y = entry["touch"]
                if not (0 <= x < WIDTH and 0 <= y < HEIGHT):
                    self.problem(at + ("touch",), f"({x}, {y}) is outside the {WIDTH}x{HEIGHT} LCD")
            if "irtv" in entry:
                try:
                    code_of(entry["irtv"])
                except ValueError as error:
                    self.problem(at + ("irtv",), str(error))

    def _checks(self, where: tuple, case: CaseSpec, python_checks: dict) -> None:
        for index, check in enumerate(case.checks):
            at = where + ("checks", index)
            kind = check["kind"]
            if "robot" in check:
                check["robot"] = self._robot(at + ("robot",), case, check["robot"])
            targets = [t for t in TARGETS if t in check]
            if kind in ("final_pose", "reach") and len(targets) != 1:
                self.problem(
                    at,
                    f"a {kind} check needs exactly one of point, marker, object"
                    + (f"; it has {', '.join(targets)}" if targets else ""),
                )
            if "marker" in check and check["marker"] > len(case.scene.markers):
                self.problem(
                    at + ("marker",),
                    f"scene {case.scene_path!r} has {len(case.scene.markers)} marker(s), no marker {check['marker']}",
                )
            if "object" in check and check["object"] > len(case.scene.objects):
                self.problem(
                    at + ("object",),
                    f"scene {case.scene_path!r} has {len(case.scene.objects)} object(s), no object {check['object']}",
                )
            if kind == "lcd_text" and ("text" in check) == ("regex" in check):
                self.problem(at, "an lcd_text check needs one of text, regex")
            if kind in ("file", "console") and sum(k in check for k in ("contains", "equals", "regex")) > 1:
                self.problem(at, f"a {kind} check takes one of contains, equals, regex")
            if "regex" in check:
                try:
                    re.compile(check["regex"])
                except re.error as error:
                    self.problem(at + ("regex",), f"not a regular expression: {error}")
            if kind == "python":
                self._python_check(at, check, python_checks)

    def _python_check(self, at: tuple, check: dict, python_checks: dict) -> None:
        file = self.path.parent / check["file"]
        try:
            source = file.read_text(encoding="utf-8")
        except OSError as error:
            self.problem(at + ("file",), f"cannot read custom check file {file}: {error.strerror}")
            return
        try:
            code = compile(source, str(file), "exec")
        except SyntaxError as error:
            self.problem(at + ("file",), f"{file}:{error.lineno}: {error.msg}")
            return
        names = set(code.co_names) | {c.co_name for c in code.co_consts if hasattr(c, "co_name")}
        if check["function"] not in names:
            self.problem(at + ("function",), f"{file} defines no function {check['function']!r}")
        python_checks[check["file"]] = source

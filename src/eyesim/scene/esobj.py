"""The .esObj object format: model, name, scale, mass, colliders, buoyancy, fixed; and its writer.

EyeSim VR files give colliders and the mass centre in the model's own space (X right, Y up,
Z forward, mm of the unscaled model); they become object-frame mm at the object's real size.
Files that say `dialect eyesim` (what we write) already use the object frame at real size.
"""

from __future__ import annotations

from pathlib import Path

from eyesim.scene.description import Collider, Location, ObjectType
from eyesim.scene.diagnostics import Diagnostics, quoted
from eyesim.scene.keyword_reader import KeywordReader
from eyesim.scene.lexer import Line, format_number, integer, number, quote_token, split_lines
from eyesim.parts.part import VR_AXIS, vr_to_robot

SHAPES = {"box": 6, "sphere": 4, "capsule": 6, "cylinder": 6}
FORMS = {
    "box": "<cx> <cy> <cz> <sx> <sy> <sz>",
    "sphere": "<cx> <cy> <cz> <r>",
    "capsule": "<cx> <cy> <cz> <r> <h> <x|y|z>",
    "cylinder": "<cx> <cy> <cz> <r> <h> <x|y|z>",
}


def parse_esobj(text: str, source: str, diagnostics: Diagnostics, where: dict | None = None) -> ObjectType:
    """An ObjectType from .esObj text; the model path stays as written (resolved by the loader).
    `where`, when given, receives the location of the 'model' reference."""
    lines = split_lines(text, source, diagnostics)
    ours = any(
        l.keyword.lower() == "dialect" and len(l.args) == 1 and l.args[0].text.lower() == "eyesim" for l in lines
    )
    reader = _ObjectReader(source, diagnostics, ours)
    for line in lines:
        reader.statement(line)
    if where is not None and reader.model_at is not None:
        where["model"] = reader.model_at
    return reader.object_type()


class _ObjectReader(KeywordReader):
    def __init__(self, source: str, diagnostics: Diagnostics, ours: bool):
        super().__init__(source, diagnostics)
        self.ours = ours
        self.fields: dict = {}
        self.colliders: list[tuple[str, list[float], str]] = []  # as written, scaled at the end
        self.mass_centre: list[float] | None = None
        self.model_at: Location | None = None

    def statement(self, line: Line) -> None:
        word = line.keyword.lower()
        if number(line.keyword) is not None and not line.args:
            self.diagnostics.warning(self.at(line), f"stray number {quoted(line.keyword)} ignored", "ignored-line")
            return
        if word in SHAPES:  # EyeSim VR 2018 wrote shapes without the `collider` keyword
            self.collider(line, 0)
            return
        self.dispatch(line, word)

    def kw_dialect(self, line: Line) -> None:
        if self.arity(line, (1,), "eyesim") and line.args[0].text.lower() not in ("eyesim", "vr"):
            self.error(line, f"dialect: expected eyesim or vr, found {quoted(line.args[0].text)}", 1)

    def kw_obj(self, line: Line) -> None:
        if self.arity(line, (1,), "<model.obj>"):
            self.fields["model"] = line.args[0].text
            self.model_at = self.at(line, 1)

    def kw_name(self, line: Line) -> None:
        if not line.args:
            self.error(line, "name: expected an object name, found nothing")
        else:
            self.fields["name"] = " ".join(t.text for t in line.args)

    def kw_scale(self, line: Line) -> None:
        if self.arity(line, (1,), "<factor>"):
            values = self.numbers(line, 1, ("scale factor",))
            if values:
                if values[0] <= 0:
                    self.error(line, f"scale: expected a factor > 0, found {quoted(line.args[0].text)}", 1, "bad-value")
                else:
                    self.fields["scale"] = values[0]

    def kw_mass(self, line: Line) -> None:
        if not self.arity(line, (1, 4), "<kg> [<x> <y> <z>]"):
            return
        values = self.numbers(line, 1, ("mass in kg", "centre x", "centre y", "centre z")[: len(line.args)])
        if values:
            if values[0] <= 0:
                self.error(line, f"mass: expected kg > 0, found {quoted(line.args[0].text)}", 1, "bad-value")
                return
            self.fields["mass"] = values[0]
            if len(values) == 4:
                self.mass_centre = values[1:]

    def kw_collider(self, line: Line) -> None:
        self.collider(line, 1)

    def collider(self, line: Line, first: int) -> None:
        """A shape whose name is token `first` (1 after `collider`, 0 for a bare shape)."""
        kind = line.tokens[first].text.lower() if len(line.tokens) > first else ""
        if kind not in SHAPES:
            found = quoted(line.tokens[first].text) if len(line.tokens) > first else "nothing"
            self.error(line, f"collider: expected box, sphere, capsule or cylinder, found {found}", first)
            return
        args = line.tokens[first + 1 :]
        if len(args) != SHAPES[kind]:
            found = quoted(" ".join(t.text for t in args)) if args else "nothing"
            self.error(
                line,
                f"{kind}: expected {SHAPES[kind]} arguments ({kind} {FORMS[kind]}), found {len(args)}: {found}",
                first,
            )
            return
        count = 4 if kind == "sphere" else 6 if kind == "box" else 5
        names = ("centre x", "centre y", "centre z") + {
            "box": ("size x", "size y", "size z"),
            "sphere": ("radius",),
        }.get(kind, ("radius", "height"))
        values = self.numbers(line, first + 1, names[:count])
        if not values:
            return
        for i, v in enumerate(values[3:]):
            if v <= 0:
                self.error(
                    line,
                    f"{kind}: expected {names[3 + i]} > 0, found {quoted(args[3 + i].text)}",
                    first + 4 + i,
                    "bad-value",
                )
                return
        axis = "y" if not self.ours else "z"
        if kind in ("capsule", "cylinder"):
            axis = args[5].text.lower()
            if axis not in ("x", "y", "z"):
                self.error(line, f"{kind}: expected axis x, y or z, found {quoted(args[5].text)}", first + 6)
                return
        self.colliders.append((kind, values, axis))

    def kw_buoyancy(self, line: Line) -> None:
        if self.arity(line, (1,), "<volume in litres>"):
            values = self.numbers(line, 1, ("volume in litres",))
            if values:
                if values[0] < 0:
                    self.error(
                        line, f"buoyancy: expected a volume >= 0, found {quoted(line.args[0].text)}", 1, "bad-value"
                    )
                else:
                    self.fields["buoyancy"] = values[0]

    def kw_fixed(self, line: Line) -> None:
        if line.args:
            self.diagnostics.warning(
                self.at(line, 1),
                f"fixed takes no arguments, found {quoted(line.args[0].text)}; ignored",
                "ignored-argument",
            )
        self.fields["fixed"] = True

    def kw_color(self, line: Line) -> None:
        if not self.arity(line, (3,), "<r> <g> <b>"):
            return
        rgb = [integer(t.text) for t in line.args]
        for i, value in enumerate(rgb):
            if value is None or not 0 <= value <= 255:
                self.error(line, f"color: expected a whole number 0..255, found {quoted(line.args[i].text)}", 1 + i)
                return
        self.fields["color"] = tuple(rgb)

    def object_type(self) -> ObjectType:
        fields = dict(self.fields)
        if "name" not in fields:
            # EyeSim VR 2018 named objects after their file
            fields["name"] = Path(self.source).stem
        scale = 1.0 if self.ours else fields.get("scale", 1.0)
        fields["colliders"] = tuple(self._collider(kind, values, axis, scale) for kind, values, axis in self.colliders)
        if self.mass_centre is not None:
            fields["center_of_mass"] = self._point(self.mass_centre, scale)
        return ObjectType(source=self.source, **fields)

    def _point(self, values: list[float], scale: float) -> tuple[float, float, float]:
        x, y, z = values if self.ours else (_scaled(v, scale) for v in vr_to_robot(*values))
        return x, y, z

    def _collider(self, kind: str, values: list[float], axis: str, scale: float) -> Collider:
        centre = self._point(values[:3], scale)
        size = values[3:]
        if not self.ours:
            axis = VR_AXIS[axis]
            if kind == "box":
                size = [size[2], size[0], size[1]]
        return Collider(
            kind,
            tuple(v if self.ours else _scaled(v, scale) for v in size),
            centre,
            axis if kind in ("capsule", "cylinder") else "z",
        )


def _scaled(value: float, scale: float) -> float:
    """value * scale without floating-point noise (14200 * 0.025 is 355, not 355.00000000000006)."""
    return round(value * scale, 6) + 0.0


def write_esobj(obj: ObjectType) -> str:
    """ObjectType as .esObj text in our dialect: object frame, real size in mm."""
    f = format_number
    out = ["# EyeSim object definition (written by eyesim convert)", "dialect eyesim"]
    if obj.model is not None:
        out.append(f"obj {quote_token(obj.model)}")
    out += [f"name {quote_token(obj.name)}", f"scale {f(obj.scale)}"]
    mass = f"mass {f(obj.mass)}"
    if obj.center_of_mass is not None:
        mass += " " + " ".join(f(v) for v in obj.center_of_mass)
    out.append(mass)
    for c in obj.colliders:
        numbers = " ".join(f(v) for v in (*c.center, *c.size))
        axis = f" {c.axis}" if c.kind in ("capsule", "cylinder") else ""
        out.append(f"collider {c.kind} {numbers}{axis}")
    out.append("color " + " ".join(str(c) for c in obj.color))
    if obj.buoyancy:
        out.append(f"buoyancy {f(obj.buoyancy)}")
    if obj.fixed:
        out.append("fixed")
    return "\n".join(out) + "\n"

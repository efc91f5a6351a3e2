"""Collisions from MuJoCo's contacts: who touched whom (robots, objects, walls), how often and when.

A contact is an episode: two things start touching at a physics step and touch until they part
for longer than REJOIN (a robot grinding along a wall loses and regains contact every few
steps; that is one collision, not hundreds). Touching the floor and a robot's parts touching
each other are not contacts."""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

NOTHING = -1  # the floor, water and anything else that is not a robot, an object or a wall
REJOIN = 0.1  # s: touching again this soon after parting continues the same episode


@dataclass(frozen=True, order=True)
class Thing:
    """What took part in a contact: kind 'robot', 'object' or 'wall' and its 1-based number
    (robots and objects as the SIM functions number them, walls in the world file's order)."""

    kind: str
    id: int

    def __str__(self) -> str:
        return f"{self.kind} {self.id}"


@dataclass
class Contact:
    """One episode of two things touching: from `start` to `end` (s of simulation time; `end`
    is None while they still touch)."""

    first: Thing
    second: Thing
    start: float
    end: float | None = None

    def involves(self, thing: Thing) -> bool:
        return thing in (self.first, self.second)

    def other(self, thing: Thing) -> Thing:
        return self.second if self.first == thing else self.first

    def as_dict(self) -> dict:
        return {"first": str(self.first), "second": str(self.second), "start": self.start, "end": self.end}


class ContactTracker:
    """A step observer (engine `step_observers`): after every physics step, reads the contacts
    MuJoCo found and opens or closes episodes. Geoms are mapped to things once; a step looks
    each contact's two geoms up in a list: a step has a few contacts (mostly wheels on the
    floor), and a plain loop over them costs less than numpy's fixed cost per array operation."""

    def __init__(self, sim):
        model = sim.world.model
        self.things: list[Thing] = []
        codes = np.full(model.ngeom, NOTHING, dtype=np.int64)
        roots = model.body_rootid[model.geom_bodyid]
        for kind, entities in (("robot", sim.robots), ("object", sim.objects)):
            for entity in entities:
                codes[roots == entity.body] = len(self.things)
                self.things.append(Thing(kind, entity.id))
        for geom in range(model.ngeom):
            name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_GEOM, geom) or ""
            if name.startswith("wall") and name[4:].isdigit():
                codes[geom] = len(self.things)
                self.things.append(Thing("wall", int(name[4:]) + 1))
        self.codes = codes.tolist()
        self.touching: dict[tuple[int, int], Contact] = {}
        self.parted: dict[tuple[int, int], Contact] = {}  # the last episode of pairs not touching now
        self.contacts: list[Contact] = []

    def __call__(self, sim) -> None:
        data, codes = sim.world.data, self.codes
        pairs = set()
        if data.ncon:
            for first, second in data.contact.geom[: data.ncon].tolist():
                a, b = codes[first], codes[second]
                if a != NOTHING and b != NOTHING and a != b:
                    pairs.add((a, b) if a < b else (b, a))
        if not pairs and not self.touching:
            return
        for pair in self.touching.keys() - pairs:
            contact = self.touching.pop(pair)
            contact.end = sim.time
            self.parted[pair] = contact
        for pair in pairs - self.touching.keys():
            parted = self.parted.pop(pair, None)
            if parted is not None and sim.time - parted.end <= REJOIN + 1e-9:
                parted.end = None  # the same collision goes on
                self.touching[pair] = parted
            else:
                contact = Contact(self.things[pair[0]], self.things[pair[1]], sim.time)
                self.contacts.append(contact)
                self.touching[pair] = contact

    def of(self, thing: Thing, with_kind: str = "any") -> list[Contact]:
        """Episodes of `thing` touching something of a kind ('robot', 'object', 'wall' or 'any')."""
        return [
            c for c in self.contacts if c.involves(thing) and (with_kind == "any" or c.other(thing).kind == with_kind)
        ]

"""The scene browser's recent files, newest first, kept from one run to the next in a small JSON
file in the user's state folder (paths.state_dir()). A missing, unreadable or damaged file starts
an empty list (the last two with a warning); one that cannot be written leaves the list to this
run (warned once). The simulator never depends on it."""

from __future__ import annotations

import json
import logging
import os
from pathlib import Path

from eyesim.paths import state_dir

log = logging.getLogger("eyesim.web")
MAX_RECENT = 10
FILE_NAME = "recent-scenes.json"


class RecentFiles:
    def __init__(self, store: Path | None = None, limit: int = MAX_RECENT):
        self.store = store if store is not None else state_dir() / FILE_NAME
        self.limit = limit
        self.paths: list[str] = self._read()  # absolute paths, newest first
        self._write_failed = False

    def note(self, path: Path) -> None:
        """`path` was opened or saved: first in the list, and the list written back."""
        text = str(Path(path).resolve())
        self.paths = [text] + [p for p in self.paths if p != text][: self.limit - 1]
        self._write()

    def _read(self) -> list[str]:
        try:
            kept = json.loads(self.store.read_text(encoding="utf-8"))
        except FileNotFoundError:
            return []
        except (OSError, UnicodeDecodeError, ValueError) as error:
            log.warning("%s: cannot read the recent scenes (%s); starting a new list", self.store, error)
            return []
        if not isinstance(kept, list) or not all(isinstance(p, str) for p in kept):
            log.warning("%s: not a list of file names; starting a new list of recent scenes", self.store)
            return []
        return kept[: self.limit]

    def _write(self) -> None:
        partial = self.store.with_name(f"{self.store.name}.{os.getpid()}.tmp")
        try:
            self.store.parent.mkdir(parents=True, exist_ok=True)
            partial.write_text(json.dumps(self.paths, indent=1), encoding="utf-8")
            partial.replace(self.store)  # whole or not at all: another run may read it meanwhile
        except OSError as error:
            if not self._write_failed:
                log.warning("%s: cannot keep the recent scenes for the next run (%s)", self.store, error)
                self._write_failed = True
            try:
                partial.unlink(missing_ok=True)
            except OSError:
                pass  # its folder is not there either

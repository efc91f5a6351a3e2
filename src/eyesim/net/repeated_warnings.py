"""Warnings about program connections that a client can cause by the thousand (attackers, a broken
program reconnecting in a loop): the first of each reason is logged in full, with its peer; the
rest within the period are only counted, and one line a period says how many there were. A soak's
KEYWait flooder once wrote 93,579 identical lines in 10 minutes."""

from __future__ import annotations

import logging
import time

PERIOD = 1.0  # s between summaries of one reason


class RepeatedWarnings:
    """Used on the simulation thread only. `summarize(now)` is called about once a second."""

    def __init__(self, log: logging.Logger, period: float = PERIOD):
        self.log = log
        self.period = period
        self._counts: dict[str, int] = {}  # reason -> warnings not logged since its last full line
        self._since: dict[str, float] = {}  # reason -> when its last full line was logged

    def warn(self, reason: str, message: str, *args) -> None:
        """Log `message % args` unless a warning of the same `reason` was logged in full within the
        period: then only count it. `reason` is what the summary says ("closed: ...")."""
        if reason in self._since:
            self._counts[reason] += 1
            return
        self._since[reason] = time.monotonic()
        self._counts[reason] = 0
        self.log.warning(message, *args)

    def summarize(self, now: float) -> None:
        """Say how many warnings of each reason were only counted, once its period is over; the
        next of that reason is logged in full again."""
        for reason, since in list(self._since.items()):
            if now - since < self.period:
                continue
            count = self._counts.pop(reason)
            del self._since[reason]
            if count:
                self.log.warning("%s: %d more program connection(s) in the last %.0f s", reason, count, now - since)

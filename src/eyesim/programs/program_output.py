"""A launched program's stdout and stderr, read on the simulation thread.

The pipes are non-blocking and watched by the simulation thread's selector, so output shows as
soon as it is written, with no reader threads (but on Windows, whose selector takes only sockets:
a thread copies each pipe into a socket, platform.readable), and is stamped with the simulation
time at which it is read. On POSIX that time repeats exactly in deterministic runs: what a program writes before a call
is in the pipe before the call's request is on its socket, so the selector reports both in the
same wait, before the call is taken; and simulation time cannot move while the program computes
between two calls. Text is passed on a whole line at a time; a line still unfinished when the
program makes a call is passed on then (`flush`), so that where lines break does not depend on
when the pipe was read."""

from __future__ import annotations

from typing import Callable

from eyesim import platform

STREAMS = ("stdout", "stderr")
READ_SIZE = 64 * 1024


class ProgramOutput:
    def __init__(self, pipes: dict, show: Callable[[str, str], None]):
        """`pipes`: stream name -> the process's pipe; `show(stream, text)`: called with each line."""
        self.pipes = {stream: platform.readable(pipe) for stream, pipe in pipes.items() if pipe is not None}
        self.show = show
        self.partial = {stream: b"" for stream in self.pipes}
        self.network = None  # the selector that watches the pipes, once watched

    def watch(self, network) -> None:
        """Have the simulation thread's selector read the pipes as output arrives."""
        self.network = network
        for stream, pipe in self.pipes.items():
            network.watch(pipe, lambda stream=stream: self.read(stream))

    def read(self, stream: str, whole: bool = False) -> None:
        """Take in what the pipe holds now and pass on complete lines (with `whole`, an unfinished
        one too). At the end of the stream the pipe is closed."""
        pipe = self.pipes.get(stream)
        if pipe is None:
            return
        data = self.partial[stream]
        ended = False
        while True:
            chunk = platform.read_available(pipe, READ_SIZE)
            if chunk is None:
                break
            if not chunk:
                ended = True
                break
            data += chunk
        cut = len(data) if whole or ended else data.rfind(b"\n") + 1
        self.partial[stream] = data[cut:]
        self._show(stream, data[:cut])
        if ended:
            self._close(stream)

    def flush(self) -> None:
        """Pass on unfinished lines (the program makes a call: what it wrote before is complete)."""
        for stream, data in self.partial.items():
            if data:
                self.partial[stream] = b""
                self._show(stream, data)

    def finish(self) -> None:
        """The program has exited: take in the rest and stop watching (a process it started may
        still hold the pipe open; what that writes later is not shown)."""
        for stream in list(self.pipes):
            platform.drain(self.pipes[stream])  # Windows: its last words may still be on their way
            self.read(stream, whole=True)
            if stream in self.pipes:  # not at its end: a process it started still holds it
                self._close(stream)

    def _show(self, stream: str, data: bytes) -> None:
        data = data.replace(b"\r\n", b"\n")  # Windows programs end lines with \r\n; a lone \r stays
        start = 0
        while start < len(data):  # lines end at \n only, as a program's own line buffering does
            end = data.find(b"\n", start) + 1 or len(data)
            self.show(stream, data[start:end].decode("utf-8", errors="replace"))
            start = end

    def _close(self, stream: str) -> None:
        pipe = self.pipes.pop(stream)
        if self.network is not None:
            self.network.unwatch(pipe)
        pipe.close()

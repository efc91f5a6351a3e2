"""A 5-megapixel camera frame (15 MB) leaves the simulation thread in pieces of at most SEND_PIECE
bytes, with other programs served between them: handing the kernel the whole frame in one send()
made the simulation thread copy megabytes while every other program waited. No timing is
asserted: the camera's program reads nothing until the other program has been answered while
part of the frame is still unsent."""

import socket
import threading

from support.client import ProgramClient
from support.scenes import arena
from support.simulator import running_simulation

from eyesim.net.program_server import SEND_PIECE

CAM5MP = 5
FRAME_BYTES = 2592 * 1944 * 3


class SendLog:
    """Every send() of the simulator's program sockets: (the peer's port, bytes handed over, bytes taken)."""

    def __init__(self, monkeypatch):
        self.sends: list[tuple[int, int, int]] = []
        self.changed = threading.Condition()
        real_send = socket.socket.send

        def send(sock, data, *flags):
            peer = sock.getpeername()[1] if sock.family in (socket.AF_INET, socket.AF_INET6) else None
            taken = 0
            try:
                taken = real_send(sock, data, *flags)
                return taken
            finally:
                with self.changed:
                    self.sends.append((peer, len(data), taken))
                    self.changed.notify_all()

        monkeypatch.setattr(socket.socket, "send", send)

    def taken_by(self, port: int) -> int:
        with self.changed:
            return sum(taken for peer, _, taken in self.sends if peer == port)

    def wait_for(self, condition) -> None:
        with self.changed:
            assert self.changed.wait_for(condition, timeout=120), self.sends[-5:]


def test_a_5_megapixel_frame_leaves_in_pieces_with_another_program_served_between(monkeypatch):
    log = SendLog(monkeypatch)
    with running_simulation(arena(robots=((500, 500, 0), (1500, 500, 180))), "realtime") as (sim, port):
        camera = ProgramClient(port, timeout=120)
        camera.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 1 << 18)  # far less than a frame, unread for now
        other = ProgramClient(port)
        camera.hello("1")
        other.hello("2")
        camera.call("CAM_INIT", CAM5MP)
        camera_port = camera.sock.getsockname()[1]
        before = log.taken_by(camera_port)
        frame = camera.send("CAM_GET")
        log.wait_for(lambda: sum(taken for peer, _, taken in log.sends if peer == camera_port) > before)
        # Part of the frame is with the kernel, the rest waits in the simulator: the other program is served.
        distances = [other.call("PSD_GET", 1)[0] for _ in range(20)]
        assert all(distance > 0 for distance in distances)
        assert log.taken_by(camera_port) - before < FRAME_BYTES
        result, width, height, pixels = camera.reply("CAM_GET", frame)
        assert (result, width, height, len(pixels)) == (0, 2592, 1944, FRAME_BYTES)
        assert len(set(pixels[::9973])) > 1  # a picture, not a blank buffer
        camera_sends = [handed for peer, handed, _ in log.sends if peer == camera_port]
        assert max(camera_sends) <= SEND_PIECE
        assert sum(taken for peer, _, taken in log.sends if peer == camera_port) - before >= FRAME_BYTES
        for client in (camera, other):
            client.close()

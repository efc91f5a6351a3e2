"""The program server: handshake, routing, and bad input that harms nobody else."""

import socket
import time

import pytest
from support.client import ProgramClient, RemoteError
from support.scenes import arena
from support.simulator import running_simulation, token_for

from eyesim.protocol import encode_frame, encode_message, generated as g


@pytest.fixture
def simulation():
    with running_simulation(arena(robots=((500, 500, 0), (1500, 500, 180)))) as (sim, port):
        yield sim, port


def test_handshake_binds_the_first_free_robot_then_the_next(simulation):
    _, port = simulation
    first, second, third = ProgramClient(port), ProgramClient(port), ProgramClient(port)
    assert first.hello() == (g.VERSION, 1, "S4")
    assert second.hello() == (g.VERSION, 2, "S4")
    with pytest.raises(RemoteError) as error:
        third.hello()
    assert error.value.code == g.ERR_NO_ROBOT and "every robot" in error.value.message


def test_handshake_by_id_and_by_name(simulation):
    _, port = simulation
    assert ProgramClient(port).hello("2")[1] == 2
    assert ProgramClient(port).hello("s4")[1] == 1  # names match case-insensitively
    with pytest.raises(RemoteError, match="no robot 'Rover'"):
        ProgramClient(port).hello("Rover")


def test_a_freed_robot_can_be_taken_again(simulation):
    _, port = simulation
    client = ProgramClient(port)
    client.hello("1")
    client.close()
    deadline = time.time() + 5
    while True:
        try:
            assert ProgramClient(port).hello("1")[1] == 1
            break
        except RemoteError:
            assert time.time() < deadline
            time.sleep(0.05)


def test_wrong_protocol_version_is_refused_with_a_reason(simulation):
    _, port = simulation
    with pytest.raises(RemoteError) as error:
        ProgramClient(port).call("HELLO", g.VERSION + 1, "", "old", 0, "")
    assert error.value.code == g.ERR_VERSION and "eyesim cc" in error.value.message


def test_requests_before_the_handshake_are_refused(simulation):
    _, port = simulation
    client = ProgramClient(port)
    with pytest.raises(RemoteError) as error:
        client.call("PSD_GET", 1)
    assert error.value.code == g.ERR_NO_HANDSHAKE
    assert client.hello()[1] == 1  # the connection still works


def test_unknown_operation_and_bad_payload_get_error_replies_and_the_connection_lives(simulation):
    _, port = simulation
    client = ProgramClient(port)
    client.hello()
    client.sock.sendall(encode_frame(999, g.KIND_REQUEST, 77, b""))
    message = client.receive()
    assert (message.kind, message.request_id) == (g.KIND_ERROR, 77)
    client.sock.sendall(encode_frame(g.OP_PSD_GET, g.KIND_REQUEST, 78, b"\x01"))
    message = client.receive()
    assert (message.kind, message.request_id) == (g.KIND_ERROR, 78)
    client.sock.sendall(encode_frame(g.OP_PSD_GET, g.KIND_REPLY, 79, b"\x01\x00\x00\x00"))
    assert client.receive().kind == g.KIND_ERROR
    assert client.call("PSD_GET", 1)[0] > 0


def test_an_oversized_frame_closes_only_that_connection(simulation):
    _, port = simulation
    bad, good = ProgramClient(port), ProgramClient(port)
    bad.hello()
    good.hello()
    bad.sock.sendall((g.MAX_FRAME + 1).to_bytes(4, "little") + b"\0" * 16)
    message = bad.receive()
    assert message.kind == g.KIND_ERROR
    with pytest.raises((ConnectionError, OSError)):
        bad.receive()
    assert good.call("PSD_GET", 1)[0] > 0


def test_a_stalled_half_frame_delays_no_other_client(simulation):
    _, port = simulation
    staller = socket.create_connection(("127.0.0.1", port))
    frame = encode_message(g.OP_HELLO, g.KIND_REQUEST, 1, (g.VERSION, "", "staller", 0, token_for(port)))
    staller.sendall(frame[:6])  # the length and half the header, then nothing
    other = ProgramClient(port)
    start = time.perf_counter()
    other.hello()
    for _ in range(20):
        other.call("PSD_GET", 1)
    assert time.perf_counter() - start < 2.0  # generous: a blocked server would hang for good
    staller.sendall(frame[6:])  # completing the frame later still works
    staller.close()


def test_garbage_bytes_never_crash_the_server(simulation):
    sim, port = simulation
    for garbage in (b"\xff" * 64, b"GET / HTTP/1.1\r\n\r\n", b"\x08\x00\x00\x00" + b"\x01" * 8):
        sock = socket.create_connection(("127.0.0.1", port))
        sock.sendall(garbage)
        sock.close()
    client = ProgramClient(port)
    assert client.hello()[1] == 1
    assert client.call("OS_GET_COUNT")[0] >= 0


def test_handler_errors_are_error_replies(simulation):
    _, port = simulation
    client = ProgramClient(port)
    client.hello()
    with pytest.raises(RemoteError, match="no PSD 9"):
        client.call("PSD_GET", 9)
    with pytest.raises(RemoteError, match="negative"):
        client.call("OS_WAIT", -5)


def test_a_huge_program_name_is_shortened_in_the_log(simulation, caplog):
    _, port = simulation
    client = ProgramClient(port)
    with caplog.at_level("INFO", logger="eyesim"):
        assert client.call("HELLO", g.VERSION, "", "p" * (1 << 20), 0, client.token)[1] == 1
        assert client.call("OS_GET_COUNT")[0] >= 0
    (line,) = [r.getMessage() for r in caplog.records if r.getMessage().endswith("connected")]
    assert line.startswith("p" * 97 + "... (robot 1, 127.0.0.1:") and len(line) < 200

"""The program token: a HELLO without the run's token is refused with a reason, logged, and its
connection closed; nobody else is affected; --no-token lets anyone in, on loopback only."""

import os
import stat

import pytest
from support.client import ProgramClient, RemoteError
from support.scenes import arena
from support.simulator import running_simulation

from eyesim.core.clock import Clock
from eyesim.core.engine import Simulation
from eyesim.net.program_server import ProgramServer
from eyesim.net.program_token import NoTokenRefused, TokenFile, token_file_path
from eyesim.protocol import generated as g


@pytest.fixture
def simulation():
    with running_simulation(arena(robots=((500, 500, 0), (1500, 500, 180)))) as (sim, port):
        yield sim, port


def test_a_program_with_the_runs_token_connects(simulation):
    sim, port = simulation
    client = ProgramClient(port, token=sim.program_token)
    assert client.hello("1") == (g.VERSION, 1, "S4")
    assert client.call("PSD_GET", 1)[0] > 0


@pytest.mark.parametrize("token, problem", [("", "sent none"), ("not-this-runs-token", "wrong program token")])
def test_a_missing_or_wrong_token_is_refused_logged_and_the_connection_closed(simulation, caplog, token, problem):
    sim, port = simulation
    good = ProgramClient(port)
    good.hello("1")
    intruder = ProgramClient(port, token=token)
    with caplog.at_level("WARNING", logger="eyesim"), pytest.raises(RemoteError) as refused:
        intruder.hello("2", program="teleporter")
    assert refused.value.code == g.ERR_BAD_TOKEN
    assert problem in refused.value.message
    assert "EYESIM_TOKEN" in refused.value.message and "--no-token" in refused.value.message
    assert sim.program_token not in refused.value.message
    with pytest.raises((ConnectionError, OSError)):
        intruder.call("SIM_SET_ROBOT", 2, 0, 0, 0, 0)  # no second guess on that connection
    (line,) = [r.getMessage() for r in caplog.records if "refused a program" in r.getMessage()]
    assert "'teleporter'" in line and ("wrong" if token else "no") + " program token" in line
    assert good.call("PSD_GET", 1)[0] > 0  # the program already connected goes on
    assert ProgramClient(port).hello("2")[1] == 2  # and robot 2 is still free for its own program


def test_the_refusal_names_the_token_file_of_the_run(simulation, tmp_path):
    sim, port = simulation
    sim.program_token_file = tmp_path / "program-token-1234"  # as eyesim run sets it
    with pytest.raises(RemoteError) as refused:
        ProgramClient(port, token="").hello()
    assert str(tmp_path / "program-token-1234") in refused.value.message


def test_no_token_lets_a_tokenless_program_in_on_loopback():
    with running_simulation(arena(robots=((500, 500, 0), (1500, 500, 180))), require_token=False) as (sim, port):
        assert sim.program_token is None
        first, second = ProgramClient(port, token=""), ProgramClient(port, token="whatever")
        assert first.hello()[1] == 1
        assert second.hello()[1] == 2  # a token is not looked at


def test_no_token_is_refused_on_an_address_other_machines_reach():
    sim = Simulation(arena(), Clock())
    try:
        with pytest.raises(NoTokenRefused, match="other machines"):
            ProgramServer(sim, "0.0.0.0", 0, require_token=False)
        ProgramServer(sim, "::1", 0, require_token=False)  # loopback, IPv6 too
    finally:
        sim.close()


def test_a_new_token_every_run():
    tokens = set()
    for _ in range(3):
        with running_simulation(arena()) as (sim, _port):
            tokens.add(sim.program_token)
    assert len(tokens) == 3 and all(len(token) >= 32 for token in tokens)


def test_the_token_file_is_the_users_own_and_goes_with_the_run(tmp_path, monkeypatch):
    monkeypatch.setenv("EYESIM_STATE_DIR", str(tmp_path / "state"))
    token_file = TokenFile("secret-1", 4321)
    token_file.write()
    assert token_file.path == token_file_path(4321) == tmp_path / "state" / "program-token-4321"
    assert token_file.path.read_text() == "secret-1\n"
    if os.name != "nt":
        assert stat.S_IMODE(token_file.path.stat().st_mode) == 0o600
        assert stat.S_IMODE(token_file.path.parent.stat().st_mode) == 0o700
    assert [p.name for p in token_file.path.parent.iterdir()] == ["program-token-4321"]  # no temporary left
    later = TokenFile("secret-2", 4321)  # a later run on the port (this one crashed)
    later.write()
    token_file.remove()  # not the later run's file
    assert later.path.read_text() == "secret-2\n"
    later.remove()
    assert not later.path.exists()

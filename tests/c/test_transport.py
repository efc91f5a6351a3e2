"""libeyesim's connection (transport.c) against a fake simulator: handshake, failures, threads."""

from __future__ import annotations

import random
import subprocess
import sys
import threading
import time

import pytest

from eyesim.protocol import generated as g

EXIT_NO_SIMULATOR, EXIT_REFUSED, EXIT_CONNECTION_LOST, EXIT_PROTOCOL = 3, 4, 5, 6

ONE_CALL = r"""
#include "eyebot.h"
#include <stdio.h>
int main(void)
{
    printf("before\n"); /* still printed when the library ends the program */
    printf("psd %d\n", PSDGet(PSD_FRONT));
    return 0;
}
"""


def run(exe, env, timeout=30):
    return subprocess.run([str(exe)], capture_output=True, text=True, timeout=timeout, env=env)


def eyesim_lines(stderr: str) -> list[str]:
    return [line for line in stderr.splitlines() if line.startswith("eyesim:")]


# ---- Handshake ---------------------------------------------------------------------------------


@pytest.mark.parametrize("robot", [None, "S4", "2"])
def test_handshake_sends_version_robot_program_and_pid(compiler, fake_sim, robot):
    exe = compiler.build(ONE_CALL, name="hello_prog")
    env = fake_sim.env() if robot is None else fake_sim.env(EYESIM_ROBOT=robot)
    proc = subprocess.Popen([str(exe)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    out, err = proc.communicate(timeout=30)
    assert (proc.returncode, out, err) == (0, "before\npsd 0\n", "")
    assert fake_sim.hellos == [(g.VERSION, robot or "", "hello_prog", proc.pid, "")]  # no token to be had
    assert fake_sim.ops() == ["PSD_GET"]


def test_handshake_sends_eyesim_token_before_the_token_file(compiler, fake_sim, tmp_path):
    exe = compiler.build(ONE_CALL, name="hello_prog")
    (tmp_path / f"program-token-{fake_sim.port}").write_text("from-the-file\n")
    ran = run(exe, fake_sim.env(EYESIM_STATE_DIR=str(tmp_path)))  # started by hand: the run's file
    assert ran.returncode == 0, ran.stderr
    ran = run(exe, fake_sim.env(EYESIM_STATE_DIR=str(tmp_path), EYESIM_TOKEN="from-the-environment"))
    assert ran.returncode == 0, ran.stderr
    (tmp_path / f"program-token-{fake_sim.port}").unlink()
    ran = run(exe, fake_sim.env(EYESIM_STATE_DIR="", XDG_STATE_HOME=str(tmp_path / "xdg")))  # the platform's folder
    assert ran.returncode == 0, ran.stderr
    (tmp_path / "xdg" / "eyesim").mkdir(parents=True)
    (tmp_path / "xdg" / "eyesim" / f"program-token-{fake_sim.port}").write_text("from-xdg")
    ran = run(exe, fake_sim.env(EYESIM_STATE_DIR="", XDG_STATE_HOME=str(tmp_path / "xdg")))
    assert ran.returncode == 0, ran.stderr
    tokens = [hello[4] for hello in fake_sim.hellos]
    expected_platform = "from-xdg" if sys.platform.startswith("linux") else ""
    assert tokens == ["from-the-file", "from-the-environment", "", expected_platform]


def test_a_refused_token_says_where_it_came_from(compiler, make_fake_sim, tmp_path):
    sim = make_fake_sim()
    sim.hello_answer = sim.Error(g.ERR_BAD_TOKEN, "this program sent a wrong program token")
    ran = run(compiler.build(ONE_CALL, name="one_call"), sim.env(EYESIM_TOKEN="stale"))
    assert ran.returncode == EXIT_REFUSED
    assert eyesim_lines(ran.stderr) == [
        f"eyesim: the simulator at 127.0.0.1:{sim.port} refused this program: this program sent a wrong program "
        f"token [it sent EYESIM_TOKEN]"
    ]
    ran = run(compiler.build(ONE_CALL, name="one_call"), sim.env(EYESIM_STATE_DIR=str(tmp_path)))
    assert eyesim_lines(ran.stderr)[0].endswith(
        f"[EYESIM_TOKEN is not set and {tmp_path / f'program-token-{sim.port}'} cannot be read]"
    )


def test_refused_handshake_prints_the_reason_and_exits(compiler, make_fake_sim):
    sim = make_fake_sim()
    sim.hello_answer = sim.Error(g.ERR_NO_ROBOT, "no robot named 'R9' in this scene")
    ran = run(compiler.build(ONE_CALL, name="one_call"), sim.env(EYESIM_ROBOT="R9"))
    assert ran.returncode == EXIT_REFUSED
    assert eyesim_lines(ran.stderr) == [
        f"eyesim: the simulator at 127.0.0.1:{sim.port} refused this program: no robot named 'R9' in this scene"
    ]
    assert ran.stdout == "before\n"


def test_simulator_hanging_up_during_the_handshake(compiler, make_fake_sim):
    sim = make_fake_sim(hello="close")
    ran = run(compiler.build(ONE_CALL, name="one_call"), sim.env())
    assert ran.returncode == EXIT_CONNECTION_LOST
    assert len(eyesim_lines(ran.stderr)) == 1
    assert "closed the connection during the handshake" in ran.stderr


# ---- No simulator ------------------------------------------------------------------------------


def test_no_simulator_waits_with_one_message_then_exits(compiler, free_port_env):
    port = free_port_env["EYESIM_PORT"]
    start = time.monotonic()
    ran = run(compiler.build(ONE_CALL, name="one_call"), free_port_env)
    elapsed = time.monotonic() - start
    assert ran.returncode == EXIT_NO_SIMULATOR
    assert 0.4 < elapsed < 5
    assert eyesim_lines(ran.stderr) == [
        f"eyesim: waiting for the simulator at 127.0.0.1:{port} (set EYESIM_HOST/EYESIM_PORT) ...",
        f"eyesim: no simulator answered at 127.0.0.1:{port} within 0.5 s (Connection refused); "
        "start the simulator first, or set EYESIM_HOST/EYESIM_PORT",
    ]
    assert ran.stdout == "before\n"


def test_a_simulator_starting_late_is_still_found(compiler, make_fake_sim, unused_port, env_for):
    exe = compiler.build(ONE_CALL, name="one_call")
    env = env_for(EYESIM_HOST="127.0.0.1", EYESIM_PORT=str(unused_port))
    proc = subprocess.Popen([str(exe)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    time.sleep(0.6)
    make_fake_sim(port=unused_port)
    out, err = proc.communicate(timeout=30)
    assert proc.returncode == 0, err
    assert out == "before\npsd 0\n"
    assert eyesim_lines(err) == [
        f"eyesim: waiting for the simulator at 127.0.0.1:{unused_port} (set EYESIM_HOST/EYESIM_PORT) ..."
    ]


def test_bad_port_setting_is_reported(compiler, free_port_env):
    ran = run(compiler.build(ONE_CALL, name="one_call"), {**free_port_env, "EYESIM_PORT": "97x"})
    assert ran.returncode == EXIT_NO_SIMULATOR
    assert eyesim_lines(ran.stderr) == ["eyesim: EYESIM_PORT=97x is not a port number (1-65535)"]


# ---- The simulator going away ------------------------------------------------------------------

POLL_FOREVER = r"""
#include "eyebot.h"
int main(void)
{
    for (;;)
        KEYRead();
}
"""

BLOCKED_THREADS = r"""
#include "eyebot.h"
#include <pthread.h>
#include <stdio.h>

static void *wait_for_key(void *unused)
{
    (void)unused;
    printf("key %d\n", KEYGet());
    return NULL;
}

int main(void)
{
    pthread_t thread;
    pthread_create(&thread, NULL, wait_for_key, NULL);
    printf("vw %d\n", VWWait());
    pthread_join(thread, NULL);
    return 0;
}
"""


def test_simulator_closing_mid_run_ends_the_program(compiler, fake_sim):
    proc = subprocess.Popen(
        [str(compiler.build(POLL_FOREVER, name="poll_forever"))],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=fake_sim.env(),
    )
    try:
        assert fake_sim.wait_for(lambda: sum(r.op == "KEY_READ" for r in fake_sim.requests) >= 20)
        fake_sim.close_clients()
        _, err = proc.communicate(timeout=10)
    finally:
        proc.kill()
    assert proc.returncode == EXIT_CONNECTION_LOST
    assert len(eyesim_lines(err)) == 1
    assert f"eyesim: lost the connection to the simulator at 127.0.0.1:{fake_sim.port}" in err


COMPUTE_FOREVER = r"""
#include "eyebot.h"
int main(void)
{
    volatile unsigned long n = 0;
    PSDGet(PSD_FRONT);
    for (;;) /* computes, never calls again */
        n++;
}
"""


def test_simulator_closing_ends_a_program_that_makes_no_call(compiler, fake_sim):
    """No thread of the library reads replies; the library's watcher notices the hang-up instead."""
    proc = subprocess.Popen(
        [str(compiler.build(COMPUTE_FOREVER, name="compute_forever"))],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=fake_sim.env(),
    )
    try:
        assert fake_sim.wait_for(lambda: fake_sim.count("PSD_GET") == 1)
        fake_sim.close_clients()
        _, err = proc.communicate(timeout=10)
    finally:
        proc.kill()
    assert proc.returncode == EXIT_CONNECTION_LOST
    assert len(eyesim_lines(err)) == 1 and "lost the connection" in err


def test_simulator_closing_ends_the_program_while_threads_are_blocked(compiler, fake_sim):
    fake_sim.script.update(KEY_GET=fake_sim.HOLD, VW_WAIT=fake_sim.HOLD)
    proc = subprocess.Popen(
        [str(compiler.build(BLOCKED_THREADS, name="blocked_threads"))],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=fake_sim.env(),
    )
    try:
        assert fake_sim.wait_for(lambda: len(fake_sim.held) == 2)
        time.sleep(0.1)
        assert proc.poll() is None
        fake_sim.close_clients()
        out, err = proc.communicate(timeout=10)
    finally:
        proc.kill()
    assert proc.returncode == EXIT_CONNECTION_LOST
    assert out == ""  # neither blocked call returned a made-up value
    assert len(eyesim_lines(err)) == 1 and "lost the connection" in err


def test_shutdown_error_ends_the_program(compiler, fake_sim):
    fake_sim.script["PSD_GET"] = fake_sim.Error(g.ERR_SHUTDOWN, "the simulator is closing")
    ran = run(compiler.build(ONE_CALL, name="one_call"), fake_sim.env())
    assert ran.returncode == EXIT_CONNECTION_LOST
    assert eyesim_lines(ran.stderr) == [
        f"eyesim: the simulator at 127.0.0.1:{fake_sim.port} is shutting down (the simulator is closing); "
        "the program ends"
    ]


STOP_AT_EXIT = r"""
#include "eyebot.h"
#include <stdio.h>
#include <stdlib.h>

static void stop(void)
{
    fprintf(stderr, "stop %d\n", VWSetSpeed(0, 0)); /* a common habit: stop the robot on exit */
}

int main(int argc, char **argv)
{
    (void)argv;
    atexit(stop);
    if (argc > 1)
        for (;;)
            KEYRead();
    return VWSetSpeed(100, 0);
}
"""


def test_atexit_handlers_may_call_the_api(compiler, fake_sim):
    ran = run(compiler.build(STOP_AT_EXIT, name="stop_at_exit"), fake_sim.env())
    assert (ran.returncode, ran.stderr) == (0, "stop 0\n")
    assert [(r.op, r.values) for r in fake_sim.requests] == [("VW_SET_SPEED", (100, 0)), ("VW_SET_SPEED", (0, 0))]


def test_atexit_handlers_calling_the_api_do_not_hang_when_the_simulator_is_gone(compiler, fake_sim, free_port_env):
    exe = compiler.build(STOP_AT_EXIT, name="stop_at_exit")
    ran = run(exe, free_port_env)
    assert ran.returncode == EXIT_NO_SIMULATOR
    assert ran.stderr.endswith("stop 1\n")

    proc = subprocess.Popen(
        [str(exe), "poll"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=fake_sim.env()
    )
    try:
        assert fake_sim.wait_for(lambda: fake_sim.count("KEY_READ") >= 5)
        fake_sim.close_clients()
        _, err = proc.communicate(timeout=10)
    finally:
        proc.kill()
    assert proc.returncode == EXIT_CONNECTION_LOST
    assert "lost the connection" in err and err.endswith("stop 1\n")


def test_a_malformed_frame_ends_the_program(compiler, fake_sim):
    fake_sim.script["PSD_GET"] = fake_sim.Garbage(b"\x02\x00\x00\x00xx")  # shorter than a header
    ran = run(compiler.build(ONE_CALL, name="one_call"), fake_sim.env())
    assert ran.returncode == EXIT_PROTOCOL
    assert eyesim_lines(ran.stderr) == [
        f"eyesim: the simulator at 127.0.0.1:{fake_sim.port} sent a malformed frame; the program ends"
    ]


# ---- Error replies -----------------------------------------------------------------------------

ERRORS = r"""
#include "eyebot.h"
#include <stdio.h>
int main(void)
{
    int x = 5, y = 5, phi = 5;
    for (int k = 0; k < 3; k++)
        printf("psd7 %d\n", PSDGet(7));
    printf("psd8 %d\n", PSDGet(8));
    printf("psd1 %d\n", PSDGet(1));
    int r = VWGetPosition(&x, &y, &phi);
    printf("vw %d %d %d %d\n", r, x, y, phi);
    printf("malformed %d\n", OSGetCount());
    printf("key %d\n", KEYGet());
    return 0;
}
"""


def test_error_replies_are_reported_once_and_give_the_error_value(compiler, fake_sim):
    fake_sim.script.update(
        PSD_GET=lambda v: fake_sim.Error(g.ERR_BAD_ARGUMENT, f"robot S4 has no PSD {v[0]}") if v[0] > 4 else (250,),
        VW_GET_POSITION=fake_sim.Error(g.ERR_NOT_SUPPORTED, "this robot has no VW drive"),
        OS_GET_COUNT=fake_sim.Raw(b"\x01\x00\x00\x00\xff"),  # one byte too many
        KEY_GET=(4,),
    )
    ran = run(compiler.build(ERRORS, name="errors"), fake_sim.env())
    assert ran.returncode == 0
    assert ran.stdout == ("psd7 -1\npsd7 -1\npsd7 -1\npsd8 -1\npsd1 250\nvw 1 0 0 0\nmalformed -1\nkey 4\n")
    assert eyesim_lines(ran.stderr) == [
        "eyesim: PSDGet: robot S4 has no PSD 7",
        "eyesim: PSDGet: robot S4 has no PSD 8",
        "eyesim: VWGetPosition: this robot has no VW drive",
        "eyesim: OSGetCount: malformed reply from the simulator (unexpected bytes after the last field)",
    ]


# ---- Threads -----------------------------------------------------------------------------------

BLOCKED_KEY_AND_BUSY_MAIN = r"""
#include "eyebot.h"
#include <pthread.h>
#include <stdio.h>

static void *wait_for_key(void *unused)
{
    (void)unused;
    int key = KEYGet();
    printf("key %d\n", key);
    return NULL;
}

int main(void)
{
    pthread_t thread;
    pthread_create(&thread, NULL, wait_for_key, NULL);
    int wrong = 0;
    for (int k = 1; k <= 50; k++)
        wrong += PSDGet(k) != 10 * k;
    printf("psd done, %d wrong\n", wrong);
    fflush(stdout);
    pthread_join(thread, NULL);
    return 0;
}
"""


def test_a_blocked_call_does_not_hold_up_other_threads(compiler, fake_sim):
    fake_sim.script.update(KEY_GET=fake_sim.HOLD, PSD_GET=lambda v: (10 * v[0],))
    proc = subprocess.Popen(
        [str(compiler.build(BLOCKED_KEY_AND_BUSY_MAIN, name="blocked_key"))],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=fake_sim.env(),
    )
    try:
        # Each PSDGet waits for its reply before the next, so 50 requests = 49 replies received while
        # KEYGet is still unanswered; then the main thread says it is done.
        assert fake_sim.wait_for(lambda: fake_sim.count("PSD_GET") == 50 and fake_sim.held_ops() == ["KEY_GET"])
        assert proc.stdout.readline() == "psd done, 0 wrong\n"
        assert fake_sim.held_ops() == ["KEY_GET"]
        fake_sim.release("KEY_GET", (4,))
        out, err = proc.communicate(timeout=10)
    finally:
        proc.kill()
    assert (proc.returncode, out, err) == (0, "key 4\n", "")


HAMMER = r"""
#include "eyebot.h"
#include <pthread.h>
#include <stdio.h>

#define THREADS 8
#define CALLS 300

static int wrong[THREADS];

static void *hammer(void *arg)
{
    int t = (int)(long)arg;
    for (int k = 0; k < CALLS; k++) {
        int id = t * 100000 + k;
        if (k % 2) {
            if (PSDGet(id) != 3 * id + 1)
                wrong[t]++;
        } else {
            int x, y, z, phi;
            if (SIMGetRobot(id, &x, &y, &z, &phi) != 0 || x != id || y != -id || z != t || phi != k)
                wrong[t]++;
        }
    }
    return NULL;
}

int main(void)
{
    pthread_t threads[THREADS];
    for (long t = 0; t < THREADS; t++)
        pthread_create(&threads[t], NULL, hammer, (void *)t);
    int total = 0;
    for (int t = 0; t < THREADS; t++) {
        pthread_join(threads[t], NULL);
        total += wrong[t];
    }
    printf("wrong %d\n", total);
    return 0;
}
"""


def test_many_threads_get_their_own_replies(compiler, fake_sim):
    rng = random.Random(7)
    lock = threading.Lock()

    def delay() -> float:
        with lock:  # random delays so that replies overtake each other
            return rng.uniform(0, 0.003)

    fake_sim.script.update(
        PSD_GET=lambda v: fake_sim.Delay(delay(), (3 * v[0] + 1,)),
        SIM_GET_ROBOT=lambda v: fake_sim.Delay(delay(), (0, v[0], -v[0], v[0] // 100000, v[0] % 100000)),
    )
    ran = run(compiler.build(HAMMER, name="hammer"), fake_sim.env(), timeout=60)
    assert (ran.returncode, ran.stdout, ran.stderr) == (0, "wrong 0\n", "")
    ids = [r.request_id for r in fake_sim.requests if r.op != "THREADS"]
    assert len(ids) == 8 * 300 and len(set(ids)) == len(ids)
    assert fake_sim.count("THREADS") == 1  # the library said once that several threads call


TOO_LONG = r"""
#include "eyebot.h"
#include <stdio.h>
#include <string.h>
static char text[65538];
int main(void)
{
    memset(text, 'x', 65537);
    printf("long %d\n", LCDPrintf("%s", text));
    text[65536] = 0;
    printf("longest %d\n", LCDPrintf("%s", text));
    return 0;
}
"""


def test_a_field_longer_than_the_simulator_takes_is_refused_before_sending(compiler, fake_sim):
    """protocol.json's lengths: LCDPrintf takes 64 KiB of text."""
    fake_sim.script.update(LCD_PRINTF=(0,))
    ran = run(compiler.build(TOO_LONG, name="too_long"), fake_sim.env())
    assert (ran.returncode, ran.stdout) == (0, "long 1\nlongest 0\n")
    assert eyesim_lines(ran.stderr) == [
        "eyesim: LCDPrintf: text of 65537 bytes is too large (the simulator takes at most 65536)"
    ]
    assert fake_sim.count("LCD_PRINTF") == 1

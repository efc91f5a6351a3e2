"""Soak and load of a real `eyesim run` process (realtime, with its viewer), all on 127.0.0.1.

Soak (--minutes, default 10): first a quiet baseline (--baseline-minutes, default 2) of 50
well-behaved C programs (programs/poll_load.c: PSDGet and VWGetPosition in a loop) alone, then the
same programs beside fuzzing clients that send random, mutated and truncated frames of every
operation, browser tabs that open and close, and attackers (issue 25): bursts of idle sockets that
never say HELLO (past the connection cap), a program pipelining thousands of KEYWait requests
without reading, and handshakes with forged program tokens. The run requires its tokens, as a
run does by default. Reported: calls served, errors, the well-behaved programs' p99 with the
attackers against the quiet baseline of the same run (ratio), and the simulator's memory (RSS),
file descriptors (named, when their count grows) and threads before and after. Also the CPU each
phase took, in seconds per second: the simulator's threads, the well-behaved programs, and this
process (the attackers, fuzzers and tabs are threads of it), which tells the simulator's own work
for the attackers from theirs on the same cores.

With --nice-attackers the attackers, fuzzers and tabs run at nice 19 (each thread of this process
lowers its own priority; Linux). They are clients on the machine the simulator runs on: at the same
priority they take the two cores from the well-behaved programs, so their p99 shows the operating
system's scheduler as much as the simulator's fairness. Niced, the figures show the simulator's
share; run it both ways and report both.

--attacks chooses which of them run (fuzz, tabs, idle, forged, keywait; all by default), to tell
their costs apart. --control makes them attack a second simulator, started before the baseline,
instead of the well-behaved programs' own: the machine carries the same clients, but another
process does their work, so the ratio shows what the attackers' load on the cores alone costs.

Load (--load, after the soak; --minutes 0 for the load alone): 100 programs connected at once each
calling in a loop, 200 browser tabs opened at once and closed, 500 connect/disconnect cycles of
programs. Each must be served with no failed call; descriptors and threads must come back.

Run:  python3 bench/soak.py [--minutes 10] [--baseline-minutes 2] [--programs 50] [--load] [--nice-attackers]
                            [--attacks fuzz,tabs,idle,forged,keywait] [--control]
      python3 bench/soak.py --minutes 0.5 --load        (a smoke run, about 2 minutes)
Exit status 1 when a check fails. Every loop is bounded in count and in time."""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import random
import resource
import re
import statistics
import struct
import subprocess
import sys
import threading
import time

import aiohttp

from common import BENCH, build_c, eyesim, print_table, write_results

sys.path.insert(0, str(BENCH.parent / "tests"))
from support.client import ProgramClient, RemoteError  # noqa: E402
from support.memory import rss_mb  # noqa: E402
from support.simulator import token_for  # noqa: E402

from eyesim.protocol import encode_frame, encode_payload, generated as g  # noqa: E402

BUILD = BENCH / "results" / "build"
HOST = "127.0.0.1"
INT_MAX, INT_MIN, U32_MAX = 2**31 - 1, -(2**31), 2**32 - 1
EDGES = [0, 1, -1, 2, 8, 255, 256, 480, 3600, 65535, 10_000_000, 10_000_001, INT_MAX, INT_MIN]
FUZZ_ROBOTS = 2
ATTACKER_NICE = 19  # with --nice-attackers
SETTLE = 3.0  # s to wait after clients leave before counting descriptors and threads


# -- the simulator --------------------------------------------------------------------------------------
class Simulator:
    """`eyesim run` on free ports, its stdout drained, its log kept in a file."""

    def __init__(self, scene: str, name: str):
        self.log_path = BENCH / "results" / f"{name}.log"
        self.log = open(self.log_path, "w")
        self.process = subprocess.Popen(
            eyesim("run", scene, "--port", "0", "--viewer-port", "0", "--clock", "realtime"),
            stdout=subprocess.PIPE,
            stderr=self.log,
            text=True,
            cwd=BENCH,
        )
        self.port = self.viewer_port = self.viewer_token = None
        deadline = time.monotonic() + 60
        for line in self.process.stdout:
            found = re.search(r"viewer: http://[^:]+:(\d+)/\?token=(\S+)", line)
            if found:
                self.viewer_port, self.viewer_token = int(found.group(1)), found.group(2)
            found = re.search(r"programs connect to [\d.]+:(\d+)", line)
            if found:
                self.port = int(found.group(1))
                break
            if time.monotonic() > deadline:
                break
        if self.port is None or self.viewer_port is None:
            self.stop()
            raise RuntimeError(f"the simulator did not start; see {self.log_path}")
        threading.Thread(target=self.process.stdout.read, daemon=True).start()

    def resources(self) -> dict:
        pid = self.process.pid
        names = sorted(open(f"/proc/{pid}/task/{task}/comm").read().strip() for task in os.listdir(f"/proc/{pid}/task"))
        fds = sorted(_fd_target(pid, fd) for fd in os.listdir(f"/proc/{pid}/fd"))
        return {
            "cpu_s": _cpu_seconds(f"/proc/{pid}/stat"),
            "thread_cpu_s": _thread_cpu(pid),
            "rss_mb": round(rss_mb(pid), 1),
            "fds": len(fds),
            "fd_targets": fds,
            "threads": len(names),
            "thread_names": names,
        }

    @property
    def program_token(self) -> str:
        return token_for(self.port)

    def tracebacks(self) -> int:
        self.log.flush()
        return self.log_path.read_text(errors="replace").count("Traceback")

    def stop(self) -> None:
        self.process.terminate()
        try:
            self.process.wait(timeout=15)
        except subprocess.TimeoutExpired:
            self.process.kill()
        self.log.close()


def _cpu_seconds(stat_path: str) -> float:
    """User + system CPU time of a process or thread, from its /proc stat."""
    try:
        with open(stat_path) as stat:
            fields = stat.read().rsplit(")", 1)[1].split()
    except OSError:
        return 0.0
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def _thread_cpu(pid: int) -> dict[str, float]:
    """CPU seconds of the process's threads, by "name/id" (Python threads are all named python, the
    first is the simulation's, the next ones in the order they started)."""
    seconds: dict[str, float] = {}
    for task in sorted(os.listdir(f"/proc/{pid}/task"), key=int):
        try:
            with open(f"/proc/{pid}/task/{task}/comm") as comm:
                name = comm.read().strip()
        except OSError:
            continue
        seconds[f"{name}/{task}"] = _cpu_seconds(f"/proc/{pid}/task/{task}/stat")
    return seconds


class CpuMeter:
    """CPU seconds per wall second over a phase: the simulator (and by thread), the programs this
    process waited for, and this process itself."""

    def __init__(self, simulator: "Simulator"):
        self.simulator = simulator
        self.start = self._now()

    def _now(self) -> dict:
        resources = self.simulator.resources()
        own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
        return {
            "wall": time.monotonic(),
            "simulator": resources["cpu_s"],
            "threads": resources["thread_cpu_s"],
            "programs": children.ru_utime + children.ru_stime,
            "bench": own.ru_utime + own.ru_stime,
        }

    def phase(self) -> dict:
        """The figures since the start or the last phase (call once the phase's programs were collected)."""
        now = self._now()
        start, self.start = self.start, now
        wall = now["wall"] - start["wall"]
        per_second = {key: round((now[key] - start[key]) / wall, 3) for key in ("simulator", "programs", "bench")}
        per_second["simulator_threads"] = {
            name: round((seconds - start["threads"].get(name, 0.0)) / wall, 3)
            for name, seconds in sorted(now["threads"].items())
            if seconds - start["threads"].get(name, 0.0) > 0.01 * wall
        }
        return per_second


def lower_priority(nice: int) -> None:
    """Lower the calling thread's priority (Linux: a thread is a task of its own; elsewhere nothing)."""
    if nice and sys.platform == "linux":
        os.setpriority(os.PRIO_PROCESS, threading.get_native_id(), nice)


def _fd_target(pid: int, fd: str) -> str:
    try:
        return re.sub(r"\[\d+\]", "[...]", os.readlink(f"/proc/{pid}/fd/{fd}"))  # socket:[inode] -> socket:[...]
    except OSError:
        return "gone"


def scene_file(robots: int) -> str:
    side = int(robots**0.5) + 1
    size = 400 * side + 400
    world = BUILD / f"soak_{robots}.wld"
    world.write_text(
        f"floor {size} {size}\n0 0 {size} 0\n{size} 0 {size} {size}\n{size} {size} 0 {size}\n0 {size} 0 0\n"
    )
    path = BUILD / f"soak_{robots}.sim"
    path.write_text(
        f"world {world.name}\n"
        + "".join(f"S4 {400 + 400 * (i % side)} {400 + 400 * (i // side)} 90\n" for i in range(robots))
    )
    return str(path)


# -- well-behaved programs --------------------------------------------------------------------------------
def start_programs(program, port: int, robots: range, seconds: float) -> list[subprocess.Popen]:
    return [
        subprocess.Popen(
            [str(program), f"{seconds:g}"],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            env=dict(
                os.environ,
                EYESIM_HOST=HOST,
                EYESIM_PORT=str(port),
                EYESIM_ROBOT=str(robot),
                EYESIM_TOKEN=token_for(port),
            ),
        )
        for robot in robots
    ]


def collect_programs(programs: list[subprocess.Popen], timeout: float) -> dict:
    """poll_load prints "calls p50_us p99_us max_us sim_ms"; a failed call prints "eyesim: ..." to stderr."""
    rows, failures = [], []
    for program in programs:
        try:
            out, err = program.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            program.kill()
            out, err = program.communicate()
            failures.append("a program did not finish in time")
        failures += [line for line in err.splitlines() if line.strip()]
        if program.returncode != 0:
            failures.append(f"exit code {program.returncode}")
        fields = out.split()
        if len(fields) == 5:
            rows.append([float(v) for v in fields])
        else:
            failures.append(f"no result line: {out!r}")
    return {
        "programs": len(programs),
        "served": sum(1 for r in rows if r[0] > 0),
        "calls": int(sum(r[0] for r in rows)),
        "max_latency_ms": max((r[3] for r in rows), default=0) / 1000,
        "worst_p99_ms": max((r[2] for r in rows), default=0) / 1000,
        "median_p99_ms": statistics.median(r[2] for r in rows) / 1000 if rows else 0,
        "failures": failures,
    }


# -- fuzz traffic -------------------------------------------------------------------------------------------
def random_value(rng: random.Random, typ: str):
    if typ == "i32":
        return rng.choice(EDGES) if rng.random() < 0.5 else rng.randint(INT_MIN, INT_MAX)
    if typ == "u32":
        return rng.choice([0, 1, 999_999_999, U32_MAX]) if rng.random() < 0.5 else rng.randint(0, U32_MAX)
    if typ == "f64":
        return rng.uniform(-1e300, 1e300)
    if typ == "i32s":
        return [random_value(rng, "i32") for _ in range(rng.randint(0, 16))]
    size = rng.choice([0, 1, 10, 100, 1000, 100_000])
    piece = (
        rng.choice(["x", "\n", "\t\n", "é", "\x00"]) if typ == "str" else rng.choice([b"\x00", b"\xff", b"\xff\xfb"])
    )
    return (piece * size)[:size]


def random_frame(rng: random.Random) -> tuple[bytes, int | None]:
    """A frame and the request id a reply must carry, or None when no reply is to be waited for."""
    op = g.OPS[rng.choice(list(g.OPS))]
    values = [random_value(rng, typ) for _, typ in op.request]
    if op.name == "CAM_INIT":
        values[0] = rng.choice([0, 1, 7])  # small images: the soak is about many calls, not big pictures
    request_id = rng.randint(1, U32_MAX)
    frame = encode_frame(op.code, g.KIND_REQUEST, request_id, encode_payload(op.request, values))
    how = rng.random()
    if how < 0.6:
        return frame, None if op.blocking else request_id
    if how < 0.75:  # a byte changed in the payload or the header (the length stays right)
        body = bytearray(frame)
        body[rng.randint(4, len(body) - 1)] = rng.randint(0, 255)
        return bytes(body), None
    if how < 0.85:  # cut short: no reply, the connection is then closed
        return frame[: rng.randint(1, len(frame) - 1)], None
    if how < 0.95:
        return bytes(rng.getrandbits(8) for _ in range(rng.randint(1, 200))), None
    return struct.pack("<I", rng.choice([0, 3, g.MAX_FRAME + 1, U32_MAX])) + bytes(8), None


def fuzzer(port: int, robot: int, until: float, seed: int, counts: dict, lock: threading.Lock, nice: int) -> None:
    """Fresh connections to `robot` until `until`, each sending up to 20 fuzzed frames."""
    lower_priority(nice)
    rng = random.Random(seed)
    while time.monotonic() < until:
        try:
            client = ProgramClient(port, HOST, timeout=10)
            client.hello(str(robot))
        except (OSError, RemoteError):
            time.sleep(0.05)  # the previous connection's robot is not free yet
            continue
        sent = replies = errors = 0
        try:
            for _ in range(rng.randint(1, 20)):
                frame, request_id = random_frame(rng)
                client.sock.sendall(frame)
                sent += 1
                if request_id is None:
                    break  # what follows a broken or blocking request is not waited for
                while True:
                    message = client.receive()
                    if message.request_id == request_id:
                        replies += message.kind == g.KIND_REPLY
                        errors += message.kind == g.KIND_ERROR
                        break
        except (OSError, ConnectionError):
            pass
        finally:
            client.close()
        with lock:
            counts["sent"] += sent
            counts["replies"] += replies
            counts["error_replies"] += errors
            counts["connections"] += 1


# -- browser tabs ----------------------------------------------------------------------------------------------
async def open_tab(session: aiohttp.ClientSession, port: int, token: str, read_for: float) -> bool:
    """Open the viewer's WebSocket, read for a while, close; True when the scene arrived."""
    async with session.ws_connect(f"ws://{HOST}:{port}/ws?token={token}", max_msg_size=0) as ws:
        first = await ws.receive(timeout=30)
        ok = first.type == aiohttp.WSMsgType.TEXT and json.loads(first.data)["type"] == "scene"
        end = time.monotonic() + read_for
        while time.monotonic() < end:
            try:
                await ws.receive(timeout=max(0.01, end - time.monotonic()))
            except asyncio.TimeoutError:
                break
        return ok


async def tabs_coming_and_going(port: int, token: str, until: float) -> dict:
    """Tabs opened and closed one after another (each reads 0.5-3 s), two at a time."""
    rng = random.Random(7)
    opened = failed = 0
    async with aiohttp.ClientSession() as session:
        while time.monotonic() < until:
            results = await asyncio.gather(
                *(open_tab(session, port, token, rng.uniform(0.5, 3)) for _ in range(2)), return_exceptions=True
            )
            opened += len(results)
            failed += sum(1 for r in results if r is not True)
    return {"opened": opened, "failed": failed}


async def many_tabs(port: int, token: str, count: int) -> dict:
    async with aiohttp.ClientSession(connector=aiohttp.TCPConnector(limit=0)) as session:
        results = await asyncio.wait_for(
            asyncio.gather(*(open_tab(session, port, token, 1.0) for _ in range(count)), return_exceptions=True),
            timeout=300,
        )
    failures = [r for r in results if r is not True]
    return {
        "opened": count,
        "failed": len(failures),
        "failures": sorted({repr(r) if isinstance(r, BaseException) else "no scene first" for r in failures})[:5],
    }


# -- the runs --------------------------------------------------------------------------------------------------
ATTACKS = ("fuzz", "tabs", "idle", "forged", "keywait")


def soak(
    minutes: float, baseline_minutes: float, programs: int, program, nice: int = 0, chosen=ATTACKS, control=False
) -> dict:
    seconds = minutes * 60
    scene = scene_file(programs + FUZZ_ROBOTS + 1)  # and one for the KEYWait flooder
    simulator = Simulator(scene, "soak")
    # control: the attackers load the machine as much, but another simulator does their work
    target = Simulator(scene, "soak_control") if control else simulator
    try:
        warm_up(simulator, programs + 1)
        if control:
            warm_up(target, programs + 1)
        before = simulator.resources()
        cpu = CpuMeter(simulator)
        quiet = collect_programs(
            start_programs(program, simulator.port, range(1, programs + 1), baseline_minutes * 60),
            timeout=baseline_minutes * 60 + 120,
        )
        quiet_cpu = cpu.phase()
        after_quiet = simulator.resources()
        start = time.monotonic()
        until = start + seconds
        well_behaved = start_programs(program, simulator.port, range(1, programs + 1), seconds)
        counts = {"sent": 0, "replies": 0, "error_replies": 0, "connections": 0}
        tabs = {"opened": 0, "failed": 0}
        lock = threading.Lock()
        fuzzers = [
            threading.Thread(target=fuzzer, args=(target.port, programs + 1 + k, until, k, counts, lock, nice))
            for k in range(FUZZ_ROBOTS if "fuzz" in chosen else 0)
        ]
        attacks = {
            "idle_sockets": 0,
            "idle_refused_or_closed": 0,
            "key_waits_sent": 0,
            "forged_tokens": 0,
            "forged_refused": 0,
        }
        attackers = [
            threading.Thread(target=attack, args=args)
            for name, attack, args in (
                ("idle", idle_sockets, (target.port, until, attacks, lock, nice)),
                ("forged", forged_tokens, (target.port, until, attacks, lock, nice)),
                ("keywait", key_wait_flood, (target.port, programs + FUZZ_ROBOTS + 1, until, attacks, lock, nice)),
                ("tabs", open_tabs, (target, until, nice, tabs)),
            )
            if name in chosen
        ]
        for thread in fuzzers + attackers:
            thread.start()
        samples = []
        sampler = threading.Thread(target=sample_memory, args=(simulator, start, until, samples))
        sampler.start()
        result = collect_programs(well_behaved, timeout=seconds + 120)
        for thread in fuzzers + attackers:
            thread.join(60)
        attack_cpu = cpu.phase()
        sampler.join(60)
        time.sleep(SETTLE)
        after = simulator.resources()
        return {
            "minutes": minutes,
            "well_behaved": result,
            "baseline": quiet,
            "baseline_minutes": baseline_minutes,
            "attackers_nice": nice,
            "cpu_per_second": {"baseline": quiet_cpu, "with_attackers": attack_cpu},
            "p99_ratio": _ratio(result["median_p99_ms"], quiet["median_p99_ms"]),
            "worst_p99_ratio": _ratio(result["worst_p99_ms"], quiet["worst_p99_ms"]),
            "fuzz": counts,
            "attacks": attacks,
            "tabs": tabs,
            "rss_mb_by_minute": samples,
            "after_baseline": after_quiet,
            "before": before,
            "after": after,
            "attacked": "a second simulator (control)" if control else "the well-behaved programs' simulator",
            "tracebacks": simulator.tracebacks() + (target.tracebacks() if control else 0),
            "simulator_alive": simulator.process.poll() is None and target.process.poll() is None,
        }
    finally:
        simulator.stop()
        if control:
            target.stop()


def open_tabs(simulator: Simulator, until: float, nice: int, tabs: dict) -> None:
    lower_priority(nice)
    tabs.update(asyncio.run(tabs_coming_and_going(simulator.viewer_port, simulator.viewer_token, until)))


def idle_sockets(port: int, until: float, attacks: dict, lock: threading.Lock, nice: int) -> None:
    """Bursts of 300 sockets that never say HELLO, held 8 s (past the 5 s handshake timeout), over and over."""
    import socket

    lower_priority(nice)
    while time.monotonic() < until - 10:
        held = []
        for _ in range(300):
            try:
                held.append(socket.create_connection((HOST, port), timeout=2))
            except OSError:
                break
        deadline = min(until, time.monotonic() + 8)
        while time.monotonic() < deadline:
            time.sleep(0.5)
        closed = 0
        for sock in held:
            sock.setblocking(False)
            try:
                closed += sock.recv(1) == b""
            except BlockingIOError:
                pass
            except OSError:
                closed += 1
            sock.close()
        with lock:
            attacks["idle_sockets"] += len(held)
            attacks["idle_refused_or_closed"] += closed


def forged_tokens(port: int, until: float, attacks: dict, lock: threading.Lock, nice: int) -> None:
    """Handshakes with a wrong program token, ten a second: each must be refused (ERR_BAD_TOKEN)."""
    lower_priority(nice)
    rng = random.Random(25)
    while time.monotonic() < until - 1:
        refused = False
        try:
            client = ProgramClient(port, HOST, token="".join(rng.choice("abcdef0123456789") for _ in range(32)))
            try:
                client.hello()
            except RemoteError as error:
                refused = error.code == g.ERR_BAD_TOKEN
            finally:
                client.close()
        except OSError:
            pass  # refused at the connection cap while the idle sockets fill it
        with lock:
            attacks["forged_tokens"] += 1
            attacks["forged_refused"] += refused
        time.sleep(0.1)


def key_wait_flood(port: int, robot: int, until: float, attacks: dict, lock: threading.Lock, nice: int) -> None:
    """A program that pipelines KEYWait requests and never reads a reply, reconnecting each minute."""
    lower_priority(nice)
    while time.monotonic() < until - 5:
        try:
            client = ProgramClient(port, HOST)
            client.hello(str(robot))
        except (OSError, RemoteError):
            time.sleep(0.5)  # its robot is still taken by the last connection, or the run is full
            continue
        client.sock.settimeout(2)
        end = min(until, time.monotonic() + 60)
        request = 1000
        try:
            while time.monotonic() < end:
                frame = encode_frame(
                    g.OP_KEY_WAIT, g.KIND_REQUEST, request, encode_payload(g.OPS[g.OP_KEY_WAIT].request, (0xFFFF,))
                )
                client.sock.sendall(frame * 100)
                request += 100
                with lock:
                    attacks["key_waits_sent"] += 100
        except OSError:
            pass  # its socket is full: the simulator holds back what it does not take (the cap)
        client.close()


def sample_memory(simulator: Simulator, start: float, until: float, samples: list) -> None:
    """The simulator's RSS once a minute (the viewer's history fills for its first 120 s, then holds)."""
    while time.monotonic() < until:
        time.sleep(min(60.0, max(0.0, until - time.monotonic())))
        samples.append((round((time.monotonic() - start) / 60, 1), simulator.resources()["rss_mb"]))


def warm_up(simulator: Simulator, robot: int) -> None:
    """One program (with a camera image) and two tabs come and go first: what the simulator makes
    once (the camera renderer's OpenGL context and threads, the PNG encoder) is then in the
    'before' figures, and only leaks show as differences."""
    client = ProgramClient(simulator.port, HOST)
    client.hello(str(robot))
    client.call("PSD_GET", 1)
    client.call("CAM_INIT", 1)
    client.call("CAM_GET")
    client.close()
    asyncio.run(many_tabs(simulator.viewer_port, simulator.viewer_token, 2))
    time.sleep(SETTLE)


def load(program) -> dict:
    simulator = Simulator(scene_file(100), "load")
    try:
        warm_up(simulator, 1)
        before = simulator.resources()
        programs = collect_programs(start_programs(program, simulator.port, range(1, 101), 10), timeout=180)
        tabs = asyncio.run(many_tabs(simulator.viewer_port, simulator.viewer_token, 200))
        cycles = connect_cycles(simulator.port, 500)
        time.sleep(SETTLE)
        after = simulator.resources()
        return {
            "programs": programs,
            "tabs": tabs,
            "cycles": cycles,
            "before": before,
            "after": after,
            "tracebacks": simulator.tracebacks(),
            "simulator_alive": simulator.process.poll() is None,
        }
    finally:
        simulator.stop()


def connect_cycles(port: int, count: int) -> dict:
    """Connect, handshake, one call, disconnect; four at a time on robots 1..4."""
    failures = []
    lock = threading.Lock()

    def cycles(robot: int, n: int) -> None:
        for _ in range(n):
            deadline = time.monotonic() + 10
            while True:
                try:
                    client = ProgramClient(port, HOST)
                    client.hello(str(robot))
                    client.call("OS_GET_COUNT")
                    client.close()
                    break
                except RemoteError as error:  # the robot is freed when the simulator reads the close
                    client.close()
                    if error.code != g.ERR_NO_ROBOT or time.monotonic() > deadline:
                        with lock:
                            failures.append(str(error))
                        break
                    time.sleep(0.01)
                except OSError as error:
                    with lock:
                        failures.append(str(error))
                    break

    threads = [threading.Thread(target=cycles, args=(robot, count // 4)) for robot in range(1, 5)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(300)
    return {"cycles": count, "failed": len(failures), "failures": failures[:5]}


def checks(soaked: dict | None, loaded: dict | None) -> list[str]:
    """What failed, in words."""
    problems = []
    for name, run in (("soak", soaked), ("load", loaded)):
        if run is None:
            continue
        if not run["simulator_alive"]:
            problems.append(f"{name}: the simulator died")
        if run["tracebacks"]:
            problems.append(f"{name}: {run['tracebacks']} tracebacks in its log")
        for kind in ("fds", "threads"):
            if run["after"][kind] > run["before"][kind]:
                names = "thread_names" if kind == "threads" else "fd_targets"
                problems.append(
                    f"{name}: {kind} {run['before'][kind]} -> {run['after'][kind]}: "
                    f"{_difference(run['before'][names], run['after'][names])}"
                )
    if soaked:
        behaved = soaked["well_behaved"]
        if behaved["failures"] or behaved["served"] != behaved["programs"]:
            problems.append(
                f"soak: well-behaved programs: {behaved['served']}/{behaved['programs']} served, "
                f"failures {behaved['failures'][:3]}"
            )
        if soaked["tabs"]["failed"]:
            problems.append(f"soak: {soaked['tabs']['failed']} tabs failed")
        quiet = soaked["baseline"]
        if quiet["failures"] or quiet["served"] != quiet["programs"]:
            problems.append(
                f"soak baseline: {quiet['served']}/{quiet['programs']} served, failures {quiet['failures'][:3]}"
            )
        attacks = soaked["attacks"]
        if attacks["forged_refused"] < attacks["forged_tokens"] * 0.5:
            problems.append(
                f"soak: only {attacks['forged_refused']} of {attacks['forged_tokens']} forged tokens refused"
            )
    if loaded:
        programs = loaded["programs"]
        if programs["failures"] or programs["served"] != programs["programs"]:
            problems.append(
                f"load: {programs['served']}/{programs['programs']} served, failures {programs['failures'][:3]}"
            )
        if loaded["tabs"]["failed"] or loaded["cycles"]["failed"]:
            problems.append(
                f"load: {loaded['tabs']['failed']} tabs and {loaded['cycles']['failed']} cycles failed "
                f"{loaded['tabs']['failures'] + loaded['cycles']['failures']}"
            )
    return problems


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--minutes", type=float, default=10.0, help="length of the soak (0: none)")
    parser.add_argument(
        "--baseline-minutes",
        type=float,
        default=2.0,
        help="the well-behaved programs alone first, the baseline of their p99",
    )
    parser.add_argument("--programs", type=int, default=50, help="well-behaved C programs during the soak")
    parser.add_argument(
        "--load", action="store_true", help="also the load scenario (100 programs, 200 tabs, 500 cycles)"
    )
    parser.add_argument(
        "--nice-attackers",
        action="store_true",
        help=f"run the attackers, fuzzers and tabs at nice {ATTACKER_NICE} (Linux), so the p99 shows the simulator's share",
    )
    parser.add_argument(
        "--control",
        action="store_true",
        help="the attackers hit a second simulator: the p99 ratio then shows what their load on the machine "
        "alone costs the well-behaved programs (run it beside a soak without it)",
    )
    parser.add_argument(
        "--attacks",
        default=",".join(ATTACKS),
        help=f"which of {', '.join(ATTACKS)} run beside the well-behaved programs (to tell their costs apart)",
    )
    arguments = parser.parse_args()
    program = build_c(BENCH / "programs" / "poll_load.c", BUILD / "poll_load")
    soaked = (
        soak(
            arguments.minutes,
            arguments.baseline_minutes,
            arguments.programs,
            program,
            ATTACKER_NICE if arguments.nice_attackers else 0,
            _attacks(parser, arguments.attacks),
            arguments.control,
        )
        if arguments.minutes > 0
        else None
    )
    if soaked:
        behaved, fuzz, cpu = soaked["well_behaved"], soaked["fuzz"], soaked["cpu_per_second"]
        print_table(
            f"Soak: {arguments.minutes:g} min, {arguments.programs} well-behaved programs, "
            f"attacks: {arguments.attacks}"
            + (f", attackers at nice {ATTACKER_NICE}" if arguments.nice_attackers else "")
            + (", attacking a second simulator (control)" if arguments.control else ""),
            [
                ("well-behaved calls", behaved["calls"]),
                ("failed well-behaved calls", len(behaved["failures"])),
                ("programs served", f"{behaved['served']}/{behaved['programs']}"),
                ("max latency (ms)", f"{behaved['max_latency_ms']:.1f}"),
                ("worst p99 (ms)", f"{behaved['worst_p99_ms']:.2f}"),
                (
                    "median p99 / worst p99, quiet baseline (ms)",
                    f"{soaked['baseline']['median_p99_ms']:.2f} / {soaked['baseline']['worst_p99_ms']:.2f}",
                ),
                (
                    "p99 with attackers / quiet: median, worst",
                    f"{soaked['p99_ratio']:.2f}, {soaked['worst_p99_ratio']:.2f}",
                ),
                ("fuzz frames / connections", f"{fuzz['sent']} / {fuzz['connections']}"),
                ("fuzz replies / error replies", f"{fuzz['replies']} / {fuzz['error_replies']}"),
                (
                    "idle sockets / refused or closed",
                    f"{soaked['attacks']['idle_sockets']} / {soaked['attacks']['idle_refused_or_closed']}",
                ),
                ("KEYWait requests sent (most never read: the cap)", soaked["attacks"]["key_waits_sent"]),
                (
                    "forged tokens / refused",
                    f"{soaked['attacks']['forged_tokens']} / {soaked['attacks']['forged_refused']}",
                ),
                ("tabs opened / failed", f"{soaked['tabs']['opened']} / {soaked['tabs']['failed']}"),
                *[
                    (
                        f"CPU s/s {phase}: simulator / programs / attackers",
                        f"{cpu[phase]['simulator']:.2f} / {cpu[phase]['programs']:.2f} / {cpu[phase]['bench']:.2f}",
                    )
                    for phase in ("baseline", "with_attackers")
                ],
                (
                    "simulator threads' CPU s/s with attackers",
                    " ".join(f"{name}:{s:.2f}" for name, s in cpu["with_attackers"]["simulator_threads"].items()),
                ),
                *_resources(soaked),
                ("tracebacks in the log", soaked["tracebacks"]),
                ("RSS (MB) by minute", " ".join(f"{m:g}:{mb:.0f}" for m, mb in soaked["rss_mb_by_minute"])),
            ],
            ("", "value"),
        )
    loaded = load(program) if arguments.load else None
    if loaded:
        programs = loaded["programs"]
        print_table(
            "Load: 100 programs at once, 200 tabs at once, 500 connect/disconnect cycles",
            [
                ("programs served", f"{programs['served']}/{programs['programs']}"),
                ("calls", programs["calls"]),
                ("failed calls", len(programs["failures"])),
                ("max latency (ms)", f"{programs['max_latency_ms']:.1f}"),
                ("tabs opened / failed", f"{loaded['tabs']['opened']} / {loaded['tabs']['failed']}"),
                ("cycles / failed", f"{loaded['cycles']['cycles']} / {loaded['cycles']['failed']}"),
                *_resources(loaded),
                ("tracebacks in the log", loaded["tracebacks"]),
            ],
            ("", "value"),
        )
    problems = checks(soaked, loaded)
    write_results("soak", {"soak": soaked, "load": loaded, "problems": problems})
    print("\n" + ("\n".join(problems) if problems else "all checks passed"))
    sys.exit(1 if problems else 0)


def _attacks(parser: argparse.ArgumentParser, names: str) -> tuple[str, ...]:
    chosen = tuple(name.strip() for name in names.split(",") if name.strip())
    unknown = [name for name in chosen if name not in ATTACKS]
    if unknown:
        parser.error(f"unknown attacks {', '.join(unknown)}; choose from {', '.join(ATTACKS)}")
    return chosen


def _ratio(value: float, baseline: float) -> float:
    return value / baseline if baseline else float("inf")


def _difference(before: list[str], after: list[str]) -> str:
    """What `after` has more of than `before` (descriptor targets, thread names)."""
    left = list(before)
    extra = []
    for item in after:
        if item in left:
            left.remove(item)
        else:
            extra.append(item)
    return ", ".join(extra) or "(none new)"


def _resources(run: dict) -> list[tuple]:
    return [
        (f"simulator {name} before -> after", f"{run['before'][name]} -> {run['after'][name]}")
        for name in ("rss_mb", "fds", "threads")
    ]


if __name__ == "__main__":
    main()

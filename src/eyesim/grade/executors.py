"""Where cases run: a local pool (one case process per core, the default) or a Dask distributed
cluster (`--cluster tcp://scheduler:8786`, or `--cluster local:N` for a cluster of N worker
processes on this machine). Both run each task with isolation.run_case_isolated, forked from a
warm runner of the worker thread where there can be one (isolation.WarmRunners), and yield
results as they finish; a case process gives the same result wherever it runs."""

from __future__ import annotations

import logging
import os
import uuid
from concurrent.futures import ThreadPoolExecutor, as_completed

from eyesim.grade.isolation import WarmRunners, failed_result, kill_running

log = logging.getLogger("eyesim")


def _result(task: dict, future) -> dict:
    """The future's result; a worker that failed is the case's grader error, not the run's end."""
    try:
        return future.result()
    except Exception as error:  # noqa: BLE001 - reported per case
        return failed_result(
            task, "grader_error", f"the worker running this case failed: {type(error).__name__}: {error}"
        )


class ExecutorError(Exception):
    pass


class LocalPool:
    """Threads that each wait on one case process at a time: `workers` processes at once. Where
    warm runners can be used (warm.py), each thread forks its cases from a runner of its own."""

    def __init__(self, workers: int | None = None):
        self.workers = workers or os.cpu_count() or 1
        self.description = f"local pool of {self.workers} worker(s)"
        self._pool: ThreadPoolExecutor | None = None
        self._runners = WarmRunners()

    def run(self, tasks: list[dict]):
        self._pool = ThreadPoolExecutor(self.workers)
        futures = {self._pool.submit(self._runners.run, task): task for task in tasks}
        for future in as_completed(futures):
            yield _result(futures[future], future)

    def close(self, abort: bool = False) -> None:
        """With `abort` (an interrupted run), cases still running are killed, not waited for."""
        if self._pool is not None:
            if abort:
                self._pool.shutdown(wait=False, cancel_futures=True)
                kill_running()
            self._pool.shutdown(wait=True, cancel_futures=True)
        self._runners.close()


class DaskCluster:
    """Cases as Dask tasks. The scheduler only ever sees the tasks (scene, spec pieces and the
    submission's files travel inside them), so workers need EyeSim and a C compiler but no
    shared file system."""

    def __init__(self, address: str):
        try:
            from distributed import Client, LocalCluster
        except ImportError:
            raise ExecutorError("--cluster needs Dask: pip install 'eyesim[cluster]' (or dask[distributed])") from None
        self._cluster = None
        try:
            if address.startswith("local:"):
                count = address.split(":", 1)[1]
                if not count.isdigit() or int(count) < 1:
                    raise ExecutorError(f"--cluster {address!r}: expected local:N with N workers, e.g. local:2")
                self._cluster = LocalCluster(
                    n_workers=int(count), threads_per_worker=1, processes=True, dashboard_address=None
                )
                self.client = Client(self._cluster)
            else:
                self.client = Client(address, timeout="10s")  # refused connections are retried until then
        except ExecutorError:
            raise
        except (OSError, TimeoutError) as error:
            raise ExecutorError(f"cannot reach the Dask scheduler at {address}: {error}") from None
        workers = self.client.scheduler_info().get("workers", {})
        self.description = f"Dask cluster {address} ({len(workers)} worker(s))"

    def run(self, tasks: list[dict]):
        from distributed import as_completed as dask_completed

        from eyesim.grade import dask_workers

        self._plugin = f"eyesim-warm-runners-{uuid.uuid4().hex}"
        self.client.register_plugin(dask_workers.WarmRunnerPlugin(), name=self._plugin)
        # pure=False: the same task twice is two runs (a resumed grading re-runs on purpose).
        futures = self.client.map(dask_workers.run_case, tasks, plugin=self._plugin, pure=False, retries=0)
        self._futures = futures
        task_of = {future.key: task for future, task in zip(futures, tasks)}
        for future in dask_completed(futures):
            yield _result(task_of[future.key], future)

    def close(self, abort: bool = False) -> None:
        for future in getattr(self, "_futures", []):
            future.cancel()
        if getattr(self, "_plugin", None) is not None:
            try:
                self.client.unregister_worker_plugin(self._plugin)  # the workers' runners end
            except Exception as error:  # noqa: BLE001 - a worker gone: its runners died with it
                log.warning("could not end the warm case runners on the Dask workers: %s", error)
        self.client.close()
        if self._cluster is not None:
            self._cluster.close()

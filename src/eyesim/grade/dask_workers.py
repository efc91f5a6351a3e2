"""Warm case runners on the Dask workers of `eyesim grade --cluster` (warm.py), as the local pool
has them: a worker plugin keeps a runner for each worker thread for one grading run. The grader
registers it under a name of its own when the run starts and unregisters it when the run is done,
which ends its runners; another grading run on the same cluster has its own."""

from __future__ import annotations

from distributed import WorkerPlugin, get_worker

from eyesim.grade.isolation import WarmRunners, run_case_isolated


class WarmRunnerPlugin(WorkerPlugin):
    def setup(self, worker) -> None:
        self.runners = WarmRunners()

    def teardown(self, worker) -> None:
        self.runners.close()


def run_case(task: dict, plugin: str) -> dict:
    """A Dask task: the case, forked by this worker thread's warm runner where there can be one."""
    runners = getattr(get_worker().plugins.get(plugin), "runners", None)
    return runners.run(task) if runners is not None else run_case_isolated(task)

"""Running a study's chunks on this machine, without Dask: in this process (one worker), or
in worker processes forked from it.

A local cluster of Dask costs its start (0.8–1.4 s), the imports of every worker (about
0.6 s of CPU each) and the scheduler's work per chunk; the machine it runs on needs none of
it. The workers here are forked from the command once it has imported the engine and
advised each member's first variant, so they start with the modules and the catalogs in
memory; each takes one chunk at a time through a pipe. A worker that dies (killed, out of
memory) costs the retry of its chunk in a new worker. Dask stays for ``--scheduler``: a
cluster past this machine.

Both runners give the chunks' results as they arrive, in the order they finish; the study
(:func:`advisor.family.study.run_study`) writes them.
"""

import contextlib
import multiprocessing
import signal
from collections import deque
from collections.abc import Generator, Iterable, Iterator
from dataclasses import dataclass
from multiprocessing.connection import wait
from typing import Any

from advisor.family.adapter import AdvisorError, advise_one
from advisor.family.chunks import ChunkResult, run_chunk
from advisor.family.spec import Family

#: (chunk number, first variant, variant after the last)
Job = tuple[int, int, int]
#: A chunk whose worker died this many times is given up (as Dask's ``retries=2``).
MAX_TRIES = 3
#: The exit code of a study given up because a chunk's worker kept dying (killed, out of
#: memory): not a bug of the advice, not a bad input; the chunks written are kept.
WORKER_LOST_EXIT = 4


class WorkerLost(AdvisorError):
    """A chunk's worker died :data:`MAX_TRIES` times: the study stops (one line, exit 4)."""

    exit_code = WORKER_LOST_EXIT  # type: ignore[assignment]


def worker_lost(job: Job, times: int) -> WorkerLost:
    number, start, stop = job
    return WorkerLost(
        f"chunk {number} (variants {start} to {stop - 1}): its worker died {times} times "
        "(killed, or out of memory?); the chunks written so far are kept: run the same "
        "command again to retry it (a smaller --chunk-size or fewer --workers need less memory)"
    )


class InProcess:
    """One worker: the chunks advised in this process, one after the other."""

    workers = 1

    def results(
        self, family: Family, jobs: Iterable[Job], catalog_dir: str | None, reports: bool
    ) -> Generator[ChunkResult, None, None]:
        for number, start, stop in jobs:
            yield run_chunk(family, number, start, stop, catalog_dir, reports)


def warm_up(family: Family, catalog_dir: str | None) -> None:
    """Advise each member's first variant in this process: the engine's modules, the
    application's and the catalogs are loaded once, before the workers are forked."""
    for m in family.members:
        advise_one(m.requirement(tuple(0 for _ in m.axes)), catalog_dir)


@contextlib.contextmanager
def sigint_blocked() -> Iterator[None]:
    """SIGINT held back while a worker starts: it inherits the mask and ignores the signal
    before it lifts it (ctrl+c reaches the whole process group; the command, not its
    workers, answers it)."""
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    old = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def serve(
    conn: Any, family: Family, catalog_dir: str | None, reports: bool, inherited: tuple = ()
) -> None:
    """A worker: advise the chunk received, send back its result, until told to stop or
    the command is gone (its end of the pipe closed: killed, it cannot say stop).

    ``inherited``: the command's ends of the pipes, this worker's and the others', copied
    by the fork; closed at once, else the worker itself would hold its pipe open and never
    see the end of a command killed with SIGKILL."""
    for other in inherited:
        other.close()
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    if hasattr(signal, "pthread_sigmask"):
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
    with contextlib.suppress(EOFError, OSError):
        while (job := conn.recv()) is not None:
            conn.send(run_chunk(family, *job, catalog_dir, reports))


@dataclass
class Worker:
    process: Any
    conn: Any  # the command's end of the pipe
    job: Job | None = None

    def give(self, job: Job | None) -> None:
        """Send the next chunk (None: stop). A worker already dead is found by its
        sentinel; its chunk is then given to another."""
        self.job = job
        with contextlib.suppress(OSError):
            self.conn.send(job)


class ForkPool:
    """Worker processes forked from this one, one chunk at a time each."""

    def __init__(self, workers: int) -> None:
        self.workers = workers
        methods = multiprocessing.get_all_start_methods()
        self.context = multiprocessing.get_context("fork" if "fork" in methods else None)

    def start(self, args: tuple, pool: list[Worker]) -> Worker:
        """A new worker; ``pool``: the workers running, whose pipe ends it must not keep."""
        ours, theirs = self.context.Pipe()
        forked = self.context.get_start_method() == "fork"
        inherited = (ours, *(w.conn for w in pool if not w.conn.closed)) if forked else ()
        with sigint_blocked():
            p = self.context.Process(target=serve, args=(theirs, *args, inherited), daemon=True)
            p.start()
        theirs.close()
        return Worker(p, ours)

    def results(
        self, family: Family, jobs: Iterable[Job], catalog_dir: str | None, reports: bool
    ) -> Generator[ChunkResult, None, None]:
        jobs = iter(jobs)
        first = [j for j in (next(jobs, None) for _ in range(self.workers)) if j is not None]
        if not first:
            return
        warm_up(family, catalog_dir)
        args = (family, catalog_dir, reports)
        pool: list[Worker] = []
        for _ in first:
            pool.append(self.start(args, pool))
        try:
            for w, job in zip(pool, first, strict=True):
                w.give(job)
            yield from self.run(pool, jobs, args)  # each worker told to stop at the end
        finally:
            stop(pool)

    def run(
        self, pool: list[Worker], jobs: Iterator[Job], args: tuple
    ) -> Generator[ChunkResult, None, None]:
        """Hand out the jobs until every one is done; replace a worker that dies."""
        retry: deque[Job] = deque()
        tries: dict[int, int] = {}
        while busy := [w for w in pool if w.job is not None]:
            ready = set(wait([w.conn for w in busy] + [w.process.sentinel for w in busy]))
            for w in busy:
                if w.conn in ready:
                    try:
                        res = w.conn.recv()
                    except (EOFError, OSError):
                        pass  # it died: its sentinel says so
                    else:
                        w.give(retry.popleft() if retry else next(jobs, None))
                        yield res
                        continue
                if w.job is not None and not w.process.is_alive():
                    retry.append(died(w, tries))
                    pool[pool.index(w)] = new = self.start(args, pool)
                    new.give(retry.popleft())


def died(w: Worker, tries: dict[int, int]) -> Job:
    """The job of a worker that died, to be given again (at most :data:`MAX_TRIES` times)."""
    assert w.job is not None
    n = w.job[0]
    tries[n] = tries.get(n, 0) + 1
    w.conn.close()
    w.process.join()
    if tries[n] >= MAX_TRIES:
        raise worker_lost(w.job, tries[n])
    return w.job


def stop(pool: list[Worker]) -> None:
    """End the workers: those told to stop exit; the others (interrupted, an error) are
    terminated mid-chunk, their chunk not written."""
    for w in pool:
        if w.job is not None:
            w.process.terminate()
    for w in pool:
        w.process.join(timeout=5)
        if w.process.is_alive():
            w.process.kill()
            w.process.join()
        w.conn.close()

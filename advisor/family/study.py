"""Running a family study, with resume and progress: on this machine
(:mod:`advisor.family.local`) or on a ``dask.distributed`` cluster (:class:`DaskRunner`).

The command splits the variants into chunks, hands one task per chunk not yet written to
the runner, and writes each chunk's rows to ``DIR/chunks/cNNNNNN.csv`` (atomically) as it
arrives. A rerun of the same study skips the chunks already written, so an interrupted or
killed study resumes where it stopped. A worker that dies mid-task costs only a retry of
its chunk. When every chunk is in, the chunks are joined into ``DIR/designs.csv``.
"""

import csv
import hashlib
import io
import itertools
import json
import math
import os
import re
import stat
import sys
import time
import uuid
from collections.abc import Callable, Generator, Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any, NamedTuple, Protocol

from advisor.family.adapter import InputError, OutputError, show, write_atomic
from advisor.family.cells import columns
from advisor.family.chunks import ChunkResult, rows_csv, run_chunk
from advisor.family.spec import Family
from advisor.family.summary import SummaryBuilder

MANIFEST = "study.json"
#: what a failed write says has become of the study (exit 2: a full disk is not a bug)
NOTHING_WRITTEN = "nothing was written"
RESUME = "the chunks written so far are kept: free space and run the same command again to resume"
START_OVER = ": free space and run the same command again"
#: (chunk number, first variant, variant after the last)
Job = tuple[int, int, int]


class StudyResult(NamedTuple):
    variants: int
    chunks: int
    computed: int  # chunks computed in this run (the others were already written)
    seconds: float  # wall time of this run's computing
    advise_seconds: float  # time the workers spent advising (sum over computed chunks)


def chunk_count(variants: int, size: int) -> int:
    """How many chunks of ``size`` variants: counted, never listed.

    >>> chunk_count(10, 4), chunk_count(8, 4), chunk_count(0, 4)
    (3, 2, 0)
    """
    return -(-variants // size)


def chunk_range(number: int, variants: int, size: int) -> tuple[int, int]:
    """``(start, stop)`` of chunk ``number``; the last may be shorter.

    >>> [chunk_range(n, 10, 4) for n in range(3)]
    [(0, 4), (4, 8), (8, 10)]
    """
    return number * size, min((number + 1) * size, variants)


def auto_chunk_size(variants: int, workers: int) -> int:
    """The chunk size recommended by the cost model of benchmarks/README.md.

    At least 8 chunks per worker keep the workers busy to the end and make a retried chunk
    cheap; at most 500 variants (about 4 s of rotary advice) per chunk, which keeps the
    scheduler's and client's serial work per chunk (about 8 ms) under a quarter of the
    workers' work up to 64 workers; at least 20 variants, so that even on a few workers a
    chunk is mostly advice. Families of very cheap variants on many workers want larger
    chunks (``--chunk-size``): see the cost model.

    >>> auto_chunk_size(1_000_000, 64), auto_chunk_size(600, 2), auto_chunk_size(50, 2)
    (500, 38, 20)
    """
    return max(20, min(500, math.ceil(variants / (8 * max(workers, 1)))))


def chunk_path(out_dir: Path, number: int) -> Path:
    return out_dir / "chunks" / f"c{number:06d}.csv"


def catalogs_stamp(catalog_dir: Path | None) -> str:
    """Identifies the catalogs a study's variants are advised with: the contents of the
    shipped catalog files and of every file of ``--catalog-dir`` (by name). Chunks computed
    with other catalogs are another study's."""
    from catalogs.loader import HERE, SHIPPED_FILES

    digest = hashlib.sha256()
    named = [(f"shipped/{f}", HERE / f) for f in SHIPPED_FILES]
    if catalog_dir is not None:
        with os.scandir(catalog_dir) as entries:
            named += sorted((f"user/{e.name}", Path(e.path)) for e in entries if e.is_file())
    for name, path in named:
        data = path.read_bytes() if path.is_file() else b""
        digest.update(f"{name}\0{len(data)}\0".encode())
        digest.update(data)
    return digest.hexdigest()[:16]


def make_manifest(
    family: Family, chunk_size: int, reports: bool, catalog_dir: Path | None = None
) -> dict[str, Any]:
    """What identifies a study's chunks: a rerun resumes only the same study."""
    return {
        "fingerprint": family.fingerprint(),
        "catalogs": catalogs_stamp(catalog_dir),
        "chunk_size": chunk_size,
        "variants": family.size,
        "reports": reports,
        "columns": columns(family),
    }


def _read_manifest(out_dir: Path) -> dict[str, Any] | None:
    try:
        old = json.loads((out_dir / "chunks" / MANIFEST).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return old if isinstance(old, dict) else None


def _another_study(out_dir: Path, old: dict[str, Any] | None = None) -> InputError:
    if old is not None and "catalogs" not in old:  # written before the catalogs were stamped
        return InputError(
            f"{out_dir}: holds chunks of another study, made by an older version of the "
            "advisor (its chunks/study.json has no catalogs stamp); delete its chunks/ "
            "folder to compute them again, or use another --out DIR"
        )
    return InputError(
        f"{out_dir}: holds chunks of another study (family, catalogs, chunk size or "
        "--reports differ); use another --out DIR or delete its chunks/ folder"
    )


def precheck_manifest(
    out_dir: Path,
    family: Family,
    chunk_size: int | None,
    reports: bool,
    catalog_dir: Path | None = None,
) -> None:
    """Refuse, before any cluster starts, a DIR that holds chunks of another study (the
    chunk size is compared only when it is already known: given, or kept from that study)."""
    path = out_dir / "chunks" / MANIFEST
    if not path.exists():
        return
    old = _read_manifest(out_dir)
    if old is None:
        raise _another_study(out_dir)
    size = chunk_size or old.get("chunk_size")
    want = make_manifest(family, size, reports, catalog_dir)  # type: ignore[arg-type]
    if old != want:
        raise _another_study(out_dir, old)


def check_manifest(out_dir: Path, manifest: dict[str, Any]) -> None:
    """Write the study's manifest, or refuse a DIR that holds chunks of another study."""
    path = out_dir / "chunks" / MANIFEST
    if path.exists():
        old = _read_manifest(out_dir)
        if old != manifest:
            raise _another_study(out_dir, old)
        return
    with writing(path, NOTHING_WRITTEN):
        path.parent.mkdir(parents=True, exist_ok=True)
        write_atomic(path, json.dumps(manifest, indent=1, sort_keys=True) + "\n")


def previous_chunk_size(out_dir: Path) -> int | None:
    """The chunk size of the study already in ``out_dir`` (a resume keeps it, whatever the
    number of workers now)."""
    try:
        size = json.loads((out_dir / "chunks" / MANIFEST).read_text(encoding="utf-8"))["chunk_size"]
    except (OSError, ValueError, KeyError, TypeError):
        return None
    return size if isinstance(size, int) and size >= 1 else None


class Progress:
    """A one-line progress bar on stderr: chunks, variants, rate and the time left."""

    def __init__(self, chunks: int, variants: int, stream: Any = None, every_s: float = 0.2):
        self.chunks, self.variants = chunks, variants
        self.stream = stream if stream is not None else sys.stderr
        self.tty = bool(getattr(self.stream, "isatty", lambda: False)())
        self.every_s = every_s
        self.t0 = time.monotonic()
        self.last = -math.inf
        self.start_variants: int | None = None
        self.open_line = False  # a bar drawn on a terminal without its line ended

    def update(self, chunks_done: int, variants_done: int, final: bool = False) -> None:
        now = time.monotonic()
        if self.start_variants is None:
            self.start_variants = variants_done
        if not final and now - self.last < (self.every_s if self.tty else 10.0):
            return
        self.last = now
        line = progress_line(
            chunks_done,
            self.chunks,
            variants_done,
            self.variants,
            variants_done - self.start_variants,
            now - self.t0,
        )
        if self.tty:
            self.stream.write("\r" + line + ("\n" if final else "\x1b[K"))
            self.open_line = not final
        else:
            self.stream.write(line + "\n")
        self.stream.flush()

    def end_line(self) -> None:
        """End a bar left open on a terminal, so that a message after it has its own line."""
        if self.open_line:
            self.stream.write("\n")
            self.stream.flush()
            self.open_line = False


def progress_line(
    chunks_done: int,
    chunks: int,
    variants_done: int,
    variants: int,
    computed: int,
    elapsed_s: float,
    width: int = 24,
) -> str:
    """``[#####-----] chunks 3/10, variants 300/1000, 250 variants/s, 2.8 s left``.

    >>> progress_line(3, 10, 300, 1000, 300, 1.2, width=10)
    '[###-------] chunks 3/10, variants 300/1000, 250 variants/s, 2.8 s left'
    """
    filled = round(width * variants_done / variants) if variants else width
    bar = "[" + "#" * filled + "-" * (width - filled) + "]"
    rate = computed / elapsed_s if elapsed_s > 0 else 0.0
    left = (variants - variants_done) / rate if rate > 0 else math.inf
    return (
        f"{bar} chunks {chunks_done}/{chunks}, variants {variants_done}/{variants}, "
        f"{rate:.0f} variants/s, {_duration(left)} left"
    )


def _duration(s: float) -> str:
    if not math.isfinite(s):
        return "? s"
    if s < 60:
        return f"{s:.1f} s"
    if s < 3600:
        return f"{s / 60:.1f} min"
    return f"{s / 3600:.1f} h"


def chunks_written(out_dir: Path, chunks: int) -> set[int]:
    """The numbers of the chunks already in ``out_dir/chunks`` (read from the folder: a
    study of many chunks is not stat-ed chunk by chunk)."""
    try:
        names = os.listdir(out_dir / "chunks")
    except FileNotFoundError:
        return set()
    done = set()
    for name in names:
        if name.startswith("c") and name.endswith(".csv") and name[1:-4].isdigit():
            n = int(name[1:-4])
            if n < chunks:
                done.add(n)
    return done


class DaskRunner:
    """The chunks as tasks on a ``dask.distributed`` cluster, at most ``window`` at a time
    (default: four per worker, at least 16): the next is submitted as one arrives, so
    neither the client nor the scheduler ever holds the whole study. A task whose worker
    dies is retried on another (twice)."""

    def __init__(self, client: Any, window: int | None = None) -> None:
        self.client = client
        self.workers = len(client.scheduler_info()["workers"]) or 1
        self.window = window or max(16, 4 * self.workers)

    def results(
        self, family: Family, jobs: Iterable[Job], catalog_dir: str | None, reports: bool
    ) -> Generator[ChunkResult, None, None]:
        from dask.distributed import as_completed

        # a key of its own per run: the tasks of an interrupted run may still be cancelling
        run_id = f"{family.fingerprint()}-{uuid.uuid4().hex[:8]}"
        jobs = iter(jobs)
        in_flight: dict[Any, Job] = {}

        def submit(job: Job) -> Any:
            fut = self.client.submit(
                run_chunk,
                family,
                *job,
                catalog_dir,
                reports,
                key=f"advisor-family-{run_id}-{job[0]}",
                retries=2,
            )
            in_flight[fut] = job
            return fut

        try:
            queue = as_completed([submit(j) for j in itertools.islice(jobs, self.window)])
            for fut in queue:
                res = result_of(fut, in_flight.pop(fut))
                fut.release()
                nxt = next(jobs, None)
                if nxt is not None:
                    queue.add(submit(nxt))
                yield res
        except BaseException:  # an error, ctrl+c, or the study stopped reading
            self.client.cancel(list(in_flight))
            raise


def result_of(fut: Any, job: Job) -> ChunkResult:
    """A chunk's result; a task whose workers kept dying (Dask gave it up) is said as the
    local runner says it (:class:`advisor.family.local.WorkerLost`)."""
    from distributed import KilledWorker

    from advisor.family.local import MAX_TRIES, worker_lost

    try:
        return fut.result()
    except KilledWorker:
        raise worker_lost(job, MAX_TRIES) from None


class Runner(Protocol):
    """What runs a study's chunks: :class:`DaskRunner`, or one of :mod:`advisor.family.local`."""

    workers: int

    def results(
        self, family: Family, jobs: Iterable[Job], catalog_dir: str | None, reports: bool
    ) -> Generator[ChunkResult, None, None]: ...


def as_runner(runner: Any, window: int | None = None) -> Runner:
    """A runner as given, or a Dask client wrapped in a :class:`DaskRunner`."""
    return runner if hasattr(runner, "results") else DaskRunner(runner, window)


def start_study(
    family: Family, out_dir: Path, chunk_size: int, reports: bool, catalog_dir: Path | None = None
) -> tuple[set[int], int]:
    """Check or write the manifest; the chunks already written and their variants."""
    check_manifest(out_dir, make_manifest(family, chunk_size, reports, catalog_dir))
    if reports:
        with writing(out_dir / "reports", NOTHING_WRITTEN):
            (out_dir / "reports").mkdir(exist_ok=True)
    done = chunks_written(out_dir, chunk_count(family.size, chunk_size))
    done = drop_damaged(out_dir, family, chunk_size, done)
    variants = sum(b - a for a, b in (chunk_range(n, family.size, chunk_size) for n in done))
    return done, variants


def remove_own_temporaries(out_dir: Path) -> None:
    """Delete the temporary files this process left in ``out_dir`` when it was interrupted:
    a ctrl+c that lands between a temporary file's creation and its writer's cleanup (the
    writers name each one ``.NAME.<pid>-<random>.tmp``) would leave it beside the results.
    Another process's temporaries (a second study into the same folder) are not touched."""
    own = f".{os.getpid()}-"
    for folder in (out_dir / "chunks", out_dir / "reports", out_dir):
        try:
            names = [e.name for e in os.scandir(folder) if e.is_file(follow_symlinks=False)]
        except OSError:
            continue
        for name in names:
            if name.startswith(".") and name.endswith(".tmp") and own in name:
                (folder / name).unlink(missing_ok=True)


def write_chunk(out_dir: Path, res: ChunkResult) -> None:
    """A chunk's reports, then its rows: a chunk file marks its reports written. A write
    that fails says what is left: the chunks written before it (kept, for a resume), or,
    where there is none yet, that nothing was written (a run that wrote no chunk removes
    the DIR it created)."""

    def kept() -> str:
        return RESUME if any_chunk_written(out_dir) else NOTHING_WRITTEN + START_OVER

    for name, text in res.reports:
        with writing(out_dir / "reports" / name, kept):
            write_replace(out_dir / "reports" / name, text)
    path = chunk_path(out_dir, res.number)
    with writing(path, kept):
        write_atomic(path, rows_csv(res.rows))


#: A chunk file's name (:func:`chunk_path`).
_CHUNK_NAME = re.compile(r"c[0-9]{6}\.csv")


def any_chunk_written(out_dir: Path) -> bool:
    """Whether ``out_dir/chunks`` holds a chunk file (a resume has something to keep)."""
    try:
        with os.scandir(out_dir / "chunks") as entries:
            return any(_CHUNK_NAME.fullmatch(e.name) for e in entries)
    except OSError:
        return False


@contextmanager
def writing(path: Path, after: str | Callable[[], str]) -> Iterator[None]:
    """Writes to ``path``; a write that fails (a full disk, a read-only folder, a quota)
    becomes an :class:`OutputError` naming the file, its reason and ``after`` (what is left
    of the study, or a function that says it when the write has failed): exit 2 in one line,
    as the batch's full disk, not a bug to report."""
    try:
        yield
    except OSError as exc:
        why = exc.strerror or type(exc).__name__
        left = after() if callable(after) else after
        raise OutputError(f"{show(path, 200)}: cannot write ({why}); {left}") from None


def run_study(
    family: Family,
    out_dir: Path,
    client: Any,
    chunk_size: int,
    *,
    reports: bool = False,
    catalog_dir: Path | None = None,
    progress: Progress | None = None,
    on_chunk: Callable[[int], None] | None = None,
    window: int | None = None,
    summary: SummaryBuilder | None = None,
) -> StudyResult:
    """Compute every chunk not yet written in ``out_dir/chunks``; return what was done.

    ``client`` is a runner (:mod:`advisor.family.local`) or a Dask client (``window``: the
    tasks it keeps on the cluster, see :class:`DaskRunner`). ``on_chunk(n_written_this_run)``
    is called after each chunk is written (tests use it to interrupt a study or kill a
    worker in mid-study). ``summary``: merges each chunk computed (the others are merged
    from their files when the chunks are joined, :func:`join_to_temp`).
    """
    n_chunks = chunk_count(family.size, chunk_size)
    done, done_variants = start_study(family, out_dir, chunk_size, reports, catalog_dir)
    done_chunks = len(done)
    if progress is not None:
        progress.update(done_chunks, done_variants, final=done_chunks == n_chunks)
    t0 = time.perf_counter()
    advise_s = 0.0
    cat = str(catalog_dir) if catalog_dir is not None else None
    jobs = ((n, *chunk_range(n, family.size, chunk_size)) for n in range(n_chunks) if n not in done)
    results = as_runner(client, window).results(family, jobs, cat, reports)
    computed = 0
    try:
        for res in results:
            write_chunk(out_dir, res)
            if summary is not None:
                start = chunk_range(res.number, family.size, chunk_size)[0]
                summary.add_result(res.number, start, res.rows, res.parts)
            computed += 1
            advise_s += res.seconds
            done_chunks += 1
            done_variants += len(res.rows)
            if progress is not None:
                progress.update(done_chunks, done_variants, final=done_chunks == n_chunks)
            if on_chunk is not None:
                on_chunk(computed)
    finally:
        results.close()  # the runner's tasks cancelled, its workers ended
    return StudyResult(family.size, n_chunks, computed, time.perf_counter() - t0, advise_s)


def write_replace(path: Path, text: str) -> None:
    """Write a per-variant report: whole or not at all (temporary file, then rename), without
    the flush to disk of :func:`write_atomic` (a thousand fsyncs would cost more than the
    advice). The chunk's CSV, written after its reports, is flushed: it marks them done."""
    # a name of its own (as io_safety.write_atomic's): two studies writing the same report
    # into one folder at once must not rename each other's temporary file away
    tmp = path.with_name(f".{path.name[:100]}.{os.getpid()}-{os.urandom(6).hex()}.tmp")
    try:
        tmp.write_text(text, encoding="utf-8", newline="\n")
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def chunk_problem(text: str, start: int, stop: int, width: int) -> str | None:
    """What is wrong with a chunk's text, or None: it must hold the rows of variants
    ``start`` … ``stop - 1`` in order, each of ``width`` cells, and end with its last line
    (a file cut short, a stale chunk of another layout or a stray file are refused).

    >>> chunk_problem("0,a\\n1,b\\n", 0, 2, 2) is None, chunk_problem("0,a\\n", 0, 2, 2)
    (True, '1 rows where 2 were expected')
    """
    if text and not text.endswith("\n"):
        return "its last line is cut short"
    rows = list(csv.reader(io.StringIO(text)))
    if len(rows) != stop - start:
        return f"{len(rows)} rows where {stop - start} were expected"
    for i, row in enumerate(rows):
        if len(row) != width or row[0] != str(start + i):
            return f"row {i + 1} is not variant {start + i} in {width} columns"
    return None


def read_chunk(out_dir: Path, family: Family, number: int, chunk_size: int) -> str:
    """A chunk's text, checked (:func:`chunk_problem`); an InputError if it is missing or
    damaged."""
    path = chunk_path(out_dir, number)
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        why: str | None = type(exc).__name__
    else:
        why = chunk_problem(
            text, *chunk_range(number, family.size, chunk_size), len(columns(family))
        )
    if why is not None:
        raise InputError(
            f"{path}: damaged chunk ({why}); run the same command again to recompute it"
        )
    return text


def drop_damaged(out_dir: Path, family: Family, chunk_size: int, done: set[int]) -> set[int]:
    """The chunks of ``done`` that are whole; the damaged ones are deleted, to be computed
    again (a chunk cut short by a full disk, or a stray file of the chunk's name)."""
    whole = set()
    for n in done:
        try:
            read_chunk(out_dir, family, n, chunk_size)
        except InputError:
            chunk_path(out_dir, n).unlink(missing_ok=True)
        else:
            whole.add(n)
    return whole


def new_file(target: Path) -> tuple[int, Path]:
    """An open temporary file beside ``target`` with the mode ``target`` has, or for a new
    file 0666 less the umask (as :func:`write_atomic` gives)."""
    try:
        mode: int | None = stat.S_IMODE(os.stat(target).st_mode)
    except FileNotFoundError:
        mode = None
    tmp = target.with_name(f".{target.name}.{os.getpid()}-{os.urandom(6).hex()}.tmp")
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0), 0o666)
    if mode is not None:
        os.fchmod(fd, mode)
    return fd, tmp


def join_to_temp(
    family: Family, out_dir: Path, chunk_size: int, summary: SummaryBuilder | None = None
) -> Path:
    """The header, then every chunk in order (each checked), in a temporary file beside
    DIR/designs.csv: the caller renames it over designs.csv once everything built from it
    is valid. An InputError (nothing left behind) if a chunk is missing or damaged.
    ``summary``: merges the chunks it has not merged yet (written by an earlier run)."""
    fd, tmp = new_file(out_dir / "designs.csv")
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as fh:
            fh.write(rows_csv([], columns(family)))
            for n in range(chunk_count(family.size, chunk_size)):
                text = read_chunk(out_dir, family, n, chunk_size)
                if summary is not None:
                    summary.add_text(n, chunk_range(n, family.size, chunk_size)[0], text)
                fh.write(text)
            fh.flush()
            os.fsync(fh.fileno())
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return tmp


def join_chunks(family: Family, out_dir: Path, chunk_size: int) -> Path:
    """Write DIR/designs.csv: the header, then every chunk in order (atomically)."""
    target = out_dir / "designs.csv"
    os.replace(join_to_temp(family, out_dir, chunk_size), target)
    return target

"""Running a family study on a ``dask.distributed`` cluster, with resume and progress.

The client splits the variants into chunks, submits one task per chunk not yet written,
and writes each chunk's rows to ``DIR/chunks/cNNNNNN.csv`` (atomically) as it arrives. A
rerun of the same study skips the chunks already written, so an interrupted or killed
study resumes where it stopped. A worker that dies mid-task costs only a retry of its
chunks: the scheduler reassigns them. When every chunk is in, the chunks are joined into
``DIR/designs.csv``.
"""

import json
import math
import os
import sys
import tempfile
import time
import uuid
from collections.abc import Callable
from pathlib import Path
from typing import Any, NamedTuple

from advisor.family.adapter import InputError, write_atomic
from advisor.family.chunks import ChunkResult, columns, rows_csv, run_chunk
from advisor.family.spec import Family

MANIFEST = "study.json"


class StudyResult(NamedTuple):
    variants: int
    chunks: int
    computed: int  # chunks computed in this run (the others were already written)
    seconds: float  # wall time of this run's computing
    advise_seconds: float  # time the workers spent advising (sum over computed chunks)


def chunk_bounds(variants: int, size: int) -> list[tuple[int, int]]:
    """``[(start, stop), …]`` blocks of ``size`` variants; the last may be shorter.

    >>> chunk_bounds(10, 4)
    [(0, 4), (4, 8), (8, 10)]
    """
    return [(s, min(s + size, variants)) for s in range(0, variants, size)]


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


def check_manifest(out_dir: Path, manifest: dict[str, Any]) -> None:
    """Write the study's manifest, or refuse a DIR that holds chunks of another study."""
    path = out_dir / "chunks" / MANIFEST
    if path.exists():
        try:
            old = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            old = None
        if old != manifest:
            raise InputError(
                f"{out_dir}: holds chunks of another study (family, chunk size or --reports "
                "differ); use another --out DIR or delete its chunks/ folder"
            )
        return
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
        else:
            self.stream.write(line + "\n")
        self.stream.flush()


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
) -> StudyResult:
    """Compute every chunk not yet written in ``out_dir/chunks``; return what was done.

    ``on_chunk(n_written_this_run)`` is called after each chunk is written (tests use it to
    interrupt a study or kill a worker in mid-study).
    """
    from dask.distributed import as_completed

    bounds = chunk_bounds(family.size, chunk_size)
    manifest = {
        "fingerprint": family.fingerprint(),
        "chunk_size": chunk_size,
        "variants": family.size,
        "reports": reports,
        "columns": columns(family),
    }
    check_manifest(out_dir, manifest)
    if reports:
        (out_dir / "reports").mkdir(exist_ok=True)
    pending = [n for n in range(len(bounds)) if not chunk_path(out_dir, n).exists()]
    done_chunks = len(bounds) - len(pending)
    todo = set(pending)
    done_variants = sum(b - a for n, (a, b) in enumerate(bounds) if n not in todo)
    if progress is not None:
        progress.update(done_chunks, done_variants, final=not pending)
    t0 = time.perf_counter()
    advise_s = 0.0
    cat = str(catalog_dir) if catalog_dir is not None else None
    # a key of its own per run: the tasks of an interrupted run may still be cancelling
    run_id = f"{manifest['fingerprint']}-{uuid.uuid4().hex[:8]}"
    futures = [
        client.submit(
            run_chunk,
            family,
            n,
            *bounds[n],
            cat,
            reports,
            key=f"advisor-family-{run_id}-{n}",
            retries=2,
        )
        for n in pending
    ]
    computed = 0
    try:
        for fut in as_completed(futures):
            res: ChunkResult = fut.result()
            fut.release()
            for name, text in res.reports:
                write_replace(out_dir / "reports" / name, text)
            write_atomic(chunk_path(out_dir, res.number), rows_csv(res.rows))
            computed += 1
            advise_s += res.seconds
            done_chunks += 1
            done_variants += len(res.rows)
            if progress is not None:
                progress.update(done_chunks, done_variants, final=done_chunks == len(bounds))
            if on_chunk is not None:
                on_chunk(computed)
    except BaseException:
        client.cancel(futures)
        raise
    return StudyResult(family.size, len(bounds), computed, time.perf_counter() - t0, advise_s)


def write_replace(path: Path, text: str) -> None:
    """Write a per-variant report: whole or not at all (temporary file, then rename), without
    the flush to disk of :func:`write_atomic` (a thousand fsyncs would cost more than the
    advice). The chunk's CSV, written after its reports, is flushed: it marks them done."""
    tmp = path.with_name(f".{path.name}.tmp")
    tmp.write_text(text, encoding="utf-8", newline="\n")
    os.replace(tmp, path)


def join_chunks(family: Family, out_dir: Path, chunk_size: int) -> Path:
    """Write DIR/designs.csv: the header, then every chunk in order (atomically)."""
    target = out_dir / "designs.csv"
    header = rows_csv([], columns(family))
    fd, tmp = tempfile.mkstemp(prefix=".designs.csv.", suffix=".tmp", dir=out_dir)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as fh:
            fh.write(header)
            for n in range(len(chunk_bounds(family.size, chunk_size))):
                fh.write(chunk_path(out_dir, n).read_text(encoding="utf-8"))
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return target

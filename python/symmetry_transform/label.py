"""Labels a collection of shapes with their principal symmetries on a Dask cluster.

    python -m symmetry_transform.label FILE|FOLDER... --output OUT.jsonl [--scheduler ADDRESS]
        [--workers N] [--timeout S] [--retries R] [--retry-errors] [--resolution N] [--planes K]
        [--samples N] [--sde-samples N] [--seed S]

Writes one JSON Lines record per file, the record of the C++ command principal_symmetries_batch:
the same fields, the same values for the same file and options (times aside). Folders are
searched recursively as the C++ command searches them. A run started again skips the files
already recorded (and those whose record is an error, unless --retry-errors). Without
--scheduler, a LocalCluster of N worker processes of one thread each runs here; with it, the
workers of that scheduler, each with this package installed, do the work.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from typing import Dict, Iterable, List, Optional

from . import _core

# Options of the records, as the C++ batch names them on its command line.
_BATCH_OPTIONS = {"resolution": "grid_resolution", "planes": "max_number_of_planes", "samples": "number_of_samples",
                  "sde_samples": "sde_samples", "seed": "random_seed"}


def record(file: str, options: Dict[str, int], timeout: float) -> str:
    """The record of one file. With a time limit, computed in a process of its own, killed after
    ``timeout`` seconds (``TimeoutError``, so that the cluster retries it)."""
    if not timeout:
        return _core.batch_record(file, options)
    command = [sys.executable, "-c", "import sys, json, symmetry_transform._core as c; "
               "print(c.batch_record(sys.argv[1], json.loads(sys.argv[2])))", file, json.dumps(options)]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout, check=True)
    except subprocess.TimeoutExpired:
        raise TimeoutError(f"stopped after the time limit of {timeout:g} s") from None
    return done.stdout.rstrip("\n")


def _error_record(file: str, reason: str) -> str:
    return json.dumps({"file": file, "status": "error", "reason": reason}, separators=(",", ":"))


def _client(scheduler: Optional[str], workers: Optional[int]):
    from dask.distributed import Client, LocalCluster
    if scheduler:
        return Client(scheduler), None
    cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                           dashboard_address=None)
    return Client(cluster), cluster


class _Progress:
    def __init__(self, total: int, quiet: bool):
        self.total, self.done, self.errors, self.quiet = total, 0, 0, quiet
        self.start = time.monotonic()

    def completed(self, error: bool) -> None:
        self.done += 1
        self.errors += error
        if not self.quiet:
            elapsed = time.monotonic() - self.start
            left = elapsed / self.done * (self.total - self.done)
            print(f"\r{self.done}/{self.total} files, {self.errors} errors, {elapsed:.0f} s, about {left:.0f} s left ",
                  end="" if self.done < self.total else "\n", file=sys.stderr, flush=True)


def label(inputs: Iterable[str], output: str, scheduler: Optional[str] = None, workers: Optional[int] = None,
          timeout: float = 0, retries: int = 0, retry_errors: bool = False, quiet: bool = False,
          **options: int) -> Dict[str, int]:
    """Labels the files and folders ``inputs`` into ``output`` (JSON Lines, appended); the options
    are those of the records (``grid_resolution``, ``max_number_of_planes``, ``number_of_samples``,
    ``sde_samples``, ``random_seed``). Returns the number of files, of those done before, and of
    errors in this run."""
    every = _core.input_files(list(inputs))
    if not every:
        raise ValueError("no input: give files or folders")
    # The C++ batch's resumption: complete records kept, a line cut short (and, with retry_errors,
    # an error record) dropped from the file.
    done = _core.files_done(output, retry_errors)
    files = [f for f in every if f not in done]
    summary = {"files": len(every), "done_before": len(every) - len(files), "errors": 0}
    if not files:
        return summary
    from dask.distributed import as_completed
    client, cluster = _client(scheduler, workers)
    progress = _Progress(len(files), quiet)
    try:
        futures = {client.submit(record, f, options, timeout, retries=retries, pure=False): f for f in files}
        with open(output, "a", encoding="utf-8") as out:
            for future in as_completed(futures):
                try:
                    line = future.result()
                except Exception as error:  # a time-out or a lost worker, after the retries
                    line = _error_record(futures[future], str(error) or type(error).__name__)
                error = '"status":"error"' in line
                summary["errors"] += error
                out.write(line + "\n")
                out.flush()
                progress.completed(error)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    return summary


def main(argv: Optional[List[str]] = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m symmetry_transform.label",
                                     description="Labels shapes with their principal symmetries on a Dask cluster.")
    parser.add_argument("inputs", nargs="+", metavar="FILE|FOLDER")
    parser.add_argument("--output", required=True, metavar="OUT.jsonl")
    parser.add_argument("--scheduler", metavar="ADDRESS", help="a Dask scheduler (default: a LocalCluster here)")
    parser.add_argument("--workers", type=int, help="workers of the LocalCluster (default: the number of cores)")
    parser.add_argument("--timeout", type=float, default=0, help="seconds per file (default 0: no limit)")
    parser.add_argument("--retries", type=int, default=0, help="retries of a file that timed out or lost its worker")
    parser.add_argument("--retry-errors", action="store_true",
                        help="processes again the files whose record is an error")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    for name in _BATCH_OPTIONS:
        parser.add_argument("--" + name.replace("_", "-"), type=int, help="as principal_symmetries_batch's option")
    args = parser.parse_args(argv)
    options = {key: getattr(args, name) for name, key in _BATCH_OPTIONS.items() if getattr(args, name) is not None}
    summary = label(args.inputs, args.output, args.scheduler, args.workers, args.timeout, args.retries,
                    args.retry_errors, args.quiet, **options)
    print(f"{summary['files']} files, {summary['done_before']} already in {args.output}, "
          f"{summary['errors']} errors in this run; records in {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

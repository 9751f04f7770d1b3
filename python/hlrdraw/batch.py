"""hlrdraw.batch: the jobs of an hlr-batch/1 manifest on a Dask cluster.

    python3 -m hlrdraw.batch MANIFEST.json --scheduler ADDRESS|local [--workers N] [--threads N]
                             [--timeout SECONDS] [--job-timeout SECONDS] [--hlr PATH]

The manifest is the one `hlr batch` runs (DESIGN.md, "The library and its entry points"); the jobs
are read and checked by `hlr batch MANIFEST --list`, so both runners take the same manifests and
run the same command lines. Each job is one Dask task that runs the hlr program on the worker:

  - the client reads the jobs' input files (meshes, a clip job's polygon files) and sends them to
    the cluster (once each, however many jobs read them); a task writes its job's inputs into a
    temporary folder at the paths the manifest spells
    (relative to the manifest's folder; a path that leaves that folder gets a folder of its own,
    keeping its file name), runs `hlr COMMAND ...` there and sends the output files back; the
    client writes them where the manifest says, atomically. So workers need no shared file system, and a job's files are the ones `hlr`
    writes for the same command line (hlr-lines/1 and hlr-surfaces/1 JSON equal apart from
    "stats" and, for paths out of the manifest's folder, the spelling of "input.files");
  - a job that fails is reported with hlr's one-line message and the others go on; the exit
    status is 1 when any job failed, as with `hlr batch`;
  - --timeout bounds the whole batch as it does `hlr batch`'s: a task still running at the deadline
    stops its hlr with SIGTERM (no file written) and reports the job stopped, a task that starts
    after it runs nothing and reports the job not run, and the exit status is 124. The deadline is
    the client's wall clock, which the workers' clocks are taken to follow; --job-timeout is every
    job's own --timeout.

--scheduler local starts a LocalCluster of --workers worker processes (default: one per core), one
job at a time each; otherwise ADDRESS is a running scheduler's ("tcp://host:8786"), whose workers
must have hlrdraw importable and the hlr program (see hlr_executable).

stdout gets one line per job as it finishes, "job K ok: OUTPUT...", "job K failed: PROBLEM" (or
at --timeout "job K stopped: ..." and "job K not run: ..."), as `hlr batch` prints them; stderr the
jobs' warnings and a summary.
"""

import argparse
import collections
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

from . import Error, _write_atomically


def hlr_executable(preferred=None):
    """The hlr program to run: `preferred` (--hlr) when given, else $HLRDRAW_HLR, else the program
    of the build this module was built by (when it is still there), else `hlr` on PATH."""
    candidates = [preferred, os.environ.get("HLRDRAW_HLR")]
    try:
        from ._paths import BUILD_HLR
        candidates.append(BUILD_HLR)
    except ImportError:
        pass
    for candidate in candidates:
        if candidate and os.access(candidate, os.X_OK) and not os.path.isdir(candidate):
            return candidate
    found = shutil.which("hlr")
    if found:
        return found
    raise Error("the hlr program is not found (give --hlr PATH, set HLRDRAW_HLR, or put hlr on PATH)")


def list_jobs(manifest, hlr=None, threads=0, job_timeout=0):
    """The manifest's jobs as `hlr batch --list` gives them: dicts with "job", "arguments" (after
    the program's name) and "inputs" and "outputs" (indices of the arguments that are paths).
    Raises Error with hlr's message for a manifest it rejects."""
    command = [hlr_executable(hlr), "batch", os.fspath(manifest), "--list"]
    if threads:
        command += ["--threads", str(threads)]
    if job_timeout:
        command += ["--job-timeout", repr(job_timeout)]
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode != 0:
        lines = run.stderr.strip().splitlines() or [f"hlr batch --list: exit status {run.returncode}"]
        message = lines[-1]
        raise Error(message[len("hlr: "):] if message.startswith("hlr: ") else message)
    return [json.loads(line) for line in run.stdout.splitlines() if line.strip()]


def timeout_text(seconds):
    """"--timeout 5" as hlr spells it (the shortest decimal that reads back)."""
    return "--timeout " + (str(int(seconds)) if seconds == int(seconds) else repr(seconds))


# How long a job has to stop after SIGTERM before the next signal (as in `hlr batch`).
GRACE_SECONDS = 5


def _stop(process):
    """SIGTERM: hlr stops as a run stopped by a signal does (no file written); a second SIGTERM
    GRACE_SECONDS later makes it exit at once, still removing its temporary files; SIGKILL after
    another."""
    for signal_now in (process.terminate, process.terminate, process.kill):
        signal_now()
        try:
            return process.communicate(timeout=GRACE_SECONDS)
        except subprocess.TimeoutExpired:
            pass
    return process.communicate()


def _run_until(command, folder, deadline):
    """Runs hlr in `folder` until it ends or the wall clock reaches `deadline` (None: no limit);
    returns (exit status, stderr, whether it was stopped)."""
    process = subprocess.Popen(command, cwd=folder, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, text=True)
    try:
        _, stderr = process.communicate(timeout=None if deadline is None else max(0, deadline - time.time()))
        return process.returncode, stderr, False
    except subprocess.TimeoutExpired:
        _, stderr = _stop(process)
        return process.returncode, stderr, process.returncode != 0


def _inside(path):
    """Whether a manifest path stays in the manifest's folder (then it is spelled the same in the
    worker's folder)."""
    if os.path.isabs(path):
        return False
    parts = os.path.normpath(path).split(os.sep)
    return parts[0] != ".."


def run_job(job, inputs, hlr=None, deadline=None, timeout=0):
    """One job on a worker (a Dask task): `inputs` maps each input path as the manifest spells it to
    the file's bytes (Dask hands the task the bytes of the futures the client scattered); `deadline`
    is the batch's end on the wall clock (None: none), `timeout` its --timeout for the messages.
    Returns {"job", "outcome": "ok"|"failed"|"stopped"|"not run", "outputs": {path: bytes},
    "problem", "warnings"}; never raises for a failed job."""
    result = {"job": job["job"], "outcome": "failed", "outputs": {}, "problem": "", "warnings": []}
    if deadline is not None and time.time() >= deadline:
        result["outcome"], result["problem"] = "not run", f"the batch's {timeout_text(timeout)} expired"
        return result
    try:
        program = hlr_executable(hlr if hlr and os.access(hlr, os.X_OK) else None)
    except Error as e:
        result["problem"] = str(e)
        return result
    arguments = list(job["arguments"])
    with tempfile.TemporaryDirectory(prefix="hlrdraw-job-") as folder:
        def local(index, path):
            # Where a manifest path goes in the worker's folder: the same spelling when it stays in
            # the manifest's folder, else a folder of its own that keeps the file name (part names
            # and title blocks come from it).
            if _inside(path):
                return path
            return os.path.join("_outside", str(index), os.path.basename(path))

        for index in job["inputs"]:
            path = arguments[index]
            arguments[index] = local(index, path)
            target = os.path.join(folder, arguments[index])
            os.makedirs(os.path.dirname(target) or folder, exist_ok=True)
            with open(target, "wb") as f:
                f.write(inputs[path])
        for index in job["outputs"]:
            arguments[index] = local(index, arguments[index])
            os.makedirs(os.path.dirname(os.path.join(folder, arguments[index])) or folder, exist_ok=True)
        returncode, stderr, stopped = _run_until([program] + arguments, folder, deadline)
        lines = [line[len("hlr: "):] if line.startswith("hlr: ") else line
                 for line in stderr.splitlines() if line]
        if returncode == 0:
            result["outcome"] = "ok"
            result["warnings"] = lines
            for index in job["outputs"]:
                with open(os.path.join(folder, arguments[index]), "rb") as f:
                    result["outputs"][job["arguments"][index]] = f.read()
        else:
            result["warnings"] = lines[:-1]
            if stopped:
                result["outcome"] = "stopped"
                result["problem"] = f"the batch's {timeout_text(timeout)} expired; no file written"
            elif returncode < 0:
                import signal
                result["problem"] = f"killed by signal {-returncode} ({signal.strsignal(-returncode)})"
            else:
                result["problem"] = lines[-1] if lines else f"exit status {returncode}"
    return result


def _upload(client, job, folder, uploaded):
    """The job's input files as futures on the cluster, each file sent once for every job that reads
    it (`uploaded`: path -> future); or the one-line problem of a file that cannot be read."""
    inputs = {}
    for index in job["inputs"]:
        path = job["arguments"][index]
        if path not in uploaded:
            try:
                with open(path if os.path.isabs(path) else os.path.join(folder, path), "rb") as f:
                    uploaded[path] = client.scatter(f.read())
            except OSError as e:
                return None, f"{path}: cannot open ({e.strerror})"
        inputs[path] = uploaded[path]
    return inputs, None


def _keep_outputs(result, folder):
    """Writes an ok job's files where the manifest says, atomically; a file that cannot be written
    fails the job."""
    try:
        for path, data in result["outputs"].items():
            target = path if os.path.isabs(path) else os.path.join(folder, path)
            os.makedirs(os.path.dirname(target) or ".", exist_ok=True)
            _write_atomically(target, data)
    except (Error, OSError) as e:
        result["outcome"], result["problem"] = "failed", str(e)


def run(manifest, scheduler="local", workers=None, threads=0, hlr=None, out=sys.stdout, err=sys.stderr,
        timeout=0, job_timeout=0):
    """Runs the manifest's jobs on Dask (see the module's help); returns how many jobs had each
    outcome, a Counter of "ok", "failed", "stopped" and "not run"."""
    from distributed import Client, LocalCluster, as_completed

    manifest = os.fspath(manifest)
    jobs = list_jobs(manifest, hlr, threads, job_timeout)
    folder = os.path.dirname(manifest) or "."
    start = time.monotonic()
    deadline = time.time() + timeout if timeout else None
    cluster = None
    if scheduler == "local":
        cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
    else:
        client = Client(scheduler)
    tally = collections.Counter()
    try:
        futures = []
        uploaded = {}
        for job in jobs:
            inputs, problem = _upload(client, job, folder, uploaded)
            if problem:
                tally["failed"] += 1
                print(f"job {job['job']} failed: {problem}", file=out, flush=True)
                continue
            futures.append(client.submit(run_job, job, inputs, hlr, deadline, timeout, pure=False,
                                         key=f"hlr-job-{job['job']}-{id(job)}"))
        for future in as_completed(futures):
            try:
                result = future.result()
            except Exception as e:  # the task itself broke (a worker lost, an import failing there)
                tally["failed"] += 1
                print(f"job ? failed: {type(e).__name__}: {e}", file=out, flush=True)
                continue
            for warning in result["warnings"]:
                print(f"hlrdraw.batch: job {result['job']}: {warning}", file=err)
            if result["outcome"] == "ok":
                _keep_outputs(result, folder)
            tally[result["outcome"]] += 1
            if result["outcome"] == "ok":
                print(f"job {result['job']} ok: " + " ".join(result["outputs"]), file=out, flush=True)
            else:
                print(f"job {result['job']} {result['outcome']}: {result['problem']}", file=out, flush=True)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    seconds = time.monotonic() - start
    if tally["stopped"] or tally["not run"]:
        print(f"hlrdraw.batch: {timeout_text(timeout)}: the batch stopped after {seconds:.3g} s; {tally['ok']} of "
              f"{len(jobs)} jobs ok, {tally['failed']} failed, {tally['stopped']} stopped, {tally['not run']} not run",
              file=err)
    else:
        print(f"hlrdraw.batch: {tally['ok']} of {len(jobs)} jobs ok, {tally['failed']} failed, in {seconds:.3g} s",
              file=err)
    return tally


def _seconds(text):
    """A --timeout value: seconds, 0 for no limit (as hlr's --timeout takes them)."""
    value = float(text)
    if not 0 <= value <= 1e9:
        raise argparse.ArgumentTypeError(f"{text} is not between 0 and 1e9 seconds")
    return value


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="python3 -m hlrdraw.batch",
        description="Run the jobs of an hlr-batch/1 manifest on a Dask cluster, one task per job.")
    parser.add_argument("manifest", help="hlr-batch/1 file; the jobs' paths are relative to its folder")
    parser.add_argument("--scheduler", required=True,
                        help="a Dask scheduler's address (tcp://host:8786), or local for a LocalCluster here")
    parser.add_argument("--workers", type=int, default=0,
                        help="with --scheduler local: worker processes (0, the default: one per core)")
    parser.add_argument("--threads", type=int, default=0,
                        help="threads of each job, passed on as its --threads unless it has one (0: as the job says)")
    parser.add_argument("--timeout", type=_seconds, default=0, metavar="SECONDS",
                        help="stop the batch after SECONDS of wall clock: running jobs are stopped (no file written), "
                             "the others not run; exit 124 (0: no limit)")
    parser.add_argument("--job-timeout", type=_seconds, default=0, metavar="SECONDS",
                        help="every job's --timeout, unless its options have one (0: as the job says)")
    parser.add_argument("--hlr", default=None, help="the hlr program (default: $HLRDRAW_HLR, the build's, or PATH's)")
    args = parser.parse_args(argv)
    try:
        tally = run(args.manifest, args.scheduler, args.workers, args.threads, args.hlr,
                    timeout=args.timeout, job_timeout=args.job_timeout)
    except Error as e:
        print(f"hlrdraw.batch: {e}", file=sys.stderr)
        return 1
    if tally["stopped"] or tally["not run"]:
        return 124  # as `hlr batch` and every hlr command at --timeout
    return 1 if tally["failed"] else 0


if __name__ == "__main__":
    # Run through the module imported by its name, not this __main__ copy, so that Dask sends its
    # tasks as references to hlrdraw.batch.run_job, which workers import, instead of by value.
    from hlrdraw import batch as _batch
    sys.exit(_batch.main())

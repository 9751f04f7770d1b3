"""hlrdraw.batch: the jobs of an hlr-batch/1 manifest on a Dask cluster.

    python3 -m hlrdraw.batch MANIFEST.json --scheduler ADDRESS|local [--workers N] [--threads N]
                             [--hlr PATH]

The manifest is the one `hlr batch` runs (DESIGN.md, "The library and its entry points"); the jobs
are read and checked by `hlr batch MANIFEST --list`, so both runners take the same manifests and
run the same command lines. Each job is one Dask task that runs the hlr program on the worker:

  - the client reads the meshes and sends them to the cluster (once each, however many jobs draw
    them); a task writes its job's meshes into a temporary folder at the paths the manifest spells
    (relative to the manifest's folder; a path that leaves that folder gets a folder of its own,
    keeping its file name), runs `hlr COMMAND ...` there and sends the output files back; the
    client writes them where the manifest says, atomically. So workers need no shared file system, and a job's files are the ones `hlr`
    writes for the same command line (hlr-lines/1 and hlr-surfaces/1 JSON equal apart from
    "stats" and, for paths out of the manifest's folder, the spelling of "input.files");
  - a job that fails is reported with hlr's one-line message and the others go on; the exit
    status is 1 when any job failed, as with `hlr batch`.

--scheduler local starts a LocalCluster of --workers worker processes (default: one per core), one
job at a time each; otherwise ADDRESS is a running scheduler's ("tcp://host:8786"), whose workers
must have hlrdraw importable and the hlr program (see hlr_executable).

stdout gets one line per job as it finishes, "job K ok: OUTPUT..." or "job K failed: PROBLEM",
as `hlr batch` prints them; stderr the jobs' warnings and a summary.
"""

import argparse
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


def list_jobs(manifest, hlr=None, threads=0):
    """The manifest's jobs as `hlr batch --list` gives them: dicts with "job", "arguments" (after
    the program's name) and "meshes" and "outputs" (indices of the arguments that are paths).
    Raises Error with hlr's message for a manifest it rejects."""
    command = [hlr_executable(hlr), "batch", os.fspath(manifest), "--list"]
    if threads:
        command += ["--threads", str(threads)]
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode != 0:
        lines = run.stderr.strip().splitlines() or [f"hlr batch --list: exit status {run.returncode}"]
        message = lines[-1]
        raise Error(message[len("hlr: "):] if message.startswith("hlr: ") else message)
    return [json.loads(line) for line in run.stdout.splitlines() if line.strip()]


def _inside(path):
    """Whether a manifest path stays in the manifest's folder (then it is spelled the same in the
    worker's folder)."""
    if os.path.isabs(path):
        return False
    parts = os.path.normpath(path).split(os.sep)
    return parts[0] != ".."


def run_job(job, meshes, hlr=None):
    """One job on a worker (a Dask task): `meshes` maps each mesh path as the manifest spells it to
    the file's bytes (Dask hands the task the bytes of the futures the client scattered). Returns {"job", "ok", "outputs": {path: bytes}, "problem", "warnings"}; never
    raises for a failed job."""
    result = {"job": job["job"], "ok": False, "outputs": {}, "problem": "", "warnings": []}
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

        for index in job["meshes"]:
            path = arguments[index]
            arguments[index] = local(index, path)
            target = os.path.join(folder, arguments[index])
            os.makedirs(os.path.dirname(target) or folder, exist_ok=True)
            with open(target, "wb") as f:
                f.write(meshes[path])
        for index in job["outputs"]:
            arguments[index] = local(index, arguments[index])
            os.makedirs(os.path.dirname(os.path.join(folder, arguments[index])) or folder, exist_ok=True)
        run = subprocess.run([program] + arguments, cwd=folder, stdin=subprocess.DEVNULL,
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        lines = [line[len("hlr: "):] if line.startswith("hlr: ") else line
                 for line in run.stderr.splitlines() if line]
        if run.returncode == 0:
            result["ok"] = True
            result["warnings"] = lines
            for index in job["outputs"]:
                with open(os.path.join(folder, arguments[index]), "rb") as f:
                    result["outputs"][job["arguments"][index]] = f.read()
        else:
            result["warnings"] = lines[:-1]
            if run.returncode < 0:
                import signal
                result["problem"] = f"killed by signal {-run.returncode} ({signal.strsignal(-run.returncode)})"
            else:
                result["problem"] = lines[-1] if lines else f"exit status {run.returncode}"
    return result


def run(manifest, scheduler="local", workers=None, threads=0, hlr=None, out=sys.stdout, err=sys.stderr):
    """Runs the manifest's jobs on Dask (see the module's help); returns how many failed."""
    from distributed import Client, LocalCluster, as_completed

    manifest = os.fspath(manifest)
    jobs = list_jobs(manifest, hlr, threads)
    folder = os.path.dirname(manifest) or "."
    start = time.monotonic()
    cluster = None
    if scheduler == "local":
        cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        client = Client(cluster)
    else:
        client = Client(scheduler)
    failed = 0
    try:
        futures = []
        uploaded = {}  # mesh path -> its bytes on the cluster, sent once for all the jobs that draw it
        for job in jobs:
            meshes = {}
            problem = None
            for index in job["meshes"]:
                path = job["arguments"][index]
                if path not in uploaded:
                    try:
                        with open(path if os.path.isabs(path) else os.path.join(folder, path), "rb") as f:
                            uploaded[path] = client.scatter(f.read())
                    except OSError as e:
                        problem = f"{path}: cannot open ({e.strerror})"
                        break
                meshes[path] = uploaded[path]
            if problem:
                failed += 1
                print(f"job {job['job']} failed: {problem}", file=out, flush=True)
                continue
            futures.append(client.submit(run_job, job, meshes, hlr, pure=False, key=f"hlr-job-{job['job']}-{id(job)}"))
        for future in as_completed(futures):
            try:
                result = future.result()
            except Exception as e:  # the task itself broke (a worker lost, an import failing there)
                failed += 1
                print(f"job ? failed: {type(e).__name__}: {e}", file=out, flush=True)
                continue
            for warning in result["warnings"]:
                print(f"hlrdraw.batch: job {result['job']}: {warning}", file=err)
            if result["ok"]:
                try:
                    for path, data in result["outputs"].items():
                        target = path if os.path.isabs(path) else os.path.join(folder, path)
                        os.makedirs(os.path.dirname(target) or ".", exist_ok=True)
                        _write_atomically(target, data)
                except (Error, OSError) as e:
                    result["ok"], result["problem"] = False, str(e)
            if result["ok"]:
                print(f"job {result['job']} ok: " + " ".join(result["outputs"]), file=out, flush=True)
            else:
                failed += 1
                print(f"job {result['job']} failed: {result['problem']}", file=out, flush=True)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    print(f"hlrdraw.batch: {len(jobs) - failed} of {len(jobs)} jobs ok, {failed} failed, in "
          f"{time.monotonic() - start:.3g} s", file=err)
    return failed


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
    parser.add_argument("--hlr", default=None, help="the hlr program (default: $HLRDRAW_HLR, the build's, or PATH's)")
    args = parser.parse_args(argv)
    try:
        failed = run(args.manifest, args.scheduler, args.workers, args.threads, args.hlr)
    except Error as e:
        print(f"hlrdraw.batch: {e}", file=sys.stderr)
        return 1
    return 1 if failed else 0


if __name__ == "__main__":
    # Run through the module imported by its name, not this __main__ copy, so that Dask sends its
    # tasks as references to hlrdraw.batch.run_job, which workers import, instead of by value.
    from hlrdraw import batch as _batch
    sys.exit(_batch.main())

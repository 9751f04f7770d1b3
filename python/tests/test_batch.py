"""hlrdraw.batch on a Dask LocalCluster against `hlr batch`: the same manifest gives the same files."""
import json
import os
import shutil
import subprocess
import sys
import time

from conftest import CLI_PARTS, CLIP, HLR, SCENES, run_hlr

MESHES = ["cube.off", "l_bracket.off", "penetrating_boxes.off", "plate_with_hole.off"]


def manifest_jobs():
    """12 jobs: every mesh in three views, drawn (SVG, DXF, JSON) or solved (surfaces JSON), one with
    options, one over two parts, and one whose mesh lies outside the manifest's folder."""
    jobs = []
    for i, mesh in enumerate(MESHES):
        stem = mesh[:-4]
        for view in ("iso", "front", "top"):
            if view == "top" and i % 2 == 1:
                jobs.append({"command": "surfaces", "meshes": [f"meshes/{mesh}"], "view": view,
                             "outputs": [f"out/{stem}_{view}_surfaces.json"]})
            else:
                jobs.append({"command": "draw", "meshes": [f"meshes/{mesh}"], "view": view,
                             "outputs": [f"out/{stem}_{view}.svg", f"out/{stem}/{view}.json"]})
    jobs[1]["options"] = ["--crease", "40", "--sheet", "A3"]
    jobs[1]["outputs"].append("out/cube_front.dxf")
    jobs[4] = {"command": "draw", "meshes": [os.path.join(CLI_PARTS, "front_box.off"),
                                             os.path.join(CLI_PARTS, "back_box.off")],
               "options": ["--dir", "1,-2,-1"], "outputs": ["out/parts.svg", "out/parts.dxf", "out/parts.json"]}
    assert len(jobs) == 12
    return jobs


def prepare(folder, jobs):
    os.makedirs(folder / "meshes")
    for mesh in MESHES:
        shutil.copy(os.path.join(SCENES, mesh), folder / "meshes" / mesh)
    manifest = folder / "manifest.json"
    manifest.write_text(json.dumps({"format": "hlr-batch/1", "jobs": jobs}))
    return manifest


def dask_batch(manifest, *extra):
    return subprocess.run([sys.executable, "-m", "hlrdraw.batch", str(manifest), "--scheduler", "local",
                           "--workers", "2", *extra], capture_output=True, text=True, timeout=240)


def without_seconds(document):
    """A JSON document without every "seconds" (hlr-check/1, hlr-clip/1's "stats")."""
    if isinstance(document, dict):
        return {key: without_seconds(value) for key, value in document.items() if key != "seconds"}
    if isinstance(document, list):
        return [without_seconds(item) for item in document]
    return document


def comparable(path):
    data = path.read_bytes()
    if path.suffix != ".json":
        return data
    document = without_seconds(json.loads(data))
    document.pop("stats", None)  # hlr-lines/1's timings and counts of work
    if isinstance(document.get("input"), dict):
        document["input"].pop("files", None)  # spelled as the runner gave the path
    return document


def out_files(folder):
    return sorted(p.relative_to(folder) for p in (folder / "out").rglob("*") if p.is_file())


def results(stdout):
    return sorted(stdout.splitlines())


def test_dask_runs_the_manifest_as_hlr_batch_does(tmp_path):
    jobs = manifest_jobs()
    local = prepare(tmp_path / "local", jobs)
    dask = prepare(tmp_path / "dask", jobs)

    run = run_hlr("batch", local, "--jobs", "2")
    assert run.code == 0, run.err
    on_dask = dask_batch(dask)
    assert on_dask.returncode == 0, on_dask.stderr

    assert len(run.out.splitlines()) == 12
    assert results(on_dask.stdout) == results(run.out)
    for line in run.out.splitlines():
        assert " ok: " in line, line
    files = sorted(p.relative_to(tmp_path / "local") for p in (tmp_path / "local" / "out").rglob("*") if p.is_file())
    assert files == sorted(p.relative_to(tmp_path / "dask") for p in (tmp_path / "dask" / "out").rglob("*") if p.is_file())
    assert len(files) == sum(len(job["outputs"]) for job in jobs)
    for name in files:
        assert comparable(tmp_path / "dask" / name) == comparable(tmp_path / "local" / name), name
    # Paths inside the manifest's folder are spelled alike in both runs.
    first = json.loads((tmp_path / "dask" / "out" / "cube" / "iso.json").read_text())
    assert first["input"]["files"] == ["meshes/cube.off"]
    # And a job's files are the ones hlr writes for its command line.
    direct = tmp_path / "direct.svg"
    assert run_hlr("draw", "meshes/l_bracket.off", "--view", "iso", "-o", direct, cwd=tmp_path / "local").code == 0
    assert direct.read_bytes() == (tmp_path / "dask" / "out" / "l_bracket_iso.svg").read_bytes()


def test_dask_reports_a_failed_job_and_finishes_the_others(tmp_path):
    jobs = [{"command": "draw", "meshes": ["meshes/cube.off"], "outputs": ["out/cube.svg"]},
            {"command": "draw", "meshes": ["meshes/missing.off"], "outputs": ["out/missing.svg"]},
            {"command": "draw", "meshes": ["meshes/cube.off"], "view": "sideways", "outputs": ["out/bad_view.svg"]}]
    manifest = prepare(tmp_path, jobs)
    on_dask = dask_batch(manifest)
    assert on_dask.returncode == 1
    lines = results(on_dask.stdout)
    assert lines == ["job 0 ok: out/cube.svg",
                     "job 1 failed: meshes/missing.off: cannot open (No such file or directory)",
                     'job 2 failed: --view: unknown view "sideways" (use front, back, top, bottom, left, right, iso, '
                     "or --dir X,Y,Z)"]
    assert results(run_hlr("batch", manifest).out) == lines
    assert sorted(os.listdir(tmp_path / "out")) == ["cube.svg"]


def test_a_malformed_manifest_is_one_line(tmp_path):
    manifest = tmp_path / "manifest.json"
    manifest.write_text(json.dumps({"format": "hlr-batch/1", "jobs": [{"command": "draw", "meshes": ["a.off"]}]}))
    on_dask = dask_batch(manifest)
    assert on_dask.returncode == 1
    assert on_dask.stderr.strip() == f'hlrdraw.batch: {manifest}: job 0: "outputs" is missing'
    assert on_dask.stdout == ""


def prepare_clip_and_check(folder):
    """A manifest of a clip job (its polygon files in the manifest's folder), a check job, a draw
    job, a shadows job and a mesh job (neither has a view)."""
    jobs = [{"command": "clip", "inputs": ["polygons/subject.json", "polygons/clip.json"], "options": ["--exact"],
             "outputs": ["out/clip.json"]},
            {"command": "check", "meshes": ["meshes/l_bracket.off"], "view": "iso", "options": ["--raster", "256"],
             "outputs": ["out/check/diff.png", "out/check/report.json"]},
            {"command": "draw", "meshes": ["meshes/cube.off"], "view": "top", "outputs": ["out/top.svg"]},
            {"command": "shadows", "meshes": ["meshes/l_bracket.off"], "options": ["--sun", "1,2,-4"],
             "outputs": ["out/shadows.csv", "out/shadows.json"]},
            {"command": "mesh", "meshes": ["meshes/plate_with_hole.off"], "outputs": ["out/plate.obj"]}]
    manifest = prepare(folder, jobs)
    os.makedirs(folder / "polygons")
    for name in ("subject.json", "clip.json"):
        shutil.copy(os.path.join(CLIP, name), folder / "polygons" / name)
    return manifest


def test_dask_runs_clip_check_shadows_and_mesh_jobs_as_hlr_batch_and_the_cli_do(tmp_path):
    local = prepare_clip_and_check(tmp_path / "local")
    dask = prepare_clip_and_check(tmp_path / "dask")
    run = run_hlr("batch", local, "--jobs", "2")
    assert run.code == 0, run.err
    on_dask = dask_batch(dask)
    assert on_dask.returncode == 0, on_dask.stderr
    assert results(on_dask.stdout) == results(run.out) == [
        "job 0 ok: out/clip.json", "job 1 ok: out/check/diff.png out/check/report.json", "job 2 ok: out/top.svg",
        "job 3 ok: out/shadows.csv out/shadows.json", "job 4 ok: out/plate.obj"]
    files = out_files(tmp_path / "local")
    assert files == out_files(tmp_path / "dask") and len(files) == 7
    for name in files:
        assert comparable(tmp_path / "dask" / name) == comparable(tmp_path / "local" / name), name
    # The clip job's file is the one `hlr clip` writes for the same command line (but its time).
    direct = tmp_path / "direct_clip.json"
    assert run_hlr("clip", "polygons/subject.json", "polygons/clip.json", "--exact", "-o", direct,
                   cwd=tmp_path / "local").code == 0
    assert without_seconds(json.loads(direct.read_text())) == \
        without_seconds(json.loads((tmp_path / "dask" / "out" / "clip.json").read_text()))


def test_dask_reports_a_clip_job_whose_input_is_missing(tmp_path):
    jobs = [{"command": "clip", "inputs": ["polygons/none.json", "polygons/clip.json"], "outputs": ["out/c.json"]}]
    manifest = prepare(tmp_path, jobs)
    on_dask = dask_batch(manifest)
    assert on_dask.returncode == 1
    assert on_dask.stdout == "job 0 failed: polygons/none.json: cannot open (No such file or directory)\n"
    assert not (tmp_path / "out").exists()


def bumpy_grid(path, n):
    """A bumpy grid of n x n vertices, 2 (n - 1)^2 triangles, none coplanar: about 10 s of work for
    hlr at n = 300 on one core (tests/cli/limits_test.cpp has the same)."""
    state = 12345
    lines = ["OFF", f"{n * n} {2 * (n - 1) * (n - 1)} 0"]
    for y in range(n):
        for x in range(n):
            state = (state * 6364136223846793005 + 1442695040888963407) % 2**64
            lines.append(f"{x} {y} {(state >> 40) / float(1 << 24)!r}")
    for y in range(n - 1):
        for x in range(n - 1):
            v = y * n + x
            lines.append(f"3 {v} {v + 1} {v + n + 1}")
            lines.append(f"3 {v} {v + n + 1} {v + n}")
    path.write_text("\n".join(lines) + "\n")
    return path


def test_a_task_stops_its_job_at_the_batchs_deadline(tmp_path):
    from hlrdraw import batch
    grid = bumpy_grid(tmp_path / "grid.off", 300).read_bytes()
    # With a sun's shadows: far longer than the deadline, however fast the drawing alone becomes.
    job = {"job": 3, "arguments": ["draw", "grid.off", "--threads", "1", "--sun", "1,2,-3", "-o", "a.svg",
                                   "-o", "a.json"],
           "inputs": [1], "outputs": [7, 9]}
    stopped = batch.run_job(job, {"grid.off": grid}, HLR, deadline=time.time() + 1, timeout=1)
    assert stopped["outcome"] == "stopped", stopped
    assert stopped["problem"] == "the batch's --timeout 1 expired; no file written"
    assert stopped["outputs"] == {}
    late = batch.run_job(job, {"grid.off": grid}, HLR, deadline=time.time() - 1, timeout=2.5)
    assert (late["outcome"], late["problem"]) == ("not run", "the batch's --timeout 2.5 expired")


def test_dask_batch_timeout_exits_124_with_one_summary_line(tmp_path):
    # The cluster takes longer than a millisecond to start: no job starts before the deadline.
    jobs = [{"command": "draw", "meshes": ["meshes/cube.off"], "outputs": ["out/cube.svg"]},
            {"command": "clip", "inputs": ["meshes/cube.off", "meshes/cube.off"], "outputs": ["out/c.json"]}]
    manifest = prepare(tmp_path, jobs)
    on_dask = dask_batch(manifest, "--timeout", "0.001")
    assert on_dask.returncode == 124, on_dask.stderr
    assert results(on_dask.stdout) == ["job 0 not run: the batch's --timeout 0.001 expired",
                                       "job 1 not run: the batch's --timeout 0.001 expired"]
    summary = [line for line in on_dask.stderr.splitlines() if line.startswith("hlrdraw.batch: ")]
    assert len(summary) == 1 and summary[0].startswith("hlrdraw.batch: --timeout 0.001: the batch stopped after ")
    assert summary[0].endswith(" s; 0 of 2 jobs ok, 0 failed, 0 stopped, 2 not run"), summary
    assert not (tmp_path / "out").exists()

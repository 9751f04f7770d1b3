"""hlrdraw.batch on a Dask LocalCluster against `hlr batch`: the same manifest gives the same files."""
import json
import os
import shutil
import subprocess
import sys

from conftest import CLI_PARTS, HLR, SCENES, run_hlr

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


def comparable(path):
    data = path.read_bytes()
    if path.suffix != ".json":
        return data
    document = json.loads(data)
    document.pop("stats", None)
    document.get("input", {}).pop("files", None)  # spelled as the runner gave the path
    return document


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

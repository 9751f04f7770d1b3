"""hlrdraw against the hlr program: the same drawings, surfaces, clips, files and messages."""
import json
import os
import threading

import numpy as np
import pytest

import hlrdraw
from conftest import CLI_PARTS, CLIP, PARTS, SCENES, SOURCE_DIR, run_hlr

CUBE_VERTICES = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                          [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=float)
CUBE_FACES = np.array([[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]])


def without_stats(document):
    """A document without what differs from run to run (timings) or by the caller (sheet counts)."""
    document = dict(document)
    document.pop("stats", None)
    return document


def cli_json(tmp_path, *args):
    out = tmp_path / "cli.json"
    run = run_hlr(*args, "-o", out)
    assert run.code == 0, run.err
    return json.loads(out.read_text())


# (files, view arguments of hlr draw, the same as hlrdraw keywords)
DRAW_CASES = [
    ([os.path.join(SCENES, "l_bracket.off")], ["--view", "iso"], {"view": "iso"}),
    ([os.path.join(SCENES, "penetrating_boxes.off")], ["--view", "front"], {"view": "front"}),
    ([os.path.join(SCENES, "edge_on.off")], ["--dir", "1,2,-3", "--crease", "60"], {"direction": (1, 2, -3), "crease": 60}),
    ([os.path.join(SCENES, "plate_with_hole.off")], ["--view", "top", "--no-intersections"],
     {"view": "top", "intersections": False}),
    ([os.path.join(CLI_PARTS, "front_box.off"), os.path.join(CLI_PARTS, "back_box.off")], ["--view", "iso"], {}),
    ([os.path.join(SCENES, "t_junction.off")], ["--dir", "0,0,-1", "--up", "1,1,0", "--kernel", "epick"],
     {"direction": (0, 0, -1), "up": (1, 1, 0), "kernel": "epick"}),
]


@pytest.mark.parametrize("files,arguments,keywords", DRAW_CASES, ids=lambda c: str(c)[-40:] if isinstance(c, str) else None)
def test_draw_gives_the_programs_json_and_arrays(tmp_path, files, arguments, keywords):
    expected = cli_json(tmp_path, "draw", *files, *arguments)
    drawing = hlrdraw.draw_file(files, **keywords)
    assert without_stats(drawing.json()) == without_stats(expected)
    assert drawing.view == expected["view"]
    assert drawing.input == expected["input"]
    lines = expected["lines"]
    assert len(drawing) == len(lines) > 0
    assert drawing.a.shape == drawing.b.shape == (len(lines), 3)
    assert drawing.a.tolist() == [line["a"] for line in lines]
    assert drawing.b.tolist() == [line["b"] for line in lines]
    assert drawing.visible.tolist() == [line["visible"] for line in lines]
    assert drawing.kind.tolist() == [line["kind"] for line in lines]
    assert drawing.mesh.tolist() == [line["mesh"] for line in lines]
    assert drawing.edge.tolist() == [line["edge"] if line["edge"] is not None else [-1, -1] for line in lines]
    assert drawing["visible"] is drawing.visible


def test_a_mesh_from_arrays_draws_as_its_file(tmp_path):
    path = tmp_path / "cube.off"
    path.write_text("OFF\n8 6 0\n" + "".join(f"{x:g} {y:g} {z:g}\n" for x, y, z in CUBE_VERTICES) +
                    "".join("4 " + " ".join(map(str, f)) + "\n" for f in CUBE_FACES))
    from_file = hlrdraw.draw_file(path, view="front")
    from_arrays = hlrdraw.draw(CUBE_VERTICES, CUBE_FACES, view="front")
    as_lists = hlrdraw.draw(CUBE_VERTICES.tolist(), [list(f) for f in CUBE_FACES], view="front")
    for drawing in (from_arrays, as_lists):
        assert drawing.json()["lines"] == from_file.json()["lines"]
    assert from_arrays.input["files"] == ["mesh"]
    # A mesh read from a file draws as the file does, groups and fans included (read_mesh keeps them).
    anchor = os.path.join(PARTS, "anchor.off")
    mesh = hlrdraw.read_mesh(anchor)
    vertices, faces = mesh
    assert vertices.shape[1] == 3 and len(faces) == len(mesh.face_index)
    assert hlrdraw.draw(mesh).json()["lines"] == hlrdraw.draw_file(anchor).json()["lines"]
    # Several meshes are one scene of several parts.
    shifted = CUBE_VERTICES + [2, 0, 0]
    two = hlrdraw.draw([(CUBE_VERTICES, CUBE_FACES), (shifted, CUBE_FACES, "right")])
    assert two.input["files"] == ["mesh0", "right"]
    assert set(two.mesh.tolist()) == {0, 1}


def test_sheets_are_the_programs_bytes(tmp_path):
    mesh = os.path.join(SCENES, "plate_with_hole.off")
    for arguments, style in [([], {}),
                             (["--sheet", "A3", "--scale", "1:2", "--hidden", "none", "--no-centre-lines",
                               "--line-group", "0.7", "--merge-distance", "0", "--contact-angle", "0"],
                              {"sheet": "A3", "scale": "1:2", "hidden": False, "centre_lines": False,
                               "line_group": 0.7, "merge_distance": 0, "contact_angle": 0})]:
        cli = [tmp_path / f"cli.{ext}" for ext in ("svg", "dxf", "pdf")]
        run = run_hlr("draw", mesh, "--view", "iso", *arguments, *sum((["-o", p] for p in cli), []))
        assert run.code == 0, run.err
        drawing = hlrdraw.draw_file(mesh, view="iso")
        hlrdraw.write_svg(drawing, tmp_path / "py.svg", **style)
        hlrdraw.write_dxf(drawing, tmp_path / "py.dxf", **style)
        hlrdraw.write_pdf(drawing, tmp_path / "py.pdf", **style)
        hlrdraw.write_json(drawing, tmp_path / "py.json")
        assert (tmp_path / "py.svg").read_bytes() == cli[0].read_bytes()
        assert (tmp_path / "py.dxf").read_bytes() == cli[1].read_bytes()
        assert (tmp_path / "py.pdf").stat().st_size > 0 and (tmp_path / "py.pdf").read_bytes()[:5] == b"%PDF-"
        assert drawing.svg(**style) == cli[0].read_text()
    assert without_stats(json.loads((tmp_path / "py.json").read_text())) == without_stats(drawing.json())
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        ["cli.svg", "cli.dxf", "cli.pdf", "py.svg", "py.dxf", "py.pdf", "py.json"])  # no temporary file left


@pytest.mark.parametrize("exact", [False, True])
def test_surfaces_give_the_programs_json(tmp_path, exact):
    files = [os.path.join(SCENES, "penetrating_boxes.off")]
    extra = ["--exact"] if exact else []
    expected = cli_json(tmp_path, "surfaces", *files, "--view", "iso", *extra)
    assert without_stats(hlrdraw.surfaces(files, view="iso", exact=exact)) == without_stats(expected)
    expected = cli_json(tmp_path, "surfaces", *files, "--dir", "1,1,1", "--keep-back-faces", "--no-consolidation")
    got = hlrdraw.surfaces(files, direction=(1, 1, 1), keep_back_faces=True, consolidation=False)
    assert without_stats(got) == without_stats(expected)


def test_clip_gives_the_programs_json(tmp_path):
    subject, clip = os.path.join(CLIP, "subject.json"), os.path.join(CLIP, "clip.json")
    for extra, exact in [([], False), (["--exact"], True)]:
        out = tmp_path / "clip.json"
        run = run_hlr("clip", subject, clip, "-o", out, *extra)
        assert run.code == 0, run.err
        expected = json.loads(out.read_text())
        with open(subject) as s, open(clip) as c:
            got = hlrdraw.clip(json.load(s), json.load(c), exact=exact)
        assert without_stats(got) == without_stats(expected)
    # Numpy contours, a polygon with a hole as a dict.
    square = np.array([[0, 0], [4, 0], [4, 4], [0, 4]], dtype=float)
    frame = {"outer": square, "holes": [square[::-1] * 0.5 + 1]}
    result = hlrdraw.clip([frame], square + [2, 0], exact=True)
    assert result["format"] == "hlr-clip/1"
    assert {len(result["inside"]), len(result["outside"])} <= {1, 2}


SHADOW_BOX = os.path.join(SOURCE_DIR, "fixtures", "shadows", "box_on_ground.off")


def test_shadows_give_the_programs_json_for_suns_and_point_lights(tmp_path):
    expected = cli_json(tmp_path, "shadows", SHADOW_BOX, "--sun", "1,2,-4", "--point-light", "1,-4,4", "--union")
    got = hlrdraw.shadows(SHADOW_BOX, sun=(1, 2, -4), point_light=np.array([1.0, -4.0, 4.0]), union=True)
    assert without_stats(got) == without_stats(expected)
    assert got["lights"] == [{"type": "directional", "direction": [1, 2, -4]}, {"type": "point", "position": [1, -4, 4]}]
    # The ground's lit area under each light (fixtures/shadows/README.md): 393 and 372.
    ground = next(s for s in got["sources"] if 0 in s["faces"])
    assert [light["lit_area"] for light in ground["lights"]] == [393, 372]
    # Several point lights, as a list; a mesh from arrays.
    two = hlrdraw.shadows(hlrdraw.read_mesh(SHADOW_BOX), point_light=[(1, -4, 4), (1, 1, 4)])
    assert [light["position"] for light in two["lights"]] == [[1, -4, 4], [1, 1, 4]]
    ground = next(s for s in two["sources"] if 0 in s["faces"])
    assert [light["lit_area"] for light in ground["lights"]] == [372, 384]


def test_draw_with_a_point_light_is_the_programs_svg(tmp_path):
    out = tmp_path / "cli.svg"
    run = run_hlr("draw", SHADOW_BOX, "--view", "top", "--point-light", "1,-4,4", "-o", out)
    assert run.code == 0, run.err
    drawing = hlrdraw.draw_file(SHADOW_BOX, view="top", point_light=(1, -4, 4))
    assert drawing.svg() == out.read_text()
    assert '<g id="shadows"' in drawing.svg()
    assert '<g id="shadows"' not in hlrdraw.draw_file(SHADOW_BOX, view="top").svg()


def test_bad_lights_raise_one_line(hlr):
    with pytest.raises(hlrdraw.Error, match=r"^point_light \(1, 1, 1\): .*inside a closed solid"):
        hlrdraw.shadows(SHADOW_BOX, point_light=(1, 1, 1))
    with pytest.raises(hlrdraw.Error, match=r"^point_light \(1, 1, 1\): "):
        hlrdraw.draw_file(SHADOW_BOX, point_light=(1, 1, 1))
    with pytest.raises(hlrdraw.Error, match=r"^sun \(0, 0, 0\): .*zero"):
        hlrdraw.shadows(SHADOW_BOX, sun=(0, 0, 0))
    with pytest.raises(hlrdraw.Error, match=r"^sun: no light"):
        hlrdraw.shadows(SHADOW_BOX)
    with pytest.raises(hlrdraw.Error, match=r"^point_light: expected 3 numbers"):
        hlrdraw.shadows(SHADOW_BOX, point_light=(1, 2))
    with pytest.raises(hlrdraw.Error, match=r"^sun: shadows are drawn by the exact path only"):
        hlrdraw.draw_file(SHADOW_BOX, sun=(1, 2, -4), kernel="epick")


# ---- bad input: the program's messages -----------------------------------------------------------

def test_bad_mesh_files_raise_the_programs_message(tmp_path):
    cases = {
        "missing.off": None,
        "empty.off": "",
        "truncated.off": "OFF\n4 1 0\n0 0 0\n1 0 0\n",
        "index.off": "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
        "nan.off": "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n",
        "bowtie.off": "OFF\n4 1 0\n0 0 0\n2 2 0\n2 0 0\n0 2 0\n4 0 1 2 3\n",
        "mesh.xyz": "x",
    }
    for name, text in cases.items():
        path = tmp_path / name
        if text is not None:
            path.write_text(text)
        run = run_hlr("draw", path, "-o", tmp_path / "out.svg")
        assert run.code == 1
        with pytest.raises(hlrdraw.Error) as raised:
            hlrdraw.draw_file(path)
        assert str(raised.value) == run.error, name
        with pytest.raises(hlrdraw.Error) as raised:
            hlrdraw.read_mesh(path)
        assert str(raised.value) == run.error, name
    assert not (tmp_path / "out.svg").exists()


def test_bad_arrays_raise_one_line_naming_the_mesh(tmp_path):
    # The same problems in arrays and in a file give the same message, the name standing for the file.
    bowtie = tmp_path / "bowtie.off"
    bowtie.write_text("OFF\n4 1 0\n0 0 0\n2 2 0\n2 0 0\n0 2 0\n4 0 1 2 3\n")
    run = run_hlr("draw", bowtie, "-o", tmp_path / "out.svg")
    with pytest.raises(hlrdraw.Error) as raised:
        hlrdraw.mesh([[0, 0, 0], [2, 2, 0], [2, 0, 0], [0, 2, 0]], [[0, 1, 2, 3]], name=str(bowtie))
    assert str(raised.value) == run.error
    triangle = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    bad = [
        ((triangle, [[0, 1, 3]]), "mesh: face 0: vertex index 3 is out of range (3 vertices)"),
        ((triangle, [[0, -1, 2]]), "mesh: face 0: vertex index -1 is out of range (3 vertices)"),
        (([[0, 0, 0], [float("nan"), 0, 0], [0, 1, 0]], [[0, 1, 2]]), "mesh: vertex 1: x coordinate nan is not a finite number"),
        (([[0, 0, 0], [1e101, 0, 0], [0, 1, 0]], [[0, 1, 2]]), "mesh: vertex 1: x coordinate 1e+101 is out of range"),
        (([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]]), "mesh: vertices have shape (3, 2), expected (n, 3)"),
        ((triangle, np.array([[0.0, 1.0, 2.0]])), "mesh: faces are not vertex indices (dtype float64, expected integers)"),
        ((triangle, [[0.0, 1.0, 2.0]]), "mesh: face 0 is not a sequence of vertex indices"),
        ((triangle, np.zeros((0, 3), dtype=int)), "mesh: no faces (the file has 3 vertices and no face)"),
        ((triangle, [[0, 1, 2], "abc"]), "mesh: face 1 is not a sequence of vertex indices"),
    ]
    for (vertices, faces), message in bad:
        with pytest.raises(hlrdraw.Error) as raised:
            hlrdraw.draw(vertices, faces)
        assert str(raised.value).startswith(message), (str(raised.value), message)
        assert isinstance(raised.value, ValueError)


def test_bad_views_and_options_raise(tmp_path):
    bracket = os.path.join(SCENES, "l_bracket.off")
    for keywords, message in [
        ({"view": "diagonal"}, 'view: unknown view "diagonal"'),
        ({"direction": (0, 0, 1), "up": (0, 0, 2)}, "direction/up: up vector is parallel to the view direction"),
        ({"direction": (0, 0, 0)}, "direction/up: view direction is zero"),
        ({"direction": (1, 2)}, "direction: expected 3 numbers"),
        ({"kernel": "float"}, 'kernel: unknown kernel "float"'),
        ({"crease": 200}, "crease: 200 degrees is outside [0, 180]"),
    ]:
        with pytest.raises(hlrdraw.Error) as raised:
            hlrdraw.draw_file(bracket, **keywords)
        assert str(raised.value).startswith(message), str(raised.value)
    # The program says the same of the view after its option's name.
    run = run_hlr("draw", bracket, "--dir", "0,0,1", "--up", "0,0,2", "-o", tmp_path / "x.svg")
    assert run.code == 2 and run.err.strip() == "hlr: --dir/--up: up vector is parallel to the view direction"

    drawing = hlrdraw.draw_file(bracket)
    for style, message in [({"sheet": "A7"}, 'sheet: unknown sheet "A7"'), ({"scale": "1:0"}, 'scale: "1:0" is not a scale'),
                           ({"units": "ft"}, 'units: unknown unit "ft"'), ({"line_group": 0.4}, "line_group: 0.4 is not"),
                           ({"scale": "50:1"}, "scale 50:1: the drawing needs")]:
        with pytest.raises(hlrdraw.Error) as raised:
            hlrdraw.write_svg(drawing, tmp_path / "x.svg", **style)
        assert str(raised.value).startswith(message), str(raised.value)
    run = run_hlr("draw", bracket, "--scale", "50:1", "-o", tmp_path / "x.svg")
    assert run.code == 2 and run.err.strip().startswith("hlr: --scale 50:1: the drawing needs")
    with pytest.raises(TypeError):
        hlrdraw.write_svg(drawing, tmp_path / "x.svg", colour="red")
    with pytest.raises(hlrdraw.Error) as raised:
        hlrdraw.write_svg(drawing, tmp_path / "no" / "such" / "x.svg")
    assert str(raised.value) == f"{tmp_path / 'no' / 'such' / 'x.svg'}: cannot write (No such file or directory)"
    with pytest.raises(hlrdraw.Error) as raised:
        hlrdraw.write_svg(drawing, tmp_path)
    assert str(raised.value) == f"{tmp_path}: cannot write (Is a directory)"
    assert list(tmp_path.iterdir()) == []  # nothing written, no temporary file left


def test_bad_polygons_raise_the_programs_message(tmp_path):
    clip = os.path.join(CLIP, "clip.json")
    for polygons, problem in [
        ([[[0, 0], [4, 0], [0, 4]], [[0, 0], [2, 2], [2, 0], [0, 2]]], "polygon 1 outer contour edges 0 and 2 intersect"),
        ([[[0, 0], [1, 0]]], "polygon 0 outer contour has 2 distinct vertices, at least 3 are needed"),
        ([[[0, 0], [float("inf"), 0], [0, 4]]], "polygon 0 outer vertex 1: x coordinate is not a finite number"),
        ([[[0, 0], [float("nan"), 0], [0, 4]]], "polygon 0 outer vertex 1: x coordinate is not a finite number"),
        ([[[0, 0], [1e101, 0], [0, 4]]], "polygon 0 outer vertex 1: x coordinate 1e+101 is out of range"),
        ([{"outer": [[0, 0], [4, 0], [4, 4], [0, 4]], "holes": [[[5, 5], [6, 5], [6, 6]]]}],
         "polygon 0 hole 0 lies outside the outer contour"),
    ]:
        path = tmp_path / "bad.json"
        path.write_text(json.dumps({"format": "hlr-polygons/1",
                                    "polygons": [p if isinstance(p, dict) else {"outer": p} for p in polygons]})
                        .replace("Infinity", "1e400").replace("NaN", "1e400"))
        run = run_hlr("clip", path, clip, "-o", tmp_path / "out.json")
        assert run.code == 1
        assert run.error.startswith(f"{path}: {problem}"), run.error
        said = run.error[len(f"{path}: "):]
        with open(clip) as c:
            clip_document = json.load(c)
        with pytest.raises(hlrdraw.Error) as raised:
            hlrdraw.clip(polygons, clip_document)
        assert str(raised.value) == f"subject: {said}"
        with pytest.raises(hlrdraw.Error) as raised:
            hlrdraw.clip(clip_document, polygons)
        assert str(raised.value) == f"clip: {said}"
    with pytest.raises(hlrdraw.Error) as raised:
        hlrdraw.clip({"format": "hlr-clip/1", "polygons": []}, [])
    assert str(raised.value) == 'subject: format is "hlr-clip/1", expected "hlr-polygons/1"'


# ---- threads and progress ------------------------------------------------------------------------

def test_jobs_run_side_by_side_in_threads_and_report_progress():
    anchor = os.path.join(PARTS, "anchor.off")
    views = ["iso", "front", "top", "right"]
    alone = {view: hlrdraw.draw_file(anchor, view=view).json()["lines"] for view in views}
    together = {}
    threads = [threading.Thread(target=lambda v=view: together.__setitem__(v, hlrdraw.draw_file(anchor, view=v).json()["lines"]))
               for view in views]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert together == alone
    assert hlrdraw.draw_file(anchor, view="iso", threads=1).json()["lines"] == alone["iso"]
    with pytest.raises(hlrdraw.Error):
        hlrdraw.draw_file(anchor, threads=-1)

    stages = []
    hlrdraw.draw_file(anchor, progress=stages.append)
    assert stages and all(isinstance(s, str) for s in stages)

    class Stop(Exception):
        pass

    def stop(stage):
        raise Stop(stage)

    with pytest.raises(Stop):
        hlrdraw.draw_file(anchor, progress=stop)


def test_the_readmes_example_runs(tmp_path, monkeypatch):
    with open(os.path.join(SOURCE_DIR, "README.md"), encoding="utf-8") as f:
        readme = f.read()
    section = readme[readme.index("\n## Python\n"):]
    code = section[section.index("```python\n") + len("```python\n"):section.index("\n```\n")]
    os.symlink(os.path.join(SOURCE_DIR, "fixtures"), tmp_path / "fixtures")
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {})
    assert (tmp_path / "cube.svg").read_bytes().startswith(b"<?xml")


INTERRUPTED_DRAW = """
import sys, time
import numpy as np
import hlrdraw
# A height field of 2 x 200 x 200 triangles with a sun's shadows: several seconds of work (without
# the shadows, under half a second), in stages that poll the stop flag.
n = 200
x, y = np.meshgrid(np.arange(n + 1.0), np.arange(n + 1.0))
z = np.sin(x * 0.37) * np.cos(y * 0.23) * 3 + (x * y) % 7 * 0.01
vertices = np.column_stack([x.ravel(), y.ravel(), z.ravel()])
i = (np.arange(n)[None, :] + (n + 1) * np.arange(n)[:, None]).ravel()
faces = np.concatenate([np.column_stack([i, i + 1, i + n + 2]), np.column_stack([i, i + n + 2, i + n + 1])])
mesh = hlrdraw.mesh(vertices, faces)
def stage(what):
    print("stage", time.monotonic(), what, flush=True)
try:
    hlrdraw.draw(mesh, view="iso", sun=(1, 2, -3), progress=stage)
    print("finished", flush=True)
except KeyboardInterrupt:
    print("KeyboardInterrupt", time.monotonic(), flush=True)
"""


def test_ctrl_c_stops_a_job_within_its_stage():
    import signal
    import subprocess
    import sys
    import time
    child = subprocess.Popen([sys.executable, "-c", INTERRUPTED_DRAW], stdout=subprocess.PIPE, text=True,
                             env=dict(os.environ))
    first = child.stdout.readline()
    assert first.startswith("stage"), first
    time.sleep(0.3)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    rest = child.communicate(timeout=60)[0].splitlines()
    assert rest and rest[-1].startswith("KeyboardInterrupt"), rest
    # Within its stage: no later stage began after the signal (at most one, begun as it was sent).
    # Decided on the order of events, not on a time, which a loaded machine would stretch.
    later = [line for line in rest if line.startswith("stage") and float(line.split()[1]) > sent]
    assert len(later) <= 1, f"the job went on into later stages: {later}"

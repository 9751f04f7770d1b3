#!/usr/bin/python3
"""Checks hlr drawings with tools outside the project: check_drawing.py [--parts A,B,...] [--render DIR] FILE...

  .dxf   read by ezdxf (recover.readfile, then a strict readfile) and audited: any audit error fails
         (ezdxf's own repairs, "fixes", are listed but pass). A drawing of hlr draw has layers
         VISIBLE and HIDDEN (or, for a scene of several meshes, NAME-VISIBLE and NAME-HIDDEN for
         each part and no VISIBLE/HIDDEN) and CENTER, every hidden layer's linetype a dashed pattern
         defined in the file, CENTER's a long-dash dotted one, and every entity on one of those
         layers. A sheet of hlr sheet (blocks VIEW_*) has layers VISIBLE, HIDDEN, CENTER and BORDER,
         in model space only BORDER entities and inserts of the view blocks, and in the blocks only
         VISIBLE, HIDDEN and CENTER entities.
         A drawing with shadows (hlr draw --sun) also has layer SHADOW with solid HATCH entities only
         (a sheet with shadows, hlr sheet --sun: in its view blocks).
  .svg   parsed with xml.etree (root <svg>, size in mm, every path and circle of the visible and
         hidden groups inside a part group <g id="part-NAME-visible|hidden" class="part-NAME">, or in
         a sheet inside a view group <g id="view-NAME">, ids unique) and rendered with rsvg-convert
         to a temporary PNG: a non-zero exit or an empty PNG fails.
  .pdf   read by poppler's pdfinfo (one page, the size of an ISO A sheet, landscape) and rendered
         by pdftoppm to a PNG that must not be blank.
  .json  the keys and types of hlr-lines/1 (DESIGN.md "The JSON contract").

--parts A,B,...  the drawings are of a scene of these parts (names as docs/FORMATS.md makes them
                 from the mesh files): the DXF must have exactly their layer pairs (upper case), the
                 SVG's part groups must name only them and name each at least once.
--render DIR     keep the renders: FILE's SVG and PDF as DIR/NAME.svg.png and DIR/NAME.pdf.png, and
                 DXFs drawn by ezdxf's drawing add-on with matplotlib as DIR/NAME.dxf.png.

One line per file, "ok" or "FAIL" first; exit status 0 only when every file passes.
Run it with Debian's interpreter, /usr/bin/python3: python3-ezdxf belongs to it.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET


class CheckFailed(Exception):
    pass


def require(condition, message):
    if not condition:
        raise CheckFailed(message)


def check_dxf(path):
    try:
        import ezdxf
        from ezdxf import recover
    except ImportError:
        raise CheckFailed(f"ezdxf is not installed for {sys.executable} (apt-get install python3-ezdxf)")
    try:
        doc, auditor = recover.readfile(path)
    except Exception as e:  # IOError, DXFStructureError, a decoding error...
        raise CheckFailed(f"ezdxf cannot read it: {type(e).__name__}: {e}")
    errors = [f"recover: {e.message}" for e in auditor.errors]
    audit = doc.audit()
    errors += [f"audit: {e.message}" for e in audit.errors]
    require(not errors, f"{len(errors)} ezdxf error(s): " + "; ".join(errors))
    try:
        ezdxf.readfile(path)  # the strict reader must take it too
    except Exception as e:
        raise CheckFailed(f"ezdxf.readfile fails: {e}")
    blocks = [b.name for b in doc.blocks if b.name.upper().startswith("VIEW_")]
    if blocks:
        return check_dxf_sheet(path, doc, blocks, auditor, audit)
    if PARTS:
        pairs = [(f"{p.upper()}-VISIBLE", f"{p.upper()}-HIDDEN") for p in PARTS]
        for name in ("VISIBLE", "HIDDEN"):
            require(not doc.layers.has_entry(name), f"layer {name} in a drawing of several parts")
    else:
        pairs = [("VISIBLE", "HIDDEN")]
    wanted = {name for pair in pairs for name in pair} | {"CENTER"}
    for name in sorted(wanted):
        require(doc.layers.has_entry(name), f"layer {name} missing")
    # hlr draw --sun: the shadows, solid HATCH entities on layer SHADOW, and nothing else there.
    shadows = None
    if doc.layers.has_entry("SHADOW"):
        on_shadow = doc.modelspace().query('*[layer=="SHADOW"]')
        require(all(e.dxftype() == "HATCH" for e in on_shadow), "entities other than HATCH on layer SHADOW")
        require(all(e.dxf.solid_fill == 1 for e in on_shadow), "a HATCH on layer SHADOW is not solid")
        shadows = len(on_shadow)
        wanted |= {"SHADOW"}
    wanted |= thin_layers(doc, [visible[: -len("VISIBLE")] + "THIN" for visible, _ in pairs])
    # ezdxf adds "Defpoints" as it loads a file
    extra = {layer.dxf.name for layer in doc.layers if layer.dxf.name.lower() != "defpoints"} - wanted - {"0"}
    require(not extra, f"unexpected layers {sorted(extra)}")
    pattern = None
    for _, hidden in pairs:
        pattern = dashed_pattern(doc, hidden)
    centre = centre_pattern(doc)
    msp = doc.modelspace()
    counts = {layer: len(msp.query(f'*[layer=="{layer}"]')) for layer in sorted(wanted)}
    require(sum(counts.values()) == len(msp), "entities on layers other than the drawing's")
    fixes = len(auditor.fixes) + len(audit.fixes)
    curves = f"{len(msp.query('CIRCLE'))} circles, {len(msp.query('ARC'))} arcs"
    if PARTS:
        per_layer = ", ".join(f"{layer} {n}" for layer, n in counts.items())
        return f"entities: {per_layer}; {curves}; hidden dashed {pattern}, ezdxf audit: 0 errors, {fixes} fixes"
    if shadows is not None:
        curves += f", {shadows} shadow hatches"
    return (f"{counts['VISIBLE']} visible, {counts['HIDDEN']} hidden, {counts['CENTER']} centre entities, {curves}, "
            f"HIDDEN dashed {pattern}, CENTER {centre}, $LTSCALE {doc.header.get('$LTSCALE', 1)}, "
            f"ezdxf audit: 0 errors, {fixes} fixes")


def dashed_pattern(doc, layer):
    ltype = doc.layers.get(layer).dxf.linetype
    require(doc.linetypes.has_entry(ltype), f"linetype {ltype} of layer {layer} is not defined in the file")
    pattern = doc.linetypes.get(ltype).simplified_line_pattern()
    require(len(pattern) >= 2 and any(x > 0 for x in pattern[1::2]),
            f"linetype {ltype} of layer {layer} is not dashed (pattern {pattern})")
    return pattern


def centre_pattern(doc):
    """CENTER's linetype: a long dash, a gap, a dot (a dash of at most a tenth of the long one), a gap."""
    pattern = dashed_pattern(doc, "CENTER")
    require(len(pattern) == 4 and pattern[2] <= pattern[0] / 10, f"CENTER is not long-dash dotted (pattern {pattern})")
    return pattern


def thin_layers(doc, names):
    """--smooth-edges thin: layers of smooth lines, continuous and narrower than VISIBLE, when defined."""
    found = set()
    for name in names:
        if not doc.layers.has_entry(name):
            continue
        layer = doc.layers.get(name)
        require(layer.dxf.linetype.upper() == "CONTINUOUS", f"layer {name} is not continuous")
        visible = name[: -len("THIN")] + "VISIBLE"
        if doc.layers.has_entry(visible):
            require(0 < layer.dxf.lineweight < doc.layers.get(visible).dxf.lineweight, f"layer {name} is not narrow")
        found.add(name)
    return found


def check_dxf_sheet(path, doc, blocks, auditor, audit):
    wanted = {"VISIBLE", "HIDDEN", "CENTER", "BORDER"}
    for name in sorted(wanted):
        require(doc.layers.has_entry(name), f"layer {name} missing")
    wanted |= thin_layers(doc, ["THIN"])
    # hlr sheet --sun: the shadows, solid HATCH entities on layer SHADOW in the view blocks only.
    hatches = 0
    if doc.layers.has_entry("SHADOW"):
        wanted |= {"SHADOW"}
        for name in blocks:
            on_shadow = doc.blocks.get(name).query('*[layer=="SHADOW"]')
            require(all(e.dxftype() == "HATCH" for e in on_shadow), f"entities other than HATCH on layer SHADOW in {name}")
            require(all(e.dxf.solid_fill == 1 for e in on_shadow), f"a HATCH on layer SHADOW in {name} is not solid")
            hatches += len(on_shadow)
        require(hatches > 0, "layer SHADOW without a HATCH in any view block")
    extra = {layer.dxf.name for layer in doc.layers if layer.dxf.name.lower() != "defpoints"} - wanted - {"0"}
    require(not extra, f"unexpected layers {sorted(extra)}")
    dashed_pattern(doc, "HIDDEN")
    centre_pattern(doc)
    msp = doc.modelspace()
    inserts = msp.query("INSERT")
    require(sorted(i.dxf.name for i in inserts) == sorted(blocks), "the view blocks are not each inserted once")
    require(all(e.dxf.layer == "BORDER" for e in msp if e.dxftype() != "INSERT"),
            "model space entities other than the view inserts off layer BORDER")
    circles = arcs = 0
    for name in blocks:
        block = doc.blocks.get(name)
        layers = {e.dxf.layer for e in block}
        require(layers <= {"VISIBLE", "HIDDEN", "CENTER", "THIN", "SHADOW"} & wanted, f"block {name} has entities on {sorted(layers)}")
        circles += len(block.query("CIRCLE"))
        arcs += len(block.query("ARC"))
    fixes = len(auditor.fixes) + len(audit.fixes)
    border = len(msp) - len(inserts)
    return (f"sheet of {len(blocks)} view blocks ({', '.join(blocks)}), {circles} circles, {arcs} arcs, "
            f"{hatches} shadow hatches, {border} border entities, ezdxf audit: 0 errors, {fixes} fixes")


def render_dxf(path):
    """The DXF drawn by ezdxf's drawing add-on with matplotlib, into RENDER (if set)."""
    if not RENDER:
        return ""
    try:
        import logging
        import matplotlib
        matplotlib.use("Agg")
        # dxflib's text style names the font file "txt" (AutoCAD's txt.shx): matplotlib has none of
        # that name and says so for every text, then uses its default font.
        logging.getLogger("matplotlib.font_manager").setLevel(logging.ERROR)
        import matplotlib.pyplot as plt
        from ezdxf.addons.drawing import Frontend, RenderContext
        from ezdxf.addons.drawing.matplotlib import MatplotlibBackend
        import ezdxf
    except ImportError as e:
        raise CheckFailed(f"cannot render the DXF: {e}")
    doc = ezdxf.readfile(path)
    fig = plt.figure()
    ax = fig.add_axes([0, 0, 1, 1])
    Frontend(RenderContext(doc), MatplotlibBackend(ax)).draw_layout(doc.modelspace(), finalize=True)
    out = os.path.join(RENDER, os.path.basename(path) + ".png")
    fig.savefig(out, dpi=150)
    plt.close(fig)
    require(os.path.getsize(out) > 0, "the DXF rendered to an empty PNG")
    return f", drawn to {out}"


SVG = "{http://www.w3.org/2000/svg}"


def check_svg_parts(root):
    """The part groups of the visible and hidden groups; returns {part: [paths visible, hidden]}."""
    ids = [e.get("id") for e in root.iter() if e.get("id") is not None]
    require(len(ids) == len(set(ids)), "repeated ids: " + ", ".join(sorted({i for i in ids if ids.count(i) > 1})))
    parts = {}
    for cls in ("visible", "hidden"):
        outer = [g for g in root.iter(SVG + "g") if g.get("id") == cls]
        if not outer:
            continue
        for child in outer[0]:
            require(child.tag == SVG + "g", f"a {child.tag} directly in group {cls}, not in a part group")
            gid, klass = child.get("id", ""), child.get("class", "")
            require(gid.startswith("part-") and gid.endswith("-" + cls), f"group {gid!r} in {cls} is not a part group")
            name = gid[len("part-"):-len(cls) - 1]
            require(klass == "part-" + name, f"group {gid} has class {klass!r}, not part-{name}")
            paths = [e for e in child if e.tag in (SVG + "path", SVG + "circle")]
            require(paths and len(paths) == len(child), f"group {gid} is empty or holds more than paths and circles")
            parts.setdefault(name, [0, 0])[0 if cls == "visible" else 1] += len(paths)
    if PARTS:
        require(set(parts) <= set(PARTS), f"part groups {sorted(set(parts) - set(PARTS))} are not parts of the scene")
        require(set(parts) == set(PARTS), f"no group for parts {sorted(set(PARTS) - set(parts))}")
    return parts


def check_svg(path):
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        raise CheckFailed(f"not well-formed XML: {e}")
    require(root.tag == "{http://www.w3.org/2000/svg}svg", f"root element is {root.tag}, not svg")
    for attribute in ("width", "height"):
        require(root.get(attribute, "").endswith("mm"), f"{attribute} is not in mm: {root.get(attribute)}")
    rsvg = shutil.which("rsvg-convert")
    require(rsvg is not None, "rsvg-convert is not installed (apt-get install librsvg2-bin)")
    with tempfile.TemporaryDirectory() as tmp:
        png = os.path.join(tmp, "render.png")
        run = subprocess.run([rsvg, "--dpi-x", "96", "--dpi-y", "96", "-o", png, path],
                             capture_output=True, text=True)
        require(run.returncode == 0, f"rsvg-convert exits {run.returncode}: {run.stderr.strip()}")
        require(os.path.exists(png) and os.path.getsize(png) > 0, "rsvg-convert wrote no PNG")
        with open(png, "rb") as f:
            require(f.read(8) == b"\x89PNG\r\n\x1a\n", "rsvg-convert output is not a PNG")
        size = os.path.getsize(png)
        kept = ""
        if RENDER:
            kept = f", kept as {os.path.join(RENDER, os.path.basename(path) + '.png')}"
            shutil.copyfile(png, os.path.join(RENDER, os.path.basename(path) + ".png"))
    paths = sum(1 for e in root.iter(SVG + "path"))
    circles = sum(1 for e in root.iter(SVG + "circle"))
    views = [g.get("id") for g in root.iter(SVG + "g") if (g.get("id") or "").startswith("view-") and g.get("class") == "view"]
    if views:
        for g in root.iter(SVG + "g"):
            if g.get("class") == "view":
                lines = [e for e in g.iter() if e.tag in (SVG + "path", SVG + "circle")]
                require(lines, f"view group {g.get('id')} is empty")
        return (f"{root.get('width')} x {root.get('height')}, sheet of {', '.join(views)}, {paths} paths, "
                f"{circles} circles, rendered ({size} bytes PNG){kept}")
    parts = check_svg_parts(root)
    summary = ", ".join(f"{name} {v}+{h}" for name, (v, h) in parts.items())
    return (f"{root.get('width')} x {root.get('height')}, {paths} paths, {circles} circles, parts (visible+hidden "
            f"paths): {summary or 'none'}, rendered ({size} bytes PNG){kept}")


ISO_A = {"A0": (1189, 841), "A1": (841, 594), "A2": (594, 420), "A3": (420, 297), "A4": (297, 210)}


def check_pdf(path):
    info = shutil.which("pdfinfo")
    render = shutil.which("pdftoppm")
    require(info is not None and render is not None, "pdfinfo or pdftoppm is missing (apt-get install poppler-utils)")
    run = subprocess.run([info, path], capture_output=True, text=True)
    require(run.returncode == 0, f"pdfinfo exits {run.returncode}: {run.stderr.strip()}")
    fields = dict(line.split(":", 1) for line in run.stdout.splitlines() if ":" in line)
    require(fields.get("Pages", "").strip() == "1", f"{fields.get('Pages', '?').strip()} pages, not 1")
    size = fields.get("Page size", "").split()
    require(len(size) >= 3, f"no page size: {fields.get('Page size')}")
    w_mm, h_mm = float(size[0]) * 25.4 / 72, float(size[2]) * 25.4 / 72
    sheet = [name for name, (w, h) in ISO_A.items() if abs(w - w_mm) < 0.5 and abs(h - h_mm) < 0.5]
    require(sheet, f"page {w_mm:.1f} x {h_mm:.1f} mm is not a landscape ISO A sheet")
    with tempfile.TemporaryDirectory() as tmp:
        stem = os.path.join(RENDER or tmp, os.path.basename(path))
        run = subprocess.run([render, "-r", "50", "-png", "-singlefile", path, stem], capture_output=True, text=True)
        require(run.returncode == 0, f"pdftoppm exits {run.returncode}: {run.stderr.strip()}")
        png = stem + ".png"
        require(os.path.exists(png) and os.path.getsize(png) > 0, "pdftoppm wrote no PNG")
        with open(png, "rb") as f:
            data = f.read()
        require(data[:8] == b"\x89PNG\r\n\x1a\n", "pdftoppm output is not a PNG")
    return f"{sheet[0]} ({w_mm:.1f} x {h_mm:.1f} mm), 1 page, rendered ({len(data)} bytes PNG)"


def is_number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def is_count(x):
    return isinstance(x, int) and not isinstance(x, bool) and x >= 0


def is_vector(x, n):
    return isinstance(x, list) and len(x) == n and all(is_number(v) for v in x)


KINDS = {"silhouette", "crease", "boundary", "intersection", "group", "smooth"}  # smooth: --smooth-edges thin


def check_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
    except (OSError, ValueError) as e:
        raise CheckFailed(f"not JSON: {e}")
    require(isinstance(doc, dict) and doc.get("format") == "hlr-lines/1", "format is not hlr-lines/1")
    inp = doc.get("input")
    require(isinstance(inp, dict), "input missing")
    require(isinstance(inp.get("files"), list) and all(isinstance(f, str) for f in inp["files"]),
            "input.files is not a list of strings")
    require(is_count(inp.get("faces")) and is_count(inp.get("vertices")), "input.faces/vertices are not counts")
    view = doc.get("view")
    require(isinstance(view, dict), "view missing")
    require(view.get("projection") == "orthographic", "view.projection is not orthographic")
    require("name" not in view or isinstance(view["name"], str), "view.name is not a string")
    require(is_vector(view.get("direction"), 3) and is_vector(view.get("up"), 3), "view.direction/up are not 3-vectors")
    matrix = view.get("world_to_view")
    require(isinstance(matrix, list) and len(matrix) == 4 and all(is_vector(r, 4) for r in matrix),
            "view.world_to_view is not a 4x4 matrix")
    lines = doc.get("lines")
    require(isinstance(lines, list), "lines is not a list")
    for i, line in enumerate(lines):
        where = f"lines[{i}]"
        require(isinstance(line, dict), f"{where} is not an object")
        require(is_vector(line.get("a"), 3) and is_vector(line.get("b"), 3), f"{where}.a/b are not 3-vectors")
        require(isinstance(line.get("visible"), bool), f"{where}.visible is not a boolean")
        require(line.get("kind") in KINDS, f"{where}.kind {line.get('kind')!r} is not a kind")
        require(is_count(line.get("mesh")), f"{where}.mesh is not a count")
        require("edge" in line, f"{where}.edge missing")
        edge = line["edge"]
        if line["kind"] == "intersection":
            require(edge is None, f"{where}.edge of an intersection line is not null")
        else:
            require(isinstance(edge, list) and len(edge) == 2 and all(is_count(v) for v in edge),
                    f"{where}.edge is not two vertex indices")
    stats = doc.get("stats")
    require(isinstance(stats, dict) and is_number(stats.get("seconds")), "stats.seconds missing")
    stages = stats.get("stage_seconds")
    require(isinstance(stages, dict) and all(is_number(stages.get(k)) for k in ("read", "sources", "sort", "lines")),
            "stats.stage_seconds lacks read, sources, sort or lines")
    require(isinstance(doc.get("kernel"), str), "kernel is not a string")
    require(is_number(stats.get("crease_degrees")), "stats.crease_degrees is not a number")
    visible = sum(1 for line in lines if line["visible"])
    return f"{len(lines)} lines ({visible} visible, {len(lines) - visible} hidden)"


def check_dxf_and_render(path):
    return check_dxf(path) + render_dxf(path)


CHECKS = {".dxf": check_dxf_and_render, ".svg": check_svg, ".json": check_json, ".pdf": check_pdf}
PARTS = []  # --parts
RENDER = None  # --render DIR


def main(argv):
    global PARTS, RENDER
    while len(argv) >= 3 and argv[1] in ("--parts", "--render"):
        if argv[1] == "--parts":
            PARTS = [p for p in argv[2].split(",") if p]
        else:
            RENDER = argv[2]
            os.makedirs(RENDER, exist_ok=True)
        argv = argv[:1] + argv[3:]
    if len(argv) < 2:
        print(__doc__.strip().splitlines()[0], file=sys.stderr)
        return 2
    failed = 0
    for path in argv[1:]:
        check = CHECKS.get(os.path.splitext(path)[1].lower())
        try:
            require(check is not None, "unknown file type (expected .dxf, .svg, .pdf or .json)")
            require(os.path.isfile(path), "no such file")
            print(f"ok   {path}: {check(path)}")
        except CheckFailed as e:
            failed += 1
            print(f"FAIL {path}: {e}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

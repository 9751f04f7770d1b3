#!/usr/bin/python3
"""End-to-end test of `hlr sheet` on the bundled flange (fixtures/parts/flange.off):
check_sheet.py HLR FLANGE CHECK_DRAWING_PY WORK_DIR

For third and first angle, the sheet is written as SVG, PDF and DXF and read back:
  SVG  the view groups where ISO 5456-2 puts them (top above the front view in third angle, below
       it in first; the right view to its right in third angle, to its left in first; the iso view
       in a free corner); front and top aligned in x, front and right in y, within 0.01 mm; the
       holes' circles in the top view on the front view's centre lines; the scale in the title
       block one of ISO 5455 and the front view 120 mm of the part wide at it; the projection
       symbol of the method (its circles right of the cone in first angle, left in third).
  PDF  poppler's pdfinfo: one A3 page (1190.55 x 841.89 pt).
  DXF  ezdxf: a block per view, inserted where the SVG puts the view, 6 CIRCLEs (holes, boss and
       bore) and 10 centre LINEs in the top view's block.
Then check_drawing.py --render audits and renders every file (PNG next to them). Errors: a --scale
that does not fit, for hlr sheet and for hlr draw, is exit 2 with one line and no file.
Exits 77 (skipped) when ezdxf or poppler's tools are missing.
"""
import math
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"
FAILURES = []


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print(f"FAIL {message}")
    return condition


def run(args):
    return subprocess.run(args, capture_output=True, text=True)


def numbers_of_path(d):
    """The points of a path's d: M, L and A end points, H and V with the current point."""
    points, x, y = [], 0.0, 0.0
    for op, args in re.findall(r"([MLHVAZ])([^MLHVAZ]*)", d):
        v = [float(t) for t in args.split()]
        if op in "ML":
            x, y = v
        elif op == "H":
            x = v[0]
        elif op == "V":
            y = v[0]
        elif op == "A":
            x, y = v[5], v[6]
        else:
            continue
        points.append((x, y))
    return points


class Box:
    def __init__(self):
        self.x0 = self.y0 = math.inf
        self.x1 = self.y1 = -math.inf

    def add(self, x, y):
        self.x0, self.y0, self.x1, self.y1 = min(self.x0, x), min(self.y0, y), max(self.x1, x), max(self.y1, y)

    def __repr__(self):
        return f"[{self.x0:.2f}, {self.x1:.2f}] x [{self.y0:.2f}, {self.y1:.2f}]"


def groups(root):
    return {g.get("id"): g for g in root.iter(SVG + "g") if g.get("id")}


def view_box(g, name):
    box = Box()
    for cls in ("visible", "hidden"):
        group = g.get(f"view-{name}-{cls}")
        if group is None:
            continue
        for e in group.iter():
            if e.tag == SVG + "path":
                for x, y in numbers_of_path(e.get("d")):
                    box.add(x, y)
            elif e.tag == SVG + "circle":
                cx, cy, r = float(e.get("cx")), float(e.get("cy")), float(e.get("r"))
                box.add(cx - r, cy - r)
                box.add(cx + r, cy + r)
    return box


def is_iso_scale(ratio):
    k = math.floor(math.log10(ratio) + 1e-9)
    return any(abs(ratio - m * 10 ** k) <= 1e-9 * ratio for m in (1, 2, 5))


def check_svg(path, third):
    root = ET.parse(path).getroot()
    g = groups(root)
    for v in ("front", "top", "right", "iso"):
        check(f"view-{v}" in g and g[f"view-{v}"].get("class") == "view", f"{path}: no group view-{v}")
    front, top, right, iso = (view_box(g, v) for v in ("front", "top", "right", "iso"))
    where = f"{path} ({'third' if third else 'first'} angle): front {front}, top {top}, right {right}, iso {iso}"
    if third:
        check(top.y1 < front.y0, f"{where}: the top view is not above the front view")
        check(right.x0 > front.x1, f"{where}: the right view is not right of the front view")
        check(iso.x0 > top.x1 and iso.y1 < right.y0, f"{where}: the iso view is not in the top right corner")
    else:
        check(top.y0 > front.y1, f"{where}: the top view is not below the front view")
        check(right.x1 < front.x0, f"{where}: the right view is not left of the front view")
        check(iso.x1 < top.x0 and iso.y0 > right.y1, f"{where}: the iso view is not in the bottom left corner")
    for a, b, what in ((front.x0, top.x0, "left"), (front.x1, top.x1, "right")):
        check(abs(a - b) <= 0.01, f"{where}: front and top {what} edges differ by {abs(a - b):.4f} mm")
    for a, b, what in ((front.y0, right.y0, "top"), (front.y1, right.y1, "bottom")):
        check(abs(a - b) <= 0.01, f"{where}: front and right {what} edges differ by {abs(a - b):.4f} mm")
    # Model points: the axes of the holes and the bore, seen as circles in the top view, are the
    # front view's vertical centre lines.
    axes_top = sorted({round(float(c.get("cx")), 3) for c in g["view-top-visible"].iter(SVG + "circle")})
    axes_front = []
    for p in g["view-front-center"].iter(SVG + "path"):
        (x0, y0), (x1, y1) = numbers_of_path(p.get("d"))
        if abs(x0 - x1) < 1e-9:
            axes_front.append(x0)
    check(len(axes_top) == 3 and len(axes_front) == 3, f"{where}: axes in top {axes_top}, front {axes_front}")
    for x in axes_top:
        check(any(abs(x - f) <= 0.01 for f in axes_front), f"{where}: no centre line in the front view at x = {x}")
    texts = [t.text or "" for t in g["title-text"].iter(SVG + "text")]
    scale_text = texts[texts.index("Scale") + 1] if "Scale" in texts else ""
    m = re.fullmatch(r"(\d+(?:\.\d+)?):(\d+(?:\.\d+)?)", scale_text)
    if check(m is not None, f"{where}: title block scale {scale_text!r}"):
        ratio = float(m.group(1)) / float(m.group(2))
        check(is_iso_scale(ratio), f"{where}: scale {scale_text} is not of ISO 5455")
        check(abs((front.x1 - front.x0) - 120 * ratio) <= 0.01, f"{where}: front view {front.x1 - front.x0} mm wide at {scale_text}")
    symbol = g.get("projection-symbol")
    if check(symbol is not None, f"{where}: no projection symbol"):
        check(symbol.get("class") == ("third-angle" if third else "first-angle"), f"{where}: symbol class {symbol.get('class')}")
        circles = [float(c.get("cx")) for c in symbol.iter(SVG + "circle")]
        cone = [x for p in symbol.findall(SVG + "path") for x, _ in numbers_of_path(p.get("d"))]
        check(len(circles) == 2 and cone, f"{where}: symbol has {len(circles)} circles")
        if circles and cone:
            check(circles[0] < min(cone) if third else circles[0] > max(cone), f"{where}: the symbol's circles are on the wrong side")
    return front


def check_pdf(path):
    r = run(["pdfinfo", path])
    check(r.returncode == 0, f"{path}: pdfinfo exits {r.returncode}")
    size = re.search(r"Page size:\s+([\d.]+) x ([\d.]+) pts", r.stdout)
    check(size and abs(float(size.group(1)) - 1190.55) < 0.01 and abs(float(size.group(2)) - 841.89) < 0.01,
          f"{path}: page size {size.group(0) if size else '?'} is not A3 landscape")
    check(re.search(r"Pages:\s+1\b", r.stdout), f"{path}: not one page")


def check_dxf(path, svg_front):
    import ezdxf
    doc = ezdxf.readfile(path)
    blocks = sorted(b.name for b in doc.blocks if b.name.startswith("VIEW_"))
    check(blocks == ["VIEW_FRONT", "VIEW_ISO", "VIEW_RIGHT", "VIEW_TOP"], f"{path}: blocks {blocks}")
    top = doc.blocks.get("VIEW_TOP")
    check(len(top.query("CIRCLE")) == 6, f"{path}: {len(top.query('CIRCLE'))} circles in VIEW_TOP, not 6")
    check(len(top.query('LINE[layer=="CENTER"]')) == 10, f"{path}: {len(top.query('LINE'))} centre lines in VIEW_TOP")
    inserts = {i.dxf.name: i for i in doc.modelspace().query("INSERT")}
    front = inserts.get("VIEW_FRONT")
    if check(front is not None, f"{path}: VIEW_FRONT not inserted"):
        # The plate's left bottom edge (x = 0, z = 0) is the view's origin: the insert point.
        x, y = front.dxf.insert[0], front.dxf.insert[1]
        check(abs(x - svg_front.x0) <= 0.01 and abs(y - (297 - svg_front.y1)) <= 0.01,
              f"{path}: VIEW_FRONT inserted at ({x:.3f}, {y:.3f}), the SVG has it at ({svg_front.x0:.3f}, {297 - svg_front.y1:.3f})")


def expect_usage_error(args, prefix, out_dir):
    before = sorted(os.listdir(out_dir))
    r = run(args)
    check(r.returncode == 2, f"{' '.join(args[1:3])}: exit {r.returncode}, not 2 ({r.stderr.strip()})")
    check(r.stderr.count("\n") == 1 and r.stderr.startswith(prefix), f"stderr {r.stderr!r}, expected one line {prefix!r}...")
    check(sorted(os.listdir(out_dir)) == before, "a file was left behind")


def main(argv):
    if len(argv) != 5:
        print(__doc__.strip().splitlines()[0], file=sys.stderr)
        return 2
    hlr, flange, checker, work = argv[1:]
    try:
        import ezdxf  # noqa: F401
    except ImportError:
        print("skipped: /usr/bin/python3 has no ezdxf (apt-get install python3-ezdxf)")
        return 77
    for tool in ("pdfinfo", "pdftoppm", "rsvg-convert"):
        if shutil.which(tool) is None:
            print(f"skipped: {tool} is missing (apt-get install poppler-utils librsvg2-bin)")
            return 77
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    files = []
    for method in ("third", "first"):
        stem = os.path.join(work, f"flange_{method}")
        r = run([hlr, "sheet", flange, "--views", "front,top,right,iso", "--projection", method, "--sheet", "A3",
                 "--title", "Flange", "--number", "HLR-015", "--author", "hlr", "--date", "2025-01-01", "--revision", "A",
                 "-o", stem + ".svg", "-o", stem + ".pdf", "-o", stem + ".dxf"])
        if not check(r.returncode == 0, f"hlr sheet --projection {method}: exit {r.returncode}: {r.stderr.strip()}"):
            continue
        front = check_svg(stem + ".svg", method == "third")
        check_pdf(stem + ".pdf")
        check_dxf(stem + ".dxf", front)
        files += [stem + ext for ext in (".svg", ".pdf", ".dxf")]
        print(f"ok   {method} angle: {r.stdout.splitlines()[0]}")
    r = run([hlr, "draw", flange, "--view", "top", "-o", os.path.join(work, "flange_top.pdf")])
    check(r.returncode == 0 and "6 circles" in r.stdout, f"hlr draw to PDF: {r.stdout} {r.stderr}")
    files.append(os.path.join(work, "flange_top.pdf"))
    errors = os.path.join(work, "errors")
    os.makedirs(errors)
    expect_usage_error([hlr, "sheet", flange, "--sheet", "A4", "--scale", "10:1", "-o", os.path.join(errors, "x.svg")],
                       "hlr: --scale 10:1: the views need ", errors)
    expect_usage_error([hlr, "draw", flange, "--view", "top", "--scale", "10:1", "-o", os.path.join(errors, "x.pdf")],
                       "hlr: --scale 10:1: the drawing needs ", errors)
    r = run(["/usr/bin/python3", checker, "--render", os.path.join(work, "png")] + files)
    print(r.stdout, end="")
    check(r.returncode == 0, "check_drawing.py failed on the sheets")
    print(f"{'FAIL' if FAILURES else 'ok  '} hlr sheet: {len(FAILURES)} problems")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

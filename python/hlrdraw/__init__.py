"""hlrdraw: hlr's exact hidden-line drawings, surfaces and polygon clipping on numpy arrays.

The same jobs as the hlr program, through the same library calls, with the same defaults and the
same one-line messages; a file written here is the file `hlr draw` writes for the same input.

    import numpy as np, hlrdraw
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                         [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=float)
    faces = np.array([[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4],
                      [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]])
    drawing = hlrdraw.draw(vertices, faces, view="iso")
    drawing.a, drawing.b, drawing.visible, drawing.kind   # one row per piece of line
    hlrdraw.write_svg(drawing, "cube.svg")                 # an A4 sheet, as `hlr draw -o cube.svg`

Meshes: wherever a mesh is taken, it may be a pair (vertices, faces) or a triple (vertices, faces,
name), a Mesh (from read_mesh or mesh), or a file path (OFF, OBJ, STL, PLY); a list of them is one
scene of several parts. vertices is an (n, 3) array of coordinates; faces an (m, k) integer array or
a sequence of polygons of any size (vertex indices from 0). Arrays are checked and prepared exactly
as a file is (welding equal vertices, fanning non-planar faces, rejecting NaN, huge coordinates,
indices out of range and faces that cross themselves). `name` stands for the file in messages and
names the part in SVG groups and DXF layers (default "mesh", or "mesh0", "mesh1", ... for several).

Views: view="front" | "back" | "top" | "bottom" | "left" | "right" | "iso" (default), or
direction=(x, y, z) with up=(x, y, z) (default +Z, or +Y when looking along Z), as hlr's --view,
--dir and --up. kernel="exact" (default) | "epick" | "double".

Errors: input that cannot be used raises hlrdraw.Error (a ValueError) with the message the hlr
program prints, without its "hlr: " ("part.off: face 3: vertex index 9 is out of range (8
vertices)"). The solving itself runs without the GIL; Ctrl-C stops it between its stages.

Speed: the exact kernel allocates a node per lazy number. The hlr program uses tcmalloc for that;
a Python process has the C library's malloc, with which a drawing takes about 30% longer (88k
faces: 1.8 s against 1.4 s). LD_PRELOAD=libtcmalloc_minimal.so.4 python3 ... gives the program's
speed.
"""

import json as _json
import math as _math
import numbers as _numbers
import os as _os
import tempfile as _tempfile

import numpy as _np

from . import _hlrdraw
from ._hlrdraw import Error, Mesh

Error.__module__ = "hlrdraw"
Mesh.__module__ = "hlrdraw"

__all__ = ["Error", "Mesh", "Drawing", "read_mesh", "mesh", "draw", "draw_file", "surfaces", "shadows", "clip",
           "write_svg", "write_pdf", "write_dxf", "write_json", "KIND_NAMES"]

# The hlr-lines/1 names of the kinds of line, in the order of their codes.
KIND_NAMES = tuple(_hlrdraw.KIND_NAMES)


def read_mesh(path):
    """The mesh in a file, as hlr reads it: a Mesh (vertices, faces = read_mesh(path) unpacks it).

    Its faces are the prepared ones (welded, fanned, split at repeated vertices), face_index says
    which face of the file each came from; drawing it draws exactly what drawing the file draws.
    """
    return _hlrdraw.read_mesh(_os.fspath(path))


def mesh(vertices, faces, name="mesh"):
    """A Mesh from arrays, checked and prepared as a file is (raises Error naming `name`)."""
    return _hlrdraw.make_mesh(str(name), vertices, faces)


def _meshes(vertices, faces):
    """The scene's meshes from draw's first two arguments."""
    if faces is not None:
        return [mesh(vertices, faces)]
    items = vertices
    if isinstance(items, (Mesh, str, _os.PathLike)) or (isinstance(items, tuple) and len(items) in (2, 3)
                                                       and not isinstance(items[0], (Mesh, str, _os.PathLike, tuple))):
        items = [items]
    items = list(items)
    out = []
    for i, item in enumerate(items):
        if isinstance(item, Mesh):
            out.append(item)
        elif isinstance(item, (str, _os.PathLike)):
            out.append(read_mesh(item))
        elif isinstance(item, (tuple, list)) and len(item) in (2, 3):
            name = item[2] if len(item) == 3 else ("mesh" if len(items) == 1 else f"mesh{i}")
            out.append(mesh(item[0], item[1], name))
        else:
            raise Error(f"meshes: item {i} is not a mesh (give (vertices, faces), (vertices, faces, name), "
                        "a Mesh or a file path)")
    if not out:
        raise Error("meshes: no mesh given")
    return out


def _vector(value):
    """A direction or up vector as a list of floats (the library checks that there are 3)."""
    if value is None:
        return None
    return [float(c) for c in _np.asarray(value, dtype=float).reshape(-1)]


def _lights(value):
    """sun= or point_light=: None, one (x, y, z) or a sequence of them, as lists of floats."""
    if value is None:
        return []
    array = _np.asarray(value, dtype=float)
    if array.ndim == 1:
        array = array.reshape(1, -1)
    if array.ndim != 2:
        raise Error("lights: give (x, y, z) or a list of them")
    return [[float(c) for c in row] for row in array]


class Drawing:
    """A line drawing of a view: every piece of every feature line, visible or hidden.

    Arrays, one row per piece (the "lines" of hlr-lines/1, in the same order):
      a, b     (n, 3) float: the piece's ends in view coordinates, model units (x right, y up, z
               towards the viewer), rounded once from the exact result
      visible  (n,) bool
      kind     (n,) str: silhouette, crease, boundary, group or intersection (kind_code: the codes,
               indices into KIND_NAMES)
      mesh     (n,) int: the part it belongs to (index of the mesh in the scene)
      edge     (n, 2) int: the mesh edge (its two vertex indices), -1, -1 for intersection lines
      line     (n,) int: the feature line the piece is part of
    drawing["a"] and drawing.arrays() give them as a dict. view, input and kernel are the JSON's
    "view" and "input" objects and its kernel; json() is the whole hlr-lines/1 document.
    """

    _ARRAYS = ("a", "b", "visible", "kind", "mesh", "edge", "line")

    def __init__(self, native):
        self._native = native
        arrays = native.arrays()
        self.a = arrays["a"]
        self.b = arrays["b"]
        self.visible = arrays["visible"]
        self.kind_code = arrays["kind"]
        self.kind = _np.array(KIND_NAMES)[self.kind_code] if len(self.kind_code) else _np.array([], dtype="<U12")
        self.mesh = arrays["mesh"]
        self.edge = arrays["edge"]
        self.line = arrays["line"]
        self.view = native.view
        self.input = native.input
        self.kernel = native.kernel

    def __len__(self):
        return len(self.a)

    def __getitem__(self, key):
        if key not in self._ARRAYS:
            raise KeyError(key)
        return getattr(self, key)

    def keys(self):
        return self._ARRAYS

    def arrays(self):
        return {key: getattr(self, key) for key in self._ARRAYS}

    def json(self):
        """The hlr-lines/1 document as a dict (what `hlr draw -o OUT.json` writes)."""
        return _json.loads(self.json_text())

    def json_text(self):
        return self._native.json()

    def svg(self, **style):
        """The SVG sheet as text; style: see write_svg."""
        return self._sheet("svg", style).decode("utf-8")

    def pdf(self, **style):
        return self._sheet("pdf", style)

    def dxf(self, **style):
        return self._sheet("dxf", style).decode("utf-8")

    def _sheet(self, fmt, style):
        options = dict(_STYLE_DEFAULTS)
        for key, value in style.items():
            if key not in options:
                raise TypeError(f"unknown sheet option {key!r} (options: {', '.join(options)})")
            options[key] = value
        return self._native.sheet(fmt, str(options["sheet"]), options["scale"], str(options["units"]),
                                  float(options["line_group"]), bool(options["hidden"]),
                                  bool(options["centre_lines"]), float(options["merge_distance"]),
                                  float(options["contact_angle"]))

    def __repr__(self):
        return (f"<hlrdraw.Drawing: {len(self)} pieces, {int(self.visible.sum())} visible, "
                f"view {self.view.get('name', 'custom')}, kernel {self.kernel}>")


# The sheet options of `hlr draw` and their defaults (README, `hlr draw`): --sheet, --scale (None:
# the largest ISO 5455 scale that fits), --units, --line-group, --hidden dashed|none (True|False),
# --no-centre-lines (centre_lines=False), --merge-distance, --contact-angle.
_STYLE_DEFAULTS = {"sheet": "A4", "scale": None, "units": "mm", "line_group": 0.5, "hidden": True,
                   "centre_lines": True, "merge_distance": 0.01, "contact_angle": 10.0}


def draw(vertices, faces=None, *, view="iso", direction=None, up=None, crease=30, intersections=True,
         sun=None, point_light=None, kernel="exact", threads=0, progress=None):
    """The line drawing of a scene in a view, as `hlr draw` makes it: a Drawing.

    draw(vertices, faces, ...) draws one mesh; draw(meshes, ...) a scene of several (see the
    module's help for what a mesh may be). crease: an edge is a crease line when its faces meet at
    more than this many degrees (--crease); intersections=False leaves out the lines where faces
    penetrate (--no-intersections). sun=(dx, dy, dz) (the direction its rays travel) and
    point_light=(x, y, z), each one light or a list of them, draw their shadows as surface detail
    (--sun, --point-light; the exact kernel only). threads: at most this many threads (--threads; 0: every core;
    the limit is the process's while the job runs). progress: a callable given each stage's
    description (the lines `hlr draw` prints for large scenes).
    """
    native = _hlrdraw.draw(_meshes(vertices, faces), str(view), _vector(direction), _vector(up), str(kernel),
                           float(crease), bool(intersections), _lights(sun), _lights(point_light), int(threads),
                           progress)
    return Drawing(native)


def draw_file(paths, **options):
    """draw() of the mesh files `paths` (one path or a list), read as `hlr draw PATH...` reads them."""
    if isinstance(paths, (str, _os.PathLike)):
        paths = [paths]
    return draw([_os.fspath(p) for p in paths], **options)


def surfaces(vertices, faces=None, *, view="iso", direction=None, up=None, kernel="exact", exact=False,
             keep_back_faces=False, consolidation=True, threads=0, progress=None):
    """The hidden-surface solution of a view: the hlr-surfaces/1 document (`hlr surfaces -o OUT.json`)
    as a dict. exact=True adds the exact "p/q" values (--exact); keep_back_faces and
    consolidation=False are --keep-back-faces and --no-consolidation; threads and progress as in
    draw."""
    text = _hlrdraw.surfaces(_meshes(vertices, faces), str(view), _vector(direction), _vector(up), str(kernel),
                             bool(exact), bool(keep_back_faces), bool(consolidation), int(threads), progress)
    return _json.loads(text)


def shadows(vertices, faces=None, *, sun=None, point_light=None, union=False, threads=0, progress=None):
    """Which part of every face each light reaches, exactly, as `hlr shadows -o OUT.json` finds it:
    the hlr-shadows/1 document as a dict (docs/FORMATS.md). sun=(dx, dy, dz) is a directional light
    whose rays travel along that direction (--sun), point_light=(x, y, z) a point light (outside the
    scene or among it, not on a face nor inside a closed solid; --point-light); each may be one light or a list of them, suns first in "lights". At
    least one light is needed. union=True adds every face's shadow over all lights (--union);
    threads and progress as in draw."""
    text = _hlrdraw.shadows(_meshes(vertices, faces), _lights(sun), _lights(point_light), bool(union), int(threads),
                            progress)
    return _json.loads(text)


# ---- clip -----------------------------------------------------------------------------------------

def _number_text(x):
    """A JSON number that reads back as exactly this double; non-finite values as a number that
    overflows, which hlr's reader rejects as "not a finite number", as it does in a file."""
    x = float(x)
    if _math.isfinite(x):
        return repr(x)
    return "-1e999" if x < 0 else "1e999"


def _json_text(value):
    """JSON text of nested dicts, sequences, numpy arrays and numbers, doubles spelled exactly."""
    if isinstance(value, dict):
        return "{" + ", ".join(_json.dumps(str(k)) + ": " + _json_text(v) for k, v in value.items()) + "}"
    if isinstance(value, _np.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_json_text(v) for v in value) + "]"
    if isinstance(value, (bool, _np.bool_)) or value is None or isinstance(value, str):
        return _json.dumps(value if not isinstance(value, _np.bool_) else bool(value))
    if isinstance(value, _numbers.Integral):
        return str(int(value))
    if isinstance(value, _numbers.Real):
        return _number_text(value)
    return _json.dumps(str(value))  # the reader names what is not a number


def _polygons_document(polygons):
    """hlr-polygons/1 text of a clip argument: an hlr-polygons/1 dict, one polygon, or a list of
    polygons, a polygon being an (n, 2) array-like (its outer contour) or a dict {"outer": ...,
    "holes": [...]}."""
    if isinstance(polygons, dict) and "polygons" in polygons:
        document = dict(polygons)
        document.setdefault("format", "hlr-polygons/1")
        return _json_text(document)
    if isinstance(polygons, dict) or (isinstance(polygons, _np.ndarray) and polygons.ndim == 2):
        polygons = [polygons]
    items = []
    for polygon in polygons:
        if isinstance(polygon, dict):
            items.append(polygon)
        else:
            items.append({"outer": polygon})
    return _json_text({"format": "hlr-polygons/1", "polygons": items})


def clip(subject, clip, *, kernel="exact", exact=False):
    """Each subject polygon clipped by the union of the clip polygons, as `hlr clip` does: the
    hlr-clip/1 document as a dict ("inside": subject ∩ clip, "outside": subject − clip, every edge
    tagged with the input edge it lies on). exact=True adds every vertex and area as exact "p/q"
    strings (--exact; fractions.Fraction reads them). Polygons: see _polygons_document; messages
    name them "subject" and "clip"."""
    text = _hlrdraw.clip(_polygons_document(subject), _polygons_document(clip), "subject", "clip", str(kernel),
                         bool(exact))
    return _json.loads(text)


# ---- files ----------------------------------------------------------------------------------------

def _write_atomically(path, data):
    """Writes `data` to `path` as hlr writes its outputs: into a temporary file beside it, renamed
    over it once written and flushed, so that no reader sees a partial file and a failure leaves
    none. Raises Error("PATH: cannot write (...)")."""
    path = _os.fspath(path)
    if isinstance(data, str):
        data = data.encode("utf-8")
    folder, base = _os.path.split(path)
    if not base or _os.path.isdir(path):
        raise Error(f"{path}: cannot write (Is a directory)")
    try:
        fd, temporary = _tempfile.mkstemp(prefix="." + base + ".tmp-", dir=folder or ".")
    except OSError as e:
        raise Error(f"{path}: cannot write ({e.strerror})") from None
    try:
        with _os.fdopen(fd, "wb") as f:
            mask = _os.umask(0)
            _os.umask(mask)
            _os.fchmod(f.fileno(), 0o666 & ~mask)  # mkstemp makes it 0600: as a plain create would
            f.write(data)
            f.flush()
            _os.fsync(f.fileno())
        _os.replace(temporary, path)
    except BaseException as e:
        try:
            _os.unlink(temporary)
        except OSError:
            pass
        if isinstance(e, OSError):
            raise Error(f"{path}: cannot write ({e.strerror})") from None
        raise


def _check_drawing(drawing):
    if not isinstance(drawing, Drawing):
        raise TypeError(f"expected an hlrdraw.Drawing (from draw), not {type(drawing).__name__}")


def write_svg(drawing, path, **style):
    """Writes the drawing's SVG sheet, as `hlr draw -o PATH.svg` does. Style (the defaults are
    hlr draw's): sheet="A4" (A0..A4), scale=None (the largest ISO 5455 scale that fits; or "1:2",
    "5:1" or a factor), units="mm" (cm, m, in), line_group=0.5 (0.35, 0.7), hidden=True (False:
    no hidden lines), centre_lines=True, merge_distance=0.01 (mm on the sheet),
    contact_angle=10 (degrees)."""
    _check_drawing(drawing)
    _write_atomically(path, drawing._sheet("svg", style))


def write_pdf(drawing, path, **style):
    """Writes the drawing's PDF sheet (`hlr draw -o PATH.pdf`); style as write_svg."""
    _check_drawing(drawing)
    _write_atomically(path, drawing._sheet("pdf", style))


def write_dxf(drawing, path, **style):
    """Writes the drawing as DXF R2000 in model units (`hlr draw -o PATH.dxf`); style as write_svg."""
    _check_drawing(drawing)
    _write_atomically(path, drawing._sheet("dxf", style))


def write_json(drawing, path):
    """Writes the drawing's hlr-lines/1 document (`hlr draw -o PATH.json`)."""
    _check_drawing(drawing)
    _write_atomically(path, drawing.json_text())

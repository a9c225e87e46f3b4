"""What a Python user expects of any package: real signatures (inspect.signature, help()) that
agree with docs/python.md, type stubs that parse and agree with the functions, the package's
metadata, and triangles with their points for shapely input, checked in exact arithmetic."""
import ast
import email
import importlib
import importlib.metadata
import inspect
import pathlib
import pydoc
import re
import subprocess
import sys
import tomllib
from fractions import Fraction

import numpy as np
import pytest

import pear
from polygons import SQUARE_WITH_HOLE, child_environment

REPO = pathlib.Path(__file__).resolve().parents[2]
PACKAGE = pathlib.Path(pear.__file__).parent


def public_functions():
    """(qualified name, function) for every function of pear.__all__ and pear.geopandas."""
    functions = [(f"pear.{name}", getattr(pear, name)) for name in pear.__all__
                 if callable(getattr(pear, name)) and not inspect.isclass(getattr(pear, name))]
    try:
        geopandas = importlib.import_module("pear.geopandas")
    except ImportError:  # no geopandas here: its functions are not checked
        return functions
    return functions + [(f"pear.geopandas.{name}", getattr(geopandas, name))
                        for name in ("triangulate", "triangle_polygons")]


def parameters(signature_text):
    """[(name, kind, default source or None)] of a signature written as Python: '(a, b=1, *, c)'."""
    args = ast.parse(f"def f{signature_text}: pass").body[0].args
    out = [(a.arg, "positional", None) for a in args.posonlyargs + args.args]
    defaults = [None] * (len(out) - len(args.defaults)) + [ast.unparse(d) for d in args.defaults]
    out = [(name, kind, default) for (name, kind, _), default in zip(out, defaults)]
    if args.vararg:
        out.append((args.vararg.arg, "*", None))
    out += [(a.arg, "keyword", None if d is None else ast.unparse(d))
            for a, d in zip(args.kwonlyargs, args.kw_defaults)]
    if args.kwarg:
        out.append((args.kwarg.arg, "**", None))
    return out


def documented_signatures(name):
    """Every '(...)' after `name` in docs/python.md that parses as a parameter list."""
    text = (REPO / "docs" / "python.md").read_text()
    found = []
    for match in re.finditer(rf"\b{re.escape(name)}\(", text):
        depth, end = 0, match.end() - 1
        for end in range(match.end() - 1, len(text)):
            depth += {"(": 1, ")": -1}.get(text[end], 0)
            if depth == 0:
                break
        candidate = " ".join(text[match.end() - 1:end + 1].split())
        try:
            found.append(parameters(candidate))
        except SyntaxError:
            pass  # a call in prose, not a parameter list
    return found


@pytest.mark.parametrize("qualified, function", public_functions(),
                         ids=[name for name, _ in public_functions()])
def test_signature_is_the_documented_one(qualified, function):
    signature = inspect.signature(function)  # raised ValueError for pybind11's functions
    assert all(p.annotation is inspect.Parameter.empty or "handle" not in str(p.annotation)
               for p in signature.parameters.values())
    runtime = parameters(str(signature.replace(return_annotation=inspect.Signature.empty)))
    documented = documented_signatures(qualified.rsplit(".", 1)[1])
    assert runtime in documented, (
        f"{qualified}{signature} is not written in docs/python.md; it has {documented}")


def test_help_shows_no_pybind11_handles():
    modules = [pear, pear._pear]
    try:
        modules.append(importlib.import_module("pear.geopandas"))
    except ImportError:
        pass  # no geopandas here
    for module in modules:
        text = pydoc.render_doc(module, renderer=pydoc.plaintext)
        assert "handle" not in text, [line for line in text.splitlines() if "handle" in line]
    text = pydoc.render_doc(pear, renderer=pydoc.plaintext)
    for name in ("validate", "quality", "orient2d", "incircle", "triangulate_points"):
        assert f"{name}{inspect.signature(getattr(pear, name))}" in text


def stub(name):
    path = PACKAGE / name
    assert path.is_file(), f"{path} is missing"
    return ast.parse(path.read_text(), filename=str(path))


def stub_functions(tree):
    """name -> the parameters of each function a stub defines (the last overload's)."""
    return {node.name: parameters(f"({ast.unparse(node.args)})") for node in tree.body
            if isinstance(node, ast.FunctionDef)}


def stub_names(tree):
    names = set(stub_functions(tree))
    for node in tree.body:
        if isinstance(node, (ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.ImportFrom):
            names.update(alias.asname or alias.name for alias in node.names)
        elif isinstance(node, (ast.AnnAssign, ast.Assign)):
            targets = [node.target] if isinstance(node, ast.AnnAssign) else node.targets
            names.update(t.id for t in targets if isinstance(t, ast.Name))
    return names


def without_defaults(params):
    return [(name, kind) for name, kind, _ in params]


def test_stubs_parse_and_name_every_public_function():
    assert (PACKAGE / "py.typed").is_file()
    package, module, geopandas = stub("__init__.pyi"), stub("_pear.pyi"), stub("geopandas.pyi")
    assert set(pear.__all__) <= stub_names(package)
    public_module = {n for n in dir(pear._pear) if not n.startswith("_")}
    assert public_module <= stub_names(module), public_module - stub_names(module)
    functions = {**stub_functions(module), **stub_functions(package),
                 **{f"geopandas.{k}": v for k, v in stub_functions(geopandas).items()}}
    for qualified, function in public_functions():
        key = qualified.removeprefix("pear.")
        assert key in functions, f"no stub for {qualified}"
        runtime = parameters(str(inspect.signature(function).replace(
            return_annotation=inspect.Signature.empty)))
        assert without_defaults(functions[key]) == without_defaults(runtime), qualified


def test_stubs_agree_with_the_module_in_mypy_stubtest(tmp_path):
    """mypy's stubtest: every name, parameter and default of the stubs as the module has it."""
    pytest.importorskip("mypy", reason="mypy (python3-mypy) checks the stubs against pear")
    # mypy finds an installed pear by its py.typed, one in a build tree through MYPYPATH.
    installed = PACKAGE.parent.name in ("site-packages", "dist-packages")
    env = child_environment(**({} if installed else {"MYPYPATH": str(PACKAGE.parent)}))
    run = subprocess.run([sys.executable, "-m", "mypy.stubtest", "pear", "--ignore-missing-stub",
                          "--mypy-config-file", str(REPO / "python" / "mypy.ini"),
                          "--allowlist", str(REPO / "python" / "stubtest-allowlist.txt")],
                         capture_output=True, text=True, timeout=300, cwd=tmp_path, env=env)
    assert run.returncode == 0, run.stdout + run.stderr


def pyproject_metadata():
    """The core metadata meson-python writes into the wheel, from pyproject.toml."""
    pyproject_metadata = pytest.importorskip("pyproject_metadata")
    config = tomllib.loads((REPO / "pyproject.toml").read_text())
    message = pyproject_metadata.StandardMetadata.from_pyproject(config, REPO).as_rfc822()
    return email.message_from_bytes(bytes(message))


def check_metadata(metadata):
    spdx = metadata.get("License-Expression") or metadata.get("License")
    assert spdx == "MIT", f"License is {spdx[:60]!r}..., not an SPDX expression"
    classifiers = metadata.get_all("Classifier") or []
    assert "License :: OSI Approved :: MIT License" in classifiers
    assert any(c.startswith("Programming Language :: Python :: 3") for c in classifiers)
    assert "Typing :: Typed" in classifiers
    urls = metadata.get_all("Project-URL") or []
    assert all(re.fullmatch(r"[^,]+, https://\S+", url) for url in urls), urls


def test_wheel_metadata_from_pyproject():
    check_metadata(pyproject_metadata())


def test_installed_metadata():
    try:
        distribution = importlib.metadata.distribution("pear")
    except importlib.metadata.PackageNotFoundError:
        pytest.skip("pear is imported from a build tree, not installed (pip install .)")
    if pathlib.Path(distribution.locate_file("pear")) != PACKAGE:
        pytest.skip(f"the pear installed at {distribution.locate_file('')} is not the one imported")
    check_metadata(distribution.metadata)
    files = {str(f) for f in distribution.files or []}
    assert {"pear/py.typed", "pear/__init__.pyi", "pear/_pear.pyi", "pear/LICENSE"} <= files


def twice_area(points):
    """Twice the signed area of a ring, exactly (Fractions of the doubles)."""
    p = [(Fraction(x), Fraction(y)) for x, y in points]
    return sum(p[i - 1][0] * p[i][1] - p[i][0] * p[i - 1][1] for i in range(len(p)))


def shapely_area(polygon):
    """Twice a shapely Polygon's area, exactly, from its own rings."""
    return abs(twice_area(polygon.exterior.coords)) - sum(
        abs(twice_area(ring.coords)) for ring in polygon.interiors)


def holed_polygon():
    """A polygon with two holes and coordinates that are not small dyadic numbers."""
    from shapely.geometry import Polygon
    outer = [(0.1 * np.cos(t) * 7.3, 0.1 * np.sin(t) * 5.9) for t in np.linspace(0, 6.2, 40)]
    holes = [[(-0.3, -0.1), (-0.1, -0.1), (-0.1, 0.1), (-0.3, 0.1)],
             [(0.1, -0.2), (0.3, -0.2), (0.2, 0.2)]]
    return Polygon(outer, holes)


def shapely_coordinates(geometry):
    """A (Multi)Polygon's coordinates in shapely's order, every ring closed, from shapely."""
    rings = [r for part in getattr(geometry, "geoms", [geometry])
             for r in [part.exterior, *part.interiors]]
    return np.vstack([np.asarray(r.coords) for r in rings])


def test_triangulate_points_gives_what_triangulate_indexes():
    pytest.importorskip("shapely")
    from shapely.geometry import MultiPolygon, Polygon
    polygon = holed_polygon()
    multi = MultiPolygon([polygon, Polygon([(5, 5), (6, 5), (5.5, 6.1)])])
    for geometry in (polygon, multi):
        points, triangles = pear.triangulate_points(geometry)
        assert points.dtype == np.float64 and triangles.dtype == np.uint32
        assert np.array_equal(points, shapely_coordinates(geometry))
        assert np.array_equal(triangles, pear.triangulate(geometry))
    points, triangles = pear.triangulate_points(polygon)
    areas = [twice_area(points[t]) for t in triangles.tolist()]
    assert all(a > 0 for a in areas)
    assert sum(areas) == shapely_area(polygon)


def test_triangulate_points_for_arrays_and_statuses():
    points, triangles = pear.triangulate_points(SQUARE_WITH_HOLE.tolist(), [4])
    assert points.dtype == np.float64 and np.array_equal(points, SQUARE_WITH_HOLE)
    assert np.array_equal(triangles, pear.triangulate(SQUARE_WITH_HOLE, [4]))
    bowtie = [[0, 0], [2, 2], [2, 0], [0, 2]]
    with pytest.raises(pear.NotSimpleError):
        pear.triangulate_points(bowtie)
    points, triangles, status = pear.triangulate_points(bowtie, strict=False)
    assert status == pear.Status.not_simple and len(points) == 4
    with pytest.raises(TypeError, match=r"triangulate_points\(\) got an unexpected keyword"):
        pear.triangulate_points(bowtie, stric=False)


def test_shapely_triangles_cover_the_polygon_exactly():
    pytest.importorskip("shapely")
    from shapely.geometry import MultiPolygon, Polygon
    polygon = holed_polygon()
    other = Polygon([(5, 5), (6, 5), (5.5, 6.1)])
    multi = MultiPolygon([polygon, other])
    points, triangles = pear.triangulate_points(multi)
    pieces = pear.shapely_triangles(points, triangles)
    assert len(pieces) == len(triangles) and all(isinstance(p, Polygon) for p in pieces)
    vertices = {tuple(p) for p in points.tolist()}
    for piece, triangle in zip(pieces, triangles.tolist()):
        ring = list(piece.exterior.coords)
        assert len(ring) == 4 and ring[0] == ring[-1] and set(ring) <= vertices
        assert ring[:3] == [tuple(points[i]) for i in triangle]  # in order, counterclockwise
    total = sum(twice_area(piece.exterior.coords[:-1]) for piece in pieces)
    assert total == shapely_area(polygon) + shapely_area(other)
    with pytest.raises(ValueError):
        pear.shapely_triangles(points, [[0, 1, len(points)]])

"""The Python module against the installed-or-built command line: same fragments, cycles and
buffers; misuse raises rastersim.Error with a message. RASTERSIM_CLI names the rastersim
executable, RASTERSIM_DOCS_DIR the documentation folder (docs/ of the checkout, or the installed
share/doc/rastersim: for its examples/worked.*). The same file is installed beside the module's
metadata (share/rastersim/python-tests) and runs there against the installed module."""
import csv
import json
import os
import subprocess

import numpy as np
import pytest

import rastersim

DOCS = os.environ.get("RASTERSIM_DOCS_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "docs"))
CLI = os.environ.get("RASTERSIM_CLI", "rastersim")


def read_tri(path):
    """The .tri lines as lists of three (x, y, z, r, g, b) vertices (docs/formats.md)."""
    triangles = []
    for line in open(path):
        values = [float(v) for v in line.split("#")[0].split("uvw")[0].split()]  # without a texture section
        if not values:
            continue
        colours = {9: [(255, 255, 255)] * 3, 12: [tuple(values[9:12])] * 3,
                   18: [tuple(values[9 + 3 * k:12 + 3 * k]) for k in range(3)]}[len(values)]
        triangles.append([tuple(values[3 * k:3 * k + 3]) + tuple(int(c) for c in colours[k]) for k in range(3)])
    return triangles


def render(tmp_path, tri, profile):
    """The CLI's fragment trace (n, 9) and stats for a .tri file."""
    fragments, stats = tmp_path / "cli.csv", tmp_path / "cli.json"
    subprocess.run([CLI, "render", str(tri), "--profile", str(profile), "--fragments", str(fragments),
                    "--stats", str(stats)], check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.reader(open(fragments)))
    assert rows[0] == list(rastersim.FRAGMENT_COLUMNS)
    return np.array([[int(v) for v in row] for row in rows[1:]], dtype=np.int64).reshape(-1, 9), json.load(open(stats))


@pytest.mark.parametrize("scene", ["worked", "default"])
def test_fragments_cycles_and_buffers_equal_the_cli(tmp_path, scene):
    if scene == "worked":
        tri = os.path.join(DOCS, "examples", "worked.tri")
        profile_path = os.path.join(DOCS, "examples", "worked.json")
    else:
        tri, profile_path = tmp_path / "default.tri", tmp_path / "default.json"
        profile_path.write_text("{}")
        subprocess.run([CLI, "render", "--scene", "default", "--dump-tri", str(tri)], check=True,
                       stdout=subprocess.DEVNULL)
    expected, stats = render(tmp_path, tri, profile_path)
    pipeline = rastersim.Pipeline(open(profile_path).read())
    for vertices in read_tri(tri):
        pipeline.submit_screen(vertices)
    fragments = pipeline.fragments()
    assert fragments.shape == expected.shape and len(expected) > 0
    assert np.array_equal(fragments, expected)
    assert pipeline.frame_cycles() == stats["cycles"]
    # Per triangle, the fragments match the cycle record.
    for t in range(pipeline.triangle_count):
        assert len(pipeline.fragments(t)) == pipeline.triangle(t)["fragments"]
    # The buffers, replayed independently from the CLI's trace.
    p = stats["profile"]
    depth = np.full((p["height"], p["width"]), p["depth_clear"], dtype=np.uint32)
    colour = np.zeros((p["height"], p["width"]), dtype=np.uint32)
    for tri_index, x, y, z, passed, r, g, b, cycle in expected:
        if passed:
            if p["depth_write"]:
                depth[y, x] = z
            colour[y, x] = (r << 16) | (g << 8) | b
    assert np.array_equal(pipeline.depth(), depth)
    assert np.array_equal(pipeline.color(), colour)


def test_setup_record_and_reset():
    pipeline = rastersim.Pipeline('{"width": 64, "height": 48}')
    vertices = [(3.5, 2.25, 0.25, 255, 0, 0), (40.0, 10.5, 0.5, 0, 255, 0), (12.75, 30.0, 0.75, 0, 0, 255)]
    index = pipeline.submit_screen(vertices)
    record = pipeline.setup_record(index)
    # The bounding box from the pixel centres inside the vertices' extent (docs/arithmetic.md).
    assert (record["x0"], record["y0"], record["x1"], record["y1"]) == (3, 2, 39, 29)
    # Edge steps are -dy 2^S and dx 2^S of the (ordered) edges: they sum to zero around the triangle.
    assert sum(record["edge_step_x"]) == 0 and sum(record["edge_step_y"]) == 0
    cycles = pipeline.frame_cycles()
    assert cycles > 0
    pipeline.reset()
    assert pipeline.triangle_count == 0 and pipeline.frame_cycles() == 0
    assert int(pipeline.depth().min()) == (1 << 24) - 1
    pipeline.submit_screen(vertices)
    assert pipeline.frame_cycles() == cycles
    assert json.loads(pipeline.profile)["width"] == 64
    assert rastersim.version().startswith("0.1.0")
    assert rastersim.version().startswith(rastersim.__version__ + " ")


def test_installed_metadata_names_the_version_and_numpy():
    # The dist-info folder beside the module: what pip and importlib.metadata read.
    import importlib.metadata
    assert importlib.metadata.version("rastersim") == rastersim.__version__
    assert importlib.metadata.requires("rastersim") == ["numpy"]


def test_setup_record_left_edge_planes():
    # With the guard bits fixed, the plane registers are z_bits + guard + 1 (depth) and 8 + guard + 1
    # (colour) bits wide (docs/widths.md): the left-edge planes are recomputed here from the record's
    # own fields with Python's exact integers and wrapped to those widths.
    pipeline = rastersim.Pipeline(width=64, height=48, z_bits=24, z_guard_bits=8)
    depth_bits, colour_bits = 24 + 8 + 1, 8 + 8 + 1

    def wrap(value, bits):
        value &= (1 << bits) - 1
        return value - (1 << bits) if value >> (bits - 1) else value

    for vertices in ([(3.5, 2.25, 0.25, 255, 0, 0), (40.0, 10.5, 0.5, 0, 255, 0), (12.75, 30.0, 0.75, 0, 0, 255)],
                     [(60.0, 1.0, 0.5, 10, 20, 30), (2.0, 20.0, 0.1, 200, 100, 0), (30.0, 46.5, 0.9, 0, 0, 255)]):
        for order in (vertices, vertices[::-1]):
            record = pipeline.setup_record(pipeline.submit_screen(order))
            left_edges = [k for k in range(3) if record["edge_step_x"][k] > 0]
            assert 1 <= len(left_edges) <= 2
            for j in range(2):
                k = left_edges[j] if j < len(left_edges) else None
                quot = record["span_quot"][k] if k is not None else 0
                step_quot = record["span_step_quot"][k] if k is not None else 0
                assert record["left_depth_start"][j] == wrap(record["depth_start"] - quot * record["depth_step_x"], depth_bits)
                assert record["left_depth_step"][j] == wrap(record["depth_step_y"] - step_quot * record["depth_step_x"], depth_bits)
                for c in range(3):
                    assert record["left_color_start"][j][c] == wrap(
                        record["color_start"][c] - quot * record["color_step_x"][c], colour_bits)
                    assert record["left_color_step"][j][c] == wrap(
                        record["color_step_y"][c] - step_quot * record["color_step_x"][c], colour_bits)


def test_profile_from_fields_equals_json():
    from_fields = rastersim.Pipeline(width=64, height=48, traversal="bbox", depth_write=False)
    from_json = rastersim.Pipeline('{"width": 64, "height": 48, "traversal": "bbox", "depth_write": false}')
    assert from_fields.profile == from_json.profile
    with pytest.raises(rastersim.Error, match="traversal"):
        rastersim.Pipeline(traversal="diagonal")
    with pytest.raises(rastersim.Error, match="not both"):
        rastersim.Pipeline('{"width": 64}', height=48)


def test_misuse_raises_an_error_with_a_message():
    with pytest.raises(rastersim.Error, match="width"):
        rastersim.Pipeline('{"width": 5000}')
    with pytest.raises(rastersim.Error, match="line"):
        rastersim.Pipeline('{"width": 64,')
    pipeline = rastersim.Pipeline('{"width": 64, "height": 48}')
    with pytest.raises(rastersim.Error, match="was not submitted"):
        pipeline.triangle(0)
    with pytest.raises(rastersim.Error, match="was not submitted"):
        pipeline.fragments(0)
    with pytest.raises(rastersim.Error, match="triangle"):
        pipeline.submit_screen([(0, 0, 0, 0, 0, 0), (1000, 0, 0, 0, 0, 0), (0, 5, 0, 0, 0, 0)])
    with pytest.raises(rastersim.Error, match="colour value 300"):
        pipeline.submit_screen([(0, 0, 0, 300, 0, 0), (10, 0, 0, 0, 0, 0), (0, 5, 0, 0, 0, 0)])
    with pytest.raises(rastersim.Error, match="depth"):
        pipeline.submit_snapped([(0, 0, 1 << 24, 0, 0, 0), (16, 0, 0, 0, 0, 0), (0, 16, 0, 0, 0, 0)])
    degenerate = pipeline.submit_screen([(1, 1, 0, 0, 0, 0), (5, 5, 0, 0, 0, 0), (9, 9, 0, 0, 0, 0)])
    assert pipeline.triangle(degenerate)["status"] == "degenerate"
    with pytest.raises(rastersim.Error, match="degenerate"):
        pipeline.setup_record(degenerate)
    with pytest.raises(TypeError):
        pipeline.submit_screen([(0, 0, 0)])

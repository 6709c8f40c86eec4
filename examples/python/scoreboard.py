#!/usr/bin/python3
"""The golden model as a scoreboard, from Python (docs/library.md): the same as
examples/scoreboard/scoreboard.c. Reads a profile (JSON) and a .tri file, submits every triangle,
prints each triangle's cycle record, writes the fragments as `rastersim render --fragments` does
and the final buffers (one "depth rrggbb" line per pixel, row-major).
With an installed rastersim: PYTHONPATH=PREFIX/lib/python3/dist-packages.
Usage: scoreboard.py PROFILE.json TRIANGLES.tri FRAGMENTS.csv BUFFERS.txt"""
import sys

import rastersim


def main(profile_path, tri_path, fragments_path, buffers_path):
    pipeline = rastersim.Pipeline(open(profile_path).read())
    for number, line in enumerate(open(tri_path), 1):
        # The positions and colours; a texture section (format version 2: "uvw" and nine numbers) is not used here.
        values = [float(v) for v in line.split("#")[0].split("uvw")[0].split()]
        if not values:
            continue
        if len(values) not in (9, 12, 18):
            sys.exit(f"scoreboard: {tri_path}:{number}: {len(values)} values, expected 9, 12 or 18")
        colours = {9: [(255, 255, 255)] * 3, 12: [values[9:12]] * 3,
                   18: [values[9 + 3 * k:12 + 3 * k] for k in range(3)]}[len(values)]
        index = pipeline.submit_screen([tuple(values[3 * k:3 * k + 3]) + tuple(int(c) for c in colours[k])
                                        for k in range(3)])
        record = pipeline.triangle(index)
        print(f"triangle {index}: {record['status']}, setup {record['setup_accept']}..{record['setup_done']}, "
              f"walker {record['walker_load']}..{record['walker_end']}, {record['fragments']} fragments")
    with open(fragments_path, "w") as out:
        out.write(",".join(rastersim.FRAGMENT_COLUMNS) + "\n")
        for row in pipeline.fragments():
            out.write(",".join(str(int(v)) for v in row) + "\n")
    print(f"cycles {pipeline.frame_cycles()}")
    with open(buffers_path, "w") as out:
        for depth, colour in zip(pipeline.depth().ravel(), pipeline.color().ravel()):
            out.write(f"{int(depth)} {int(colour):06x}\n")


if __name__ == "__main__":
    if len(sys.argv) != 5:
        sys.exit("usage: scoreboard.py PROFILE.json TRIANGLES.tri FRAGMENTS.csv BUFFERS.txt")
    try:
        main(*sys.argv[1:])
    except rastersim.Error as error:
        sys.exit(f"scoreboard: {error}")

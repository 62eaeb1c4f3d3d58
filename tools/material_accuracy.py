"""Per-object comparison of the material-layers scene (tests/data/blender/material_layers) and
the glass scene (tests/data/blender/glass); called by tools/material-accuracy.sh, which renders
the images.

Usage: material_accuracy.py [--nodes A,B,...] NODES.txt NAME=LIT.hdr:REFERENCE.hdr ...

NODES is lit-render --reference --node-map's file (the node each pixel sees first: a sheet, not
what lies behind it). For each named pair and each object (a node named in --nodes, the spheres
below by default), over the object's inner pixels (the pixel and its four neighbours see it), in
luminance (Rec. 709): the mean of LIT ÷ the mean of REFERENCE. Prints one markdown table row per
pair.
"""

import sys

import numpy as np

from room_accuracy import read_hdr, read_node_map

SPHERES = ["plain", "clearcoat", "clearcoat_rough", "specular", "ior", "coated_metal", "sheen"]


def inner_masks(nodes, names, objects):
    masks = {}
    for index, name in names.items():
        if name not in objects:
            continue
        m = nodes == index
        inner = m.copy()
        inner[1:, :] &= m[:-1, :]
        inner[:-1, :] &= m[1:, :]
        inner[:, 1:] &= m[:, :-1]
        inner[:, :-1] &= m[:, 1:]
        inner[0, :] = inner[-1, :] = False
        inner[:, 0] = inner[:, -1] = False
        masks[name] = inner
    return masks


def main():
    args = sys.argv[1:]
    objects = SPHERES
    if args and args[0] == "--nodes":
        objects = args[1].split(",")
        args = args[2:]
    names, nodes = read_node_map(args[0])
    masks = inner_masks(nodes, names, objects)
    for arg in args[1:]:
        label, pair = arg.split("=", 1)
        lit_path, ref_path = pair.split(":", 1)
        lit = read_hdr(lit_path)  # luminance
        ref = read_hdr(ref_path)
        cells = []
        for name in objects:
            m = masks.get(name)
            if m is None or not m.any() or ref[m].mean() <= 1e-9:
                cells.append("—")
            else:
                cells.append(f"{lit[m].mean() / ref[m].mean():.3f}")
        print(f"| {label} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()

"""Per-sphere comparison of the material-layers scene (tests/data/blender/material_layers);
called by tools/material-accuracy.sh, which renders the images.

Usage: material_accuracy.py NODES.txt NAME=LIT.hdr:REFERENCE.hdr ...

NODES is lit-render --reference --node-map's file (the node each pixel sees). For each named pair
and each sphere (a node whose name is one of the spheres below), over the sphere's inner pixels
(the pixel and its four neighbours see it), in luminance (Rec. 709): the mean of LIT ÷ the mean of
REFERENCE. Prints one markdown table row per pair.
"""

import sys

import numpy as np

from room_accuracy import read_hdr, read_node_map

SPHERES = ["plain", "clearcoat", "clearcoat_rough", "specular", "ior", "coated_metal", "sheen"]


def inner_masks(nodes, names):
    masks = {}
    for index, name in names.items():
        if name not in SPHERES:
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
    names, nodes = read_node_map(sys.argv[1])
    masks = inner_masks(nodes, names)
    for arg in sys.argv[2:]:
        label, pair = arg.split("=", 1)
        lit_path, ref_path = pair.split(":", 1)
        lit = read_hdr(lit_path)  # luminance
        ref = read_hdr(ref_path)
        cells = []
        for sphere in SPHERES:
            m = masks.get(sphere)
            if m is None or not m.any() or ref[m].mean() <= 1e-9:
                cells.append("—")
            else:
                cells.append(f"{lit[m].mean() / ref[m].mean():.3f}")
        print(f"| {label} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()

"""Compares renders of the sun room (tests/data/blender/sun_room) over the pixels lit only by
bounced light; called by tools/room-accuracy.sh, which renders the Lit images.

Usage: room_accuracy.py DIRECT.hdr REFERENCE.hdr [--second-seed REFERENCE2.hdr] [--nodes MAP.txt] NAME=IMAGE.hdr ...

DIRECT is Lit with GI off: a pixel whose direct light is 0 (and whose 8 neighbours' is) is lit
only by bounced light. REFERENCE is the truth the others are measured against. For each image, over
those pixels, in luminance (Rec. 709):
  mean       mean of the image ÷ mean of the reference;
  RMSE       root mean square of image − reference, ÷ the reference's mean (noise included);
  blotches   the image scaled to the reference's mean over those pixels (the level is the mean
             column's business), then both box-filtered 7 × 7 over those pixels, and the RMS of
             the difference ÷ the reference's mean: what is left of the error once pixel noise
             is averaged away and the level matched. A cloud-like blotch tens of pixels wide
             survives the filter, per-pixel noise mostly does not.
With --second-seed (the reference rendered again with another seed), the reference's own pixel
noise σ is estimated from the two (RMS of their difference ÷ √2), and each row gets a fourth
column:
  RMSE − noise  √(RMSE² − σ²): the image's RMSE against the noise-free truth, the reference's
             noise taken out of it; and the first line says σ, and what a reference with a quarter
             of the samples would score (2σ: noise falls as 1/√samples).
With --nodes (lit-render --reference --node-map: the node each pixel sees), two more tables follow,
each after a blank line, per surface (scene node with at least 40 of those pixels): each image's
mean ÷ the reference's there, and the blotches within the surface (as above, with the level
matched and the filter run over the surface's pixels alone), which tell a cloud-like blotch on a
wall from light that differs between surfaces.
Prints a line on the pixels compared, then one markdown table row per image.
"""

import sys

import numpy as np


def read_hdr(path):
    data = open(path, "rb").read()
    end = data.index(b"\n\n") + 2
    line_end = data.index(b"\n", end)
    size = data[end:line_end].split()
    height, width = int(size[1]), int(size[3])
    p = line_end + 1
    image = np.zeros((height, width, 4), np.uint8)
    for y in range(height):
        if data[p] == 2 and data[p + 1] == 2:  # new run-length encoding, one channel at a time
            p += 4
            for c in range(4):
                x = 0
                while x < width:
                    n = data[p]
                    p += 1
                    if n > 128:
                        n -= 128
                        image[y, x:x + n, c] = data[p]
                        p += 1
                    else:
                        image[y, x:x + n, c] = np.frombuffer(data[p:p + n], np.uint8)
                        p += n
                    x += n
        else:
            image[y] = np.frombuffer(data[p:p + 4 * width], np.uint8).reshape(width, 4)
            p += 4 * width
    exponent = image[..., 3].astype(np.int32)
    scale = np.where(exponent > 0, np.ldexp(1.0, exponent - 136), 0.0)
    rgb = image[..., :3] * scale[..., None]
    return rgb @ np.array([0.2126, 0.7152, 0.0722])


def box_filter(values, mask, radius):
    """Mean of `values` over the masked pixels in each (2r+1)² window (0 where none)."""
    v = np.where(mask, values, 0.0)
    m = mask.astype(np.float64)
    def window_sum(a):
        padded = np.pad(a, radius)
        integral = padded.cumsum(0).cumsum(1)
        integral = np.pad(integral, ((1, 0), (1, 0)))
        k = 2 * radius + 1
        return integral[k:, k:] - integral[:-k, k:] - integral[k:, :-k] + integral[:-k, :-k]
    counts = window_sum(m)
    return np.where(counts > 0, window_sum(v) / np.maximum(counts, 1), 0.0)


def read_node_map(path):
    """(names by index, node index per pixel as an array, rows top first) of a lit-render node map."""
    lines = open(path).read().split("\n")
    width, height = (int(v) for v in lines[1].split())
    count = int(lines[2].split()[1])
    names = {}
    for line in lines[3:3 + count]:
        index, _, name = line.partition(" ")
        names[int(index)] = name
    rows = lines[4 + count:4 + count + height]
    nodes = np.array([[int(t.rstrip("*")) for t in row.split()] for row in rows], np.int64)
    return names, nodes.reshape(height, width)


def main():
    args = sys.argv[1:]
    node_map = None
    if "--nodes" in args:
        i = args.index("--nodes")
        node_map = read_node_map(args[i + 1])
        del args[i:i + 2]
    second_seed = None
    if "--second-seed" in args:
        i = args.index("--second-seed")
        second_seed = read_hdr(args[i + 1])
        del args[i:i + 2]
    direct, reference = read_hdr(args[0]), read_hdr(args[1])
    dark = direct <= 1e-6
    eroded = dark.copy()
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            eroded &= np.roll(np.roll(dark, dy, 0), dx, 1)
    mask = eroded & (reference > 0)
    mask[0, :] = mask[-1, :] = False
    mask[:, 0] = mask[:, -1] = False
    ref_mean = reference[mask].mean()
    ref_smooth = box_filter(reference, mask, 3)
    noise = None
    line = f"pixels lit only by bounced light: {mask.sum()} of {mask.size}; reference mean {ref_mean:.4f}"
    if second_seed is not None:
        noise = np.sqrt(((reference - second_seed)[mask] ** 2).mean() / 2.0) / ref_mean
        line += (f"; the reference's own noise {100 * noise:.1f} % of its mean (with a quarter of its samples "
                 f"{200 * noise:.1f} %)")
    print(line)
    images = []
    for arg in args[2:]:
        name, path = arg.split("=", 1)
        image = read_hdr(path)
        images.append((name, image))
        if image.shape != reference.shape:
            print(f"| {name} | size {image.shape} differs from the reference's {reference.shape} | | |")
            continue
        rmse = np.sqrt(((image - reference)[mask] ** 2).mean()) / ref_mean
        smooth = box_filter(image * (ref_mean / max(image[mask].mean(), 1e-12)), mask, 3)
        blotches = np.sqrt(((smooth - ref_smooth)[mask] ** 2).mean()) / ref_mean
        row = f"| {name} | {image[mask].mean() / ref_mean:.3f} | {100 * rmse:.1f} % | {100 * blotches:.1f} % |"
        if noise is not None:
            row += f" {100 * np.sqrt(max(rmse ** 2 - noise ** 2, 0.0)):.1f} % |"
        print(row)
    if node_map is not None:
        names, nodes = node_map

        def surface_table(caption, cell):
            """Prints `caption`, then a row per surface of at least 40 pixels: cell(image, surface, ref_mean)."""
            print()
            print(caption)
            print()
            print("| surface | pixels | " + " | ".join(name for name, _ in images) + " |")
            print("|---|---:|" + "---:|" * len(images))
            for index in sorted(names):
                surface = mask & (nodes == index)
                if surface.sum() < 40:
                    continue
                ref = reference[surface].mean()
                cells = [cell(image, surface, ref) if image.shape == reference.shape else "" for _, image in images]
                print(f"| {names[index]} | {surface.sum()} | " + " | ".join(cells) + " |")

        surface_table("Per surface (scene node): each image's mean ÷ the reference's over the surface's pixels lit "
                      "only by bounced light (surfaces with at least 40):",
                      lambda image, surface, ref: f"{image[surface].mean() / ref:.2f}")

        def blotches_within(image, surface, ref):
            smooth = box_filter(image * (ref / max(image[surface].mean(), 1e-12)), surface, 3)
            ref_smooth_here = box_filter(reference, surface, 3)
            return f"{100 * np.sqrt(((smooth - ref_smooth_here)[surface] ** 2).mean()) / ref:.1f} %"

        surface_table("Per surface, blotches within it: each image scaled to the reference's mean over the surface's "
                      "pixels, both box-filtered 7 × 7 over those pixels alone, the RMS of the difference ÷ the "
                      "reference's mean there (light that differs from surface to surface, the table above, does not "
                      "count; a gradient across the surface that differs does):", blotches_within)

if __name__ == "__main__":
    main()

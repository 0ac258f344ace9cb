#!/usr/bin/env python3
"""Draws the lessons' geometric diagrams as SVG, computed rather than drawn by
hand: diagrams.py OUT_DIR (the `diagrams` target writes docs/diagrams/).

  00_tga_layout.svg          a TGA file's header fields and an RLE packet
  01_bresenham_midpoint.svg  the midpoint decision between two candidate pixels
  02_edge_functions.svg      edge functions, the inside, and the top-left rule
  02_barycentric_areas.svg   barycentric weights as ratios of areas
  03_painter_cycle.svg       three sticks, each over the next: no order works
  03_depth_mapping.svg       stored depth against view distance, per format
  04_mip_footprint.svg       a pixel's footprint in the texture and its mip level
  05_perspective_edge.svg    along an edge from w = 1 to w = 3: screen position against
                             surface position, and 1/w linear on the screen
  05_frustum_ndc.svg         the view frustum seen from the side, and the NDC cube it becomes
  05_clip_fan.svg            a triangle crossing the near plane, cut to a quad and drawn as a fan
  06_reflection_vectors.svg  the vectors n, l, v, r and h at a lit point
  06_srgb_curve.svg          sRGB bytes against linear light, bytes 128 and 188 marked
  06_normal_matrix.svg       a circle squashed by M: the normal carried by M, and by M^-T
  07_mirrored_seam.svg       a seam where the texture is mirrored: the two frames it needs
  07_tbn_frame.svg           a triangle in the texture and on the surface, with T and B
  08_two_passes.svg          the light's box and its map, the camera's frustum, a point in shadow
  08_acne.svg                a tilted surface against the map's stored depths: acne, and the bias
  08_light_box_fit.svg       the light's box fitted to the scene or to the view: texel size
  08_normal_offset.svg       the point looked up moved along its normal: acne gone, by a texel
  08_pcf_kernel.svg          a 3x3 kernel's answers around (u, v), and the edge they soften
  09_cosine_sampling.svg     uniform points on the disc lifted onto the hemisphere: directions drawn
                             as the cosine (Malley's method)
  09_cube_faces.svg          a direction's face and place, seen from above; the six faces unfolded
  09_latlong.svg             the lat-long map: longitude across, latitude up, the pole's row, the seam
  09_reflect_refract.svg     reflection and refraction at glass, with Snell's angles and Fresnel's share
  09_microfacets.svg         a rough surface as tiny mirrors: the facets facing h, one shadowed, one masked
  09_lobe_lean.svg           GGX's one-bounce lobe seen head-on and at 75 degrees, against the mirror direction
  09_split_sum.svg           the split sum's two halves: the BRDF's albedo over n.v and roughness, the lobes that blur the light
  10_kernels.svg             Crytek's ball and the hemisphere's half ball at a floor point beside a box,
                             the samples the depth buffer hides, and the range check
  10_horizon.svg             one slice through the eye: the horizons h1 and h2, the normal's angle gamma,
                             and the open arc between them
  12_tiles_and_bins.svg      a frame cut into tiles, each tile's bin of triangles, the owning thread
  12_blocks.svg              one triangle over 8x8 blocks: rejected, accepted whole, tested per pixel
  12_visibility_buffer.svg   drawing back to front: shaded per passing pixel, or once from the id buffer
  12_lane_queue.svg          a triangle's pixels of a few blocks, queued into full vectors
  12_fragment_queue.svg      tiny triangles' pixels shaded triangle by triangle, or queued as
                             fragments across the triangles of a model (flushed where the model changes)
  12_block_rows.svg          a triangle of a few pixels in one 8x8 block: every row tested and walked,
                             or only the rows its box of pixel centres reaches
  12_shadow_pass.svg         a shadow map's block skip under a negative depth bias: bounded by the
                             unbiased nearest depth (a nearer triangle lost) or by the biased one
  12_texel_words.svg         a packed texel's 32-bit word: the normal map's RGB and, in its alpha
                             byte, the specular map's value; a pixel's gathers before and after
  12_srgb_entry.svg          lesson 06's sRGB search as two dependent gathers, or one gather of a
                             32-bit entry (the slice's first byte, its step as a 24-bit fraction)
  12_albedo_word.svg         the decoded albedo's texel in one 32-bit word (square roots in 11, 11
                             and 10 bits), and each layout's error per byte in output levels
  12_shadow_lookup.svg       one vector's eight pixels looked up in the shadow map: eight points,
                             each with its own 2x2 texels, scattered over the map
  13_frame_path.svg          one frame of the viewer, from the keyboard to the window
"""
import math
import pathlib
import sys

import matplotlib
import matplotlib.patches
import matplotlib.text

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Polygon, Rectangle  # noqa: E402

INK, LINE, ACCENT, SOFT = "#222222", "#2060c0", "#d04020", "#e8eef8"


# The docs site's column is about 615 px wide at a 1280 px window: a figure
# wider than that is shrunk to it, and its text with it. Text must stay 8 px
# or more as shown (site/check_site.py fails a diagram whose text is not):
# a figure raises any smaller font to its floor before it is laid out.
COLUMN_PX, MIN_TEXT_PX = 615, 8.4


def smallest_font(figure):
    """The least font size, in points, that shows as MIN_TEXT_PX on the page."""
    width_in = figure.get_figwidth()
    shown_px = min(width_in * 96, COLUMN_PX)  # an SVG's point is 96/72 CSS pixels
    return MIN_TEXT_PX * width_in * 72 / shown_px


def save(figure, out, name):
    floor = smallest_font(figure)
    for text in figure.findobj(matplotlib.text.Text):
        if text.get_text() and text.get_fontsize() < floor:
            text.set_fontsize(floor)
    for axes in figure.axes:  # tick labels are made again when drawn: their size is a setting
        for axis in ("x", "y"):
            labels = getattr(axes, f"get_{axis}ticklabels")()
            if labels and min(label.get_fontsize() for label in labels) < floor:
                axes.tick_params(axis=axis, labelsize=floor)
    figure.tight_layout()
    figure.savefig(out / name, metadata={"Date": None})
    plt.close(figure)
    print(f"wrote {out / name}")


def pixel_grid(axes, width, height):
    for x in range(width + 1):
        axes.plot([x, x], [0, height], color="#bbbbbb", lw=0.6)
    for y in range(height + 1):
        axes.plot([0, width], [y, y], color="#bbbbbb", lw=0.6)
    for x in range(width):
        for y in range(height):
            axes.plot(x + 0.5, y + 0.5, ".", color="#999999", ms=3)
    axes.set_xlim(-0.2, width + 0.2)
    axes.set_ylim(-0.2, height + 0.2)
    axes.set_aspect("equal")
    axes.axis("off")


# The 18-byte TGA header as tga.cpp reads it: (first byte, length, field).
TGA_HEADER = [(0, 1, "ID\nlength"), (1, 1, "map\ntype"), (2, 1, "image\ntype"), (3, 5, "colour map\n(unused)"),
              (8, 4, "x, y origin\n(unused)"), (12, 2, "width"), (14, 2, "height"), (16, 1, "pixel\ndepth"),
              (17, 1, "image\ndescr.")]


def tga_layout(out):
    figure, axes = plt.subplots(figsize=(9, 4.4))
    byte = 1.8  # width of a byte: the header in two rows, so that a byte's box holds its name
    for first, length, label in TGA_HEADER:
        row = 0 if first < 12 else 1
        x, y = (first - 12 * row) * byte, 3.4 - 1.7 * row
        axes.add_patch(Rectangle((x, y), length * byte, 1, fill=True, color=SOFT, ec=LINE))
        axes.text(x + length * byte / 2, y + 0.5, label, ha="center", va="center", fontsize=8)
        axes.text(x, y + 1.1, str(first), fontsize=7, color="#777777")
    axes.text(6 * byte, 2.8, "18", fontsize=7, color="#777777")
    axes.add_patch(Rectangle((6 * byte, 1.7), 4.4, 1, fill=False, ec="#999999", ls="--"))
    axes.text(6 * byte + 2.2, 2.2, "ID, palette,\nthen pixels", ha="center", va="center", fontsize=8,
              color="#555555")
    axes.text(0, 4.95, "Header: 18 bytes, little-endian. Descriptor bit 5: top row first; bit 4: right to left.",
              fontsize=8)
    # An RLE stream: a run packet and a raw packet, as the encoder writes them.
    packets = [("1 | 0000011", "run of 4:\nheader, then 1 pixel", 3), ("0 | 0000010", "raw, 3 pixels:\nheader, then 3 pixels", 9)]
    x = 0.0
    head = 3.0
    for bits, label, data_len in packets:
        axes.add_patch(Rectangle((x, -0.6), head, 1, color="#f4c7b8", ec=ACCENT))
        axes.text(x + head / 2, -0.1, bits, ha="center", va="center", fontsize=8)
        axes.add_patch(Rectangle((x + head, -0.6), data_len * 0.75, 1, color=SOFT, ec=LINE))
        axes.text(x + head + data_len * 0.375, -0.1, "B G R" if data_len == 3 else "B G R  B G R  B G R",
                  ha="center", va="center", fontsize=8)
        axes.text(x + 0.1, -1.2, label, fontsize=8, va="center")
        x += head + data_len * 0.75 + 1.2
    axes.text(0, 0.75, "RLE packets (24-bit): bit 7 of the header byte = run, bits 0-6 = count - 1", fontsize=8)
    axes.set_xlim(-0.3, 22.0)
    axes.set_ylim(-1.8, 5.3)
    axes.axis("off")
    save(figure, out, "00_tga_layout.svg")


def bresenham(x0, y0, x1, y1):
    """The shallow-case midpoint line, as the lesson derives it."""
    a, b = x1 - x0, y1 - y0
    decision, y, pixels = 2 * b - a, y0, []
    for x in range(x0, x1 + 1):
        pixels.append((x, y))
        if decision > 0:
            y += 1
            decision -= 2 * a
        decision += 2 * b
    return pixels


def bresenham_midpoint(out):
    figure, axes = plt.subplots(figsize=(7, 4))
    width, height = 9, 5
    pixel_grid(axes, width, height)
    start, end = (0, 0), (8, 3)
    pixels = bresenham(*start, *end)
    for x, y in pixels:
        axes.add_patch(Rectangle((x, y), 1, 1, color=SOFT, zorder=0))
    axes.plot([start[0] + 0.5, end[0] + 0.5], [start[1] + 0.5, end[1] + 0.5], color=LINE, lw=2)
    # One decision, at the third pixel: the candidates east and north-east, and their midpoint.
    x, y = pixels[2]
    east, north_east, mid = (x + 1.5, y + 0.5), (x + 1.5, y + 1.5), (x + 1.5, y + 1.0)
    axes.plot(*east, "o", color=INK, ms=6)
    axes.plot(*north_east, "o", color=INK, ms=6)
    axes.plot(*mid, "x", color=ACCENT, ms=9, mew=2)
    line_y = start[1] + 0.5 + (end[1] - start[1]) / (end[0] - start[0]) * (mid[0] - start[0] - 0.5)
    above = line_y > mid[1]
    axes.annotate("M = midpoint of the two candidates", mid, (mid[0] + 1.2, mid[1] + 2.2),
                  arrowprops=dict(arrowstyle="->", color=ACCENT), color=ACCENT, fontsize=9)
    axes.annotate(f"line {'above' if above else 'below'} M: step to the "
                  f"{'north-east' if above else 'east'} pixel", (mid[0], line_y),
                  (mid[0] + 1.2, mid[1] - 1.6), arrowprops=dict(arrowstyle="->", color=LINE),
                  color=LINE, fontsize=9)
    axes.set_title("Bresenham: the sign of F at the midpoint picks the next pixel (shaded: the line's pixels)",
                   fontsize=9)
    save(figure, out, "01_bresenham_midpoint.svg")


def edge_functions(out):
    figure, axes = plt.subplots(figsize=(6, 5))
    width, height = 10, 8
    pixel_grid(axes, width, height)
    v = [(1.5, 1.5), (8.5, 1.5), (4.5, 6.5)]  # counter-clockwise, window y up
    area = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0])

    def edge(a, b, p):
        return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])

    def top_left(a, b):
        dx, dy = b[0] - a[0], b[1] - a[1]
        return dy < 0 or (dy == 0 and dx < 0)

    edges = [(v[1], v[2]), (v[2], v[0]), (v[0], v[1])]
    for x in range(width):
        for y in range(height):
            p = (x + 0.5, y + 0.5)
            values = [edge(a, b, p) for a, b in edges]
            inside = all(e > 0 or (e == 0 and top_left(a, b)) for e, (a, b) in zip(values, edges))
            on_edge = any(e == 0 for e in values) and all(e >= 0 for e in values)
            if inside:
                axes.add_patch(Rectangle((x, y), 1, 1, color=SOFT, zorder=0))
            if on_edge:
                axes.plot(*p, "o", color=ACCENT if inside else INK, ms=5, mfc="none" if not inside else ACCENT)
    axes.add_patch(Polygon(v, closed=True, fill=False, ec=LINE, lw=1.8))
    for a, b in edges:
        middle = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        axes.annotate("", (middle[0] + (b[0] - a[0]) * 0.08, middle[1] + (b[1] - a[1]) * 0.08), middle,
                      arrowprops=dict(arrowstyle="->", color=LINE, lw=1.5))
        kind = "left edge: its centres are in" if top_left(a, b) else "right or bottom edge: its centres are out"
        axes.text(middle[0] + 0.3, middle[1] - 0.35, kind, fontsize=7, color=LINE)
    axes.set_title(f"E(p) = cross(b − a, p − a) ≥ 0 on all three edges (twice the area: {area:g}).\n"
                   "Filled dots: centres exactly on an edge that the top-left rule keeps; open: ones it drops",
                   fontsize=8)
    save(figure, out, "02_edge_functions.svg")


def barycentric_areas(out):
    figure, axes = plt.subplots(figsize=(5.5, 4.5))
    v = [(0.0, 0.0), (6.0, 0.5), (2.0, 5.0)]
    p = (2.6, 1.8)

    def area(a, b, c):
        return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))

    total = area(*v)
    colours = ["#f4c7b8", "#c6dcf2", "#d4ecc8"]
    for k in range(3):
        a, b = v[(k + 1) % 3], v[(k + 2) % 3]
        weight = area(p, a, b) / total
        axes.add_patch(Polygon([p, a, b], closed=True, color=colours[k], ec="white"))
        centre = ((p[0] + a[0] + b[0]) / 3, (p[1] + a[1] + b[1]) / 3)
        axes.text(*centre, f"λ{k} = {weight:.2f}", ha="center", va="center", fontsize=9)
    for k, (x, y) in enumerate(v):
        axes.plot(x, y, "o", color=INK)
        axes.text(x + (0.15 if k else -0.45), y + (0.15 if k != 1 else -0.45), f"v{k}", fontsize=10)
    axes.plot(*p, "o", color=ACCENT)
    axes.text(p[0] + 0.12, p[1] + 0.12, "p", color=ACCENT, fontsize=10)
    axes.set_aspect("equal")
    axes.axis("off")
    axes.set_title("λk = area of the triangle opposite vk, over the whole area;\n"
                   "λ0 + λ1 + λ2 = 1 and λ0·v0 + λ1·v1 + λ2·v2 = p", fontsize=9)
    save(figure, out, "02_barycentric_areas.svg")


def painter_cycle(out):
    figure, axes = plt.subplots(figsize=(5, 4.6))
    names, colours = ["A", "B", "C"], ["#dc503c", "#50b45a", "#466edc"]
    radius, half = 1.0, 0.12
    corners = [(radius * math.cos(math.pi * (0.5 + 2 * i / 3)), radius * math.sin(math.pi * (0.5 + 2 * i / 3)))
               for i in range(3)]
    sticks = []
    for i in range(3):  # as hsr_scenes.cpp builds them: past corner i to past corner i + 1
        a, b = corners[i], corners[(i + 1) % 3]
        dx, dy = b[0] - a[0], b[1] - a[1]
        start, end = (a[0] - 0.25 * dx, a[1] - 0.25 * dy), (b[0] + 0.25 * dx, b[1] + 0.25 * dy)
        length = math.hypot(end[0] - start[0], end[1] - start[1])
        nx, ny = -(end[1] - start[1]) / length * half, (end[0] - start[0]) / length * half
        sticks.append([(start[0] - nx, start[1] - ny), (end[0] - nx, end[1] - ny),
                       (end[0] + nx, end[1] + ny), (start[0] + nx, start[1] + ny)])
        axes.add_patch(Polygon(sticks[i], closed=True, color=colours[i]))
        middle = ((start[0] + end[0]) / 2, (start[1] + end[1]) / 2)
        axes.text(middle[0] * 1.9, middle[1] * 1.9, names[i], fontsize=11, ha="center", va="center",
                  color=colours[i], fontweight="bold")
    # At corner i, stick i (near there) lies over stick i + 2 (far there): redraw
    # its first third, which holds that crossing, on top.
    for i in range(3):
        s0, s1, e1, e0 = sticks[i][0], sticks[i][1], sticks[i][2], sticks[i][3]

        def third(p, q):
            return (p[0] + (q[0] - p[0]) / 3, p[1] + (q[1] - p[1]) / 3)

        axes.add_patch(Polygon([s0, third(s0, s1), third(e0, e1), e0], closed=True, color=colours[i]))
        j = (i + 2) % 3
        axes.text(corners[i][0] * 1.5, corners[i][1] * 1.5 + (0.12 if i == 0 else -0.12),
                  f"{names[i]} over {names[j]}", fontsize=8, ha="center", va="center", color=INK)
    axes.set_aspect("equal")
    axes.set_xlim(-1.9, 1.9)
    axes.set_ylim(-1.3, 1.9)
    axes.axis("off")
    axes.set_title("A runs from near (top) to far (bottom left), B from near (bottom left) to far (right),\n"
                   "C from near (right) to far (top): each lies over the next at one crossing,\n"
                   "so no drawing order of whole sticks is right", fontsize=8)
    save(figure, out, "03_painter_cycle.svg")


def depth_mapping(out):
    figure, axes = plt.subplots(figsize=(6.5, 4.2))
    near, far = 0.1, 1000.0
    ws = [near * (far / near) ** (i / 400) for i in range(401)]
    standard = [far * (w - near) / (w * (far - near)) for w in ws]
    reverse = [near * (far - w) / (w * (far - near)) for w in ws]
    linear = [(w - near) / (far - near) for w in ws]
    axes.plot(ws, standard, color=LINE, label="standard: d = f (w − n) / (w (f − n))")
    axes.plot(ws, reverse, color=ACCENT, label="reverse-Z: 1 − d")
    axes.plot(ws, linear, color="#888888", ls="--", label="linear in w (not affine in screen space)")
    half = 2 * near * far / (far + near)
    axes.axvline(half, color=LINE, lw=0.6, ls=":")
    axes.text(half * 1.2, 0.45, f"d reaches 0.5 at w = {half:.2f}:\nhalf of all depth values\nlie in front of it",
              fontsize=7, color=LINE)
    axes.set_xscale("log")
    axes.set_xlabel("view distance w (near 0.1, far 1000)")
    axes.set_ylabel("stored depth")
    axes.legend(fontsize=7, loc="center right")
    axes.grid(True, which="both", alpha=0.3)
    axes.set_title("How each format spends its values over distance", fontsize=9)
    save(figure, out, "03_depth_mapping.svg")


def mip_footprint(out):
    figure, axes = plt.subplots(figsize=(6, 5))
    # A pixel's footprint in texel units: the parallelogram spanned by the
    # derivatives of (u, v) * size along x and y, as level_of_detail sees it.
    du, dv = (6.0, 1.5), (-1.2, 2.4)
    origin = (3.0, 2.0)
    corners = [origin, (origin[0] + du[0], origin[1] + du[1]),
               (origin[0] + du[0] + dv[0], origin[1] + du[1] + dv[1]), (origin[0] + dv[0], origin[1] + dv[1])]
    for x in range(13):
        axes.plot([x, x], [0, 8], color="#cccccc", lw=0.5)
    for y in range(9):
        axes.plot([0, 12], [y, y], color="#cccccc", lw=0.5)
    axes.add_patch(Polygon(corners, closed=True, color=SOFT, ec=LINE, lw=1.5))
    along_x, along_y = math.hypot(*du), math.hypot(*dv)
    rho = max(along_x, along_y)
    level = math.log2(rho)
    texel = 2 ** math.floor(level)
    centre = (origin[0] + (du[0] + dv[0]) / 2, origin[1] + (du[1] + dv[1]) / 2)
    axes.add_patch(Rectangle((centre[0] - texel / 2, centre[1] - texel / 2), texel, texel, fill=False,
                             ec=ACCENT, lw=1.5, ls="--"))
    axes.annotate(f"|∂(u,v)/∂x| = {along_x:.1f} texels", (origin[0] + du[0] / 2, origin[1] + du[1] / 2),
                  (6.5, 0.6), arrowprops=dict(arrowstyle="->", color=LINE), color=LINE, fontsize=8)
    axes.annotate(f"|∂(u,v)/∂y| = {along_y:.1f} texels", (origin[0] + dv[0] / 2, origin[1] + dv[1] / 2),
                  (0.2, 6.8), arrowprops=dict(arrowstyle="->", color=LINE), color=LINE, fontsize=8)
    axes.text(8.3, 6.4, f"ρ = longer side = {rho:.1f}\nlevel = log2 ρ = {level:.2f}\n"
              f"dashed: one texel of level {math.floor(level)}\n({texel} × {texel} of level 0)",
              fontsize=8, color=ACCENT)
    axes.set_xlim(0, 12)
    axes.set_ylim(0, 8)
    axes.set_aspect("equal")
    axes.axis("off")
    axes.set_title("One pixel's footprint in the texture (grid: level-0 texels) and the mip level chosen for it",
                   fontsize=8)
    save(figure, out, "04_mip_footprint.svg")


def perspective_edge(out):
    # The edge of docs/05_perspective.md's worked example: from A (w = 1) to
    # B (w = 3). A surface point at fraction t along it lies at screen fraction
    # sigma = t w_B / ((1 - t) w_A + t w_B).
    w_a, w_b = 1.0, 3.0
    ts = [i / 200 for i in range(201)]
    sigmas = [t * w_b / ((1 - t) * w_a + t * w_b) for t in ts]
    figure, (left, right) = plt.subplots(1, 2, figsize=(9, 3.8))
    left.plot(sigmas, ts, color=LINE, label="surface fraction t at screen fraction σ")
    left.plot([0, 1], [0, 1], color="#888888", ls="--", label="what affine interpolation assumes")
    left.plot([0.5], [0.25], "o", color=ACCENT)
    left.annotate("screen midpoint σ = ½\nis the surface point t = ¼", (0.5, 0.25), (0.55, 0.08),
                  arrowprops=dict(arrowstyle="->", color=ACCENT), color=ACCENT, fontsize=8)
    left.set_xlabel("screen fraction σ along the edge")
    left.set_ylabel("surface fraction t")
    left.legend(fontsize=7, loc="upper left")
    left.set_title("Equal screen steps are unequal surface steps", fontsize=9)
    inverse_w = [1 / ((1 - t) * w_a + t * w_b) for t in ts]
    right.plot(sigmas, inverse_w, color=LINE, label="1/w: a straight line in σ")
    right.plot(sigmas, [(1 - t) * w_a + t * w_b for t in ts], color=ACCENT, label="w itself: not straight")
    right.set_xlabel("screen fraction σ along the edge")
    right.legend(fontsize=7, loc="upper left")
    right.set_title("Why the pipeline interpolates 1/w and a/w", fontsize=9)
    for axes in (left, right):
        axes.grid(True, alpha=0.3)
    save(figure, out, "05_perspective_edge.svg")


def frustum_ndc(out):
    # The page's walk-through: fov 60 degrees, near 1, far 10, the eye-space
    # point (1, 0.5, -4). Left: the frustum from the side (view distance
    # d = -z_e across, y_e up). Right: the same in NDC (z_ndc across, y_ndc
    # up), the frustum now the cube [-1, 1]^3; equal steps of distance
    # crowd towards the far face, as z_ndc is linear in 1/d.
    near, far, half_angle = 1.0, 10.0, math.radians(30)
    a, b = -(far + near) / (far - near), -2 * far * near / (far - near)
    point_y, point_d = 0.5, 4.0
    figure, (left, right) = plt.subplots(1, 2, figsize=(8.6, 3.6), gridspec_kw={"width_ratios": [1.7, 1]})
    t = math.tan(half_angle)
    left.add_patch(Polygon([(near, -near * t), (far, -far * t), (far, far * t), (near, near * t)], closed=True,
                           color=SOFT, ec=LINE, lw=1.2))
    left.plot([0, far], [0, far * t], color="#999999", lw=0.8, ls="--")
    left.plot([0, far], [0, -far * t], color="#999999", lw=0.8, ls="--")
    left.plot([0], [0], "o", color=INK)
    left.text(-0.2, 0.35, "eye", fontsize=8, ha="right")
    left.plot([0, point_d], [0, point_y], color=ACCENT, lw=0.8, ls=":")
    left.plot([point_d], [point_y], "o", color=ACCENT)
    left.text(point_d + 0.15, point_y + 0.15, "(y 0.5, d 4)", color=ACCENT, fontsize=8)
    for d in range(1, 11):
        left.plot([d, d], [-0.12, 0.12], color=INK, lw=0.6)
    left.text(near, -near * t - 0.7, "near, d = 1", fontsize=8, ha="center", color=LINE)
    left.text(far, -far * t - 0.7, "far, d = 10", fontsize=8, ha="center", color=LINE)
    left.text(5.5, 4.4, "y = ±d · tan(θ/2), θ = 60°", fontsize=8, ha="center", rotation=0)
    left.set_xlim(-1.2, 11)
    left.set_ylim(-6.6, 6.6)
    left.set_aspect("equal")
    left.axis("off")
    left.set_title("Eye space, from the side: the view frustum\n(view distance d = −z_e across)", fontsize=8)

    right.add_patch(Rectangle((-1, -1), 2, 2, color=SOFT, ec=LINE, lw=1.2))
    for d in range(1, 11):  # equal steps of distance, where they land in NDC
        z = (a * -d + b) / d
        right.plot([z, z], [-1, -0.9], color=INK, lw=0.6)
        if d in (1, 2, 4, 10):
            right.text(z, -1.12, str(d), fontsize=7, ha="center", va="top")
    z_point = (a * -point_d + b) / point_d
    y_point = (1 / t) * point_y / point_d
    right.plot([z_point], [y_point], "o", color=ACCENT)
    right.text(z_point - 0.05, y_point + 0.1, "(y 0.217, z 0.667)", color=ACCENT, fontsize=8, ha="right")
    right.text(-1, 1.08, "near: z = −1", fontsize=8, color=LINE, ha="center")
    right.text(1, 1.08, "far: z = +1", fontsize=8, color=LINE, ha="center")
    right.text(0, -1.45, "d = 1 … 10 in NDC z: crowded towards far", fontsize=7, ha="center")
    right.set_xlim(-1.5, 1.5)
    right.set_ylim(-1.7, 1.4)
    right.set_aspect("equal")
    right.axis("off")
    right.set_title("NDC, after dividing by w = d:\nthe frustum is the cube [−1, 1]³ (y_ndc up, z_ndc across)",
                    fontsize=8)
    save(figure, out, "05_frustum_ndc.svg")


def clip_fan(out):
    # Seen from above (x across, view depth down the page): a triangle with one
    # corner behind the near plane, cut by Sutherland-Hodgman into a convex
    # quad, then drawn as the fan (0, 1, 2), (0, 2, 3).
    near = 0.6
    a, b, c = (-1.4, 3.2), (1.8, 2.6), (0.4, -0.5)  # (x, distance in front of the eye)

    def cut(p, q):  # where the edge p-q crosses distance = near
        t = (p[1] - near) / (p[1] - q[1])
        return (p[0] + (q[0] - p[0]) * t, near)

    quad = [a, b, cut(b, c), cut(c, a)]
    figure, axes = plt.subplots(figsize=(6.4, 4.4))
    axes.add_patch(Polygon([a, b, c], closed=True, fill=False, ec="#999999", ls="--"))
    axes.add_patch(Polygon(quad, closed=True, color=SOFT, ec=LINE, lw=1.5))
    axes.plot([quad[0][0], quad[2][0]], [quad[0][1], quad[2][1]], color=LINE, lw=1, ls=":")
    axes.plot([-2.4, 2.6], [near, near], color=ACCENT, lw=1.2)
    axes.text(-2.4, near - 0.22, "near plane (z = −w in clip space)", color=ACCENT, fontsize=8)
    axes.plot([-2.4, 2.6], [0, 0], color=INK, lw=0.6, ls="-.")
    axes.text(-2.4, 0.08, "the eye's plane, w = 0", fontsize=8)
    axes.plot([0], [0], "o", color=INK)
    for name, point, dx in (("0", quad[0], -0.25), ("1", quad[1], 0.12), ("2", quad[2], 0.1),
                            ("3", quad[3], -0.3)):
        axes.text(point[0] + dx, point[1] + 0.1, name, color=LINE, fontsize=9)
    axes.text(c[0] + 0.1, c[1] - 0.05, "behind the plane: cut away", color="#777777", fontsize=8)
    axes.text(-0.2, 2.0, "fan: (0, 1, 2)\nand (0, 2, 3)", color=LINE, fontsize=8)
    axes.set_xlim(-2.5, 2.7)
    axes.set_ylim(-0.8, 3.6)
    axes.set_aspect("equal")
    axes.axis("off")
    axes.set_title("Clipping at the near plane, seen from above:\nthe triangle becomes a convex quad, drawn as a fan",
                   fontsize=8)
    save(figure, out, "05_clip_fan.svg")


def reflection_vectors(out):
    figure, axes = plt.subplots(figsize=(6, 3.8))
    axes.plot([-2.2, 2.2], [0, 0], color=INK, lw=1.5)
    axes.add_patch(Rectangle((-2.2, -0.35), 4.4, 0.35, color=SOFT))
    angle_l, angle_v = math.radians(35), math.radians(-60)  # from the normal, towards +x and -x
    vectors = {"n": (0.0, 1.6), "l": (1.6 * math.sin(angle_l), 1.6 * math.cos(angle_l)),
               "v": (1.6 * math.sin(angle_v), 1.6 * math.cos(angle_v))}
    lx, ly = vectors["l"][0] / 1.6, vectors["l"][1] / 1.6
    vectors["r"] = (1.6 * -lx, 1.6 * ly)  # l mirrored about n: r = 2 (n.l) n - l
    hx, hy = lx + vectors["v"][0] / 1.6, ly + vectors["v"][1] / 1.6
    norm = math.hypot(hx, hy)
    vectors["h"] = (1.6 * hx / norm, 1.6 * hy / norm)  # halfway between l and v
    colours = {"n": INK, "l": ACCENT, "v": LINE, "r": ACCENT, "h": "#208040"}
    words = {"n": "n: the normal", "l": "l: towards the light", "v": "v: towards the eye",
             "r": "r: l mirrored about n", "h": "h = (l + v) / |l + v|"}
    for name, (x, y) in vectors.items():
        axes.annotate("", (x, y), (0, 0), arrowprops=dict(arrowstyle="->", color=colours[name], lw=1.6,
                                                         ls="--" if name in "rh" else "-"))
        axes.text(x * 1.08, y * 1.08 + 0.05, words[name], color=colours[name], fontsize=8,
                  ha="left" if x >= 0 else "right")
    axes.text(0, -0.6, "Phong's highlight: (r · v)^s      Blinn-Phong's: (n · h)^s      diffuse: n · l",
              ha="center", fontsize=8)
    axes.set_xlim(-2.6, 2.6)
    axes.set_ylim(-0.8, 2.0)
    axes.set_aspect("equal")
    axes.axis("off")
    save(figure, out, "06_reflection_vectors.svg")


def srgb_to_linear(c):
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def srgb_curve(out):
    figure, axes = plt.subplots(figsize=(6, 4.2))
    bytes_ = list(range(256))
    axes.plot(bytes_, [srgb_to_linear(b / 255) for b in bytes_], color=LINE, label="linear light of an sRGB byte")
    axes.plot([0, 255], [0, 1], color="#888888", ls="--", label="byte / 255: what lighting the bytes assumes")
    half = srgb_to_linear(128 / 255)
    axes.plot([128, 128, 0], [0, half, half], color=ACCENT, lw=0.8, ls=":")
    axes.text(132, half - 0.06, f"byte 128 is {half:.3f} of full light,\nnot 0.5", color=ACCENT, fontsize=8)
    byte_half = min(bytes_, key=lambda b: abs(srgb_to_linear(b / 255) - 0.5))
    axes.plot([0, byte_half, byte_half], [0.5, 0.5, 0], color="#208040", lw=0.8, ls=":")
    axes.text(byte_half + 4, 0.52, f"half the light is byte {byte_half}", color="#208040", fontsize=8)
    axes.set_xlabel("stored byte")
    axes.set_ylabel("linear light (0 to 1)")
    axes.set_xlim(0, 255)
    axes.set_ylim(0, 1)
    axes.legend(fontsize=7, loc="upper left")
    axes.grid(True, alpha=0.3)
    axes.set_title("sRGB spends its bytes on the dark end", fontsize=9)
    save(figure, out, "06_srgb_curve.svg")


def normal_matrix(out):
    # A unit circle squashed to half its height by M = diag(1, 0.5). At the
    # point at 40 degrees, the tangent goes with M; the normal carried by M
    # is no longer perpendicular to it, the one carried by M^-T is.
    sx, sy = 1.0, 0.5
    a = math.radians(40)
    p = (math.cos(a), math.sin(a))
    tangent = (-math.sin(a), math.cos(a))
    normal = p
    q = (sx * p[0], sy * p[1])
    t_m = (sx * tangent[0], sy * tangent[1])
    n_m = (sx * normal[0], sy * normal[1])
    n_it = (normal[0] / sx, normal[1] / sy)

    def unit(v, length=0.6):
        n = math.hypot(*v)
        return (v[0] / n * length, v[1] / n * length)

    def degrees(u, v):
        return math.degrees(math.acos((u[0] * v[0] + u[1] * v[1]) / (math.hypot(*u) * math.hypot(*v))))

    figure, (left, right) = plt.subplots(1, 2, figsize=(9, 3.6))
    ts = [2 * math.pi * i / 200 for i in range(201)]
    left.plot([math.cos(t) for t in ts], [math.sin(t) for t in ts], color=INK)
    right.plot([sx * math.cos(t) for t in ts], [sy * math.sin(t) for t in ts], color=INK)
    for axes, origin, arrows in ((left, p, [(tangent, LINE, "tangent"), (normal, ACCENT, "normal")]),
                                 (right, q, [(t_m, LINE, "M · tangent"), (n_m, "#999999", "M · normal"),
                                             (n_it, ACCENT, "M⁻ᵀ · normal")])):
        for v, colour, label in arrows:
            d = unit(v)
            axes.annotate("", (origin[0] + d[0], origin[1] + d[1]), origin,
                          arrowprops=dict(arrowstyle="->", color=colour, lw=1.6))
            axes.text(origin[0] + d[0] * 1.1, origin[1] + d[1] * 1.1, label, color=colour, fontsize=8)
        axes.set_aspect("equal")
        axes.set_xlim(-1.3, 1.9)
        axes.set_ylim(-1.2, 1.5)
        axes.axis("off")
    left.set_title("a unit circle and one point's tangent and normal", fontsize=9)
    right.set_title(f"squashed by M = diag(1, ½): M · normal is {abs(90 - degrees(t_m, n_m)):.0f}° off\n"
                    f"perpendicular to the tangent, M⁻ᵀ · normal {abs(90 - degrees(t_m, n_it)):.0f}°", fontsize=9)
    save(figure, out, "06_normal_matrix.svg")


def mirrored_seam(out):
    # A strip whose texture is mirrored about its middle line: u = |x|. On the
    # left half u grows to the left, on the right half to the right; along the
    # seam, one vertex needs both frames.
    figure, axes = plt.subplots(figsize=(6.4, 3.4))
    for x in range(-3, 4):
        axes.plot([x, x], [0, 2], color="#bbbbbb", lw=0.6)
    for y in range(3):
        axes.plot([-3, 3], [y, y], color="#bbbbbb", lw=0.6)
    axes.add_patch(Rectangle((-3, 0), 3, 2, color=SOFT, alpha=0.6))
    axes.plot([0, 0], [0, 2], color=ACCENT, lw=1.5)
    axes.text(0, 2.12, "seam: u = 0 on both sides", color=ACCENT, fontsize=8, ha="center")
    for side, sign in (("left half: u = −x, T points left, w = −1", -1), ("right half: u = x, T points right, w = +1", 1)):
        origin = (0.05 * sign, 1.0)
        axes.annotate("", (origin[0] + 1.1 * sign, 1.0), origin, arrowprops=dict(arrowstyle="->", color=LINE, lw=1.8))
        axes.annotate("", (origin[0], 1.9), origin, arrowprops=dict(arrowstyle="->", color="#208040", lw=1.8))
        axes.text(origin[0] + 1.2 * sign, 1.05, "T", color=LINE, fontsize=9, ha="center")
        axes.text(1.7 * sign, 0.25, side, color=INK, fontsize=7, ha="center")
    axes.text(0.12, 1.8, "B", color="#208040", fontsize=9)
    axes.text(0, -0.35, "averaged over both halves, T is zero (or whatever rounding leaves): split frames keep one per side",
              fontsize=7, ha="center")
    axes.set_xlim(-3.3, 3.3)
    axes.set_ylim(-0.5, 2.4)
    axes.set_aspect("equal")
    axes.axis("off")
    save(figure, out, "07_mirrored_seam.svg")


def tbn_frame(out):
    # A face's T and B solve [e1; e2] = [du1 dv1; du2 dv2] [T; B]: the surface
    # directions in which u and v grow (tangents.cpp's face_frame), here on a
    # triangle drawn flat so both panels are in the plane of the page.
    uv = [(0.1, 0.1), (0.9, 0.25), (0.35, 0.85)]
    pos = [(0.0, 0.0), (2.2, -0.4), (0.3, 1.6)]
    d1 = (uv[1][0] - uv[0][0], uv[1][1] - uv[0][1])
    d2 = (uv[2][0] - uv[0][0], uv[2][1] - uv[0][1])
    e1 = (pos[1][0] - pos[0][0], pos[1][1] - pos[0][1])
    e2 = (pos[2][0] - pos[0][0], pos[2][1] - pos[0][1])
    det = d1[0] * d2[1] - d2[0] * d1[1]
    t = ((e1[0] * d2[1] - e2[0] * d1[1]) / det, (e1[1] * d2[1] - e2[1] * d1[1]) / det)
    b = ((e2[0] * d1[0] - e1[0] * d2[0]) / det, (e2[1] * d1[0] - e1[1] * d2[0]) / det)
    figure, (left, right) = plt.subplots(1, 2, figsize=(9, 3.8))
    left.add_patch(Rectangle((0, 0), 1, 1, fill=False, ec="#999999"))
    left.add_patch(Polygon(uv, closed=True, color=SOFT, ec=LINE, lw=1.5))
    left.annotate("", (0.45, 0.05), (0.05, 0.05), arrowprops=dict(arrowstyle="->", color=ACCENT, lw=1.6))
    left.annotate("", (0.05, 0.45), (0.05, 0.05), arrowprops=dict(arrowstyle="->", color="#208040", lw=1.6))
    left.text(0.47, 0.03, "u", color=ACCENT, fontsize=9)
    left.text(0.0, 0.47, "v", color="#208040", fontsize=9)
    left.set_title("the face in the texture", fontsize=9)
    right.add_patch(Polygon(pos, closed=True, color=SOFT, ec=LINE, lw=1.5))
    centre = (sum(p[0] for p in pos) / 3, sum(p[1] for p in pos) / 3)
    for v, colour, label in ((t, ACCENT, "T: where u grows"), (b, "#208040", "B: where v grows")):
        scale = 0.5 / math.hypot(*v)
        tip = (centre[0] + v[0] * scale, centre[1] + v[1] * scale)
        right.annotate("", tip, centre, arrowprops=dict(arrowstyle="->", color=colour, lw=1.8))
        right.text(tip[0] + 0.05, tip[1] + 0.05, label, color=colour, fontsize=8)
    angle = math.degrees(math.acos((t[0] * b[0] + t[1] * b[1]) / (math.hypot(*t) * math.hypot(*b))))
    right.set_title(f"the same face on the surface: T and B {angle:.0f}° apart here;\n"
                    "the frame keeps T (made perpendicular to N) and rebuilds B = w (N × T)", fontsize=9)
    for axes in (left, right):
        axes.set_aspect("equal")
        axes.axis("off")
    left.set_xlim(-0.1, 1.1)
    left.set_ylim(-0.1, 1.1)
    right.set_xlim(-0.3, 2.6)
    right.set_ylim(-0.6, 1.9)
    save(figure, out, "07_tbn_frame.svg")


def two_passes(out):
    # Side view. A directional light from the upper right: its orthographic
    # box is a rectangle along its direction; the map is the box's near side,
    # cut into texels. A floor, a box-shaped caster on it, the camera's frustum
    # from the left. Point P on the floor: its ray to the light meets the
    # caster first, so the texel stores the caster's depth, nearer than P's.
    figure, axes = plt.subplots(figsize=(7.2, 4.6))
    light = (math.cos(math.radians(55)), math.sin(math.radians(55)))  # towards the light
    across = (-light[1], light[0])
    axes.plot([-3.2, 3.4], [0, 0], color=INK, lw=1.5)
    axes.add_patch(Rectangle((-0.3, 0), 0.9, 0.9, color="#c08040", alpha=0.8))
    axes.text(0.15, 0.4, "caster", ha="center", fontsize=8, color="white")
    # The light's box: centred on the scene, 5 wide across the light, 5 deep.
    centre = (0.2, 0.5)
    half_w, half_d = 2.6, 2.6
    corners = []
    for sw, sd in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
        corners.append((centre[0] + across[0] * sw * half_w + light[0] * sd * half_d,
                        centre[1] + across[1] * sw * half_w + light[1] * sd * half_d))
    axes.add_patch(Polygon(corners, closed=True, fill=False, ec=ACCENT, lw=1, ls="--"))
    near = [corners[2], corners[3]]  # the side towards the light: the map
    texels = 12
    for i in range(texels + 1):
        t = i / texels
        x = near[0][0] + (near[1][0] - near[0][0]) * t
        y = near[0][1] + (near[1][1] - near[0][1]) * t
        axes.plot([x - light[0] * 0.08, x + light[0] * 0.08], [y - light[1] * 0.08, y + light[1] * 0.08],
                  color=ACCENT, lw=0.8)
    axes.plot([near[0][0], near[1][0]], [near[0][1], near[1][1]], color=ACCENT, lw=2)
    angle = math.degrees(math.atan2(near[1][1] - near[0][1], near[1][0] - near[0][0]))
    if angle > 90 or angle < -90:
        angle -= 180 if angle > 0 else -180
    axes.text((near[0][0] + near[1][0]) / 2 + light[0] * 0.7, (near[0][1] + near[1][1]) / 2 + light[1] * 0.7,
              "the shadow map: one depth per texel", color=ACCENT, fontsize=8, rotation=angle,
              ha="center", va="center", rotation_mode="anchor")
    # P, its ray to the light, the caster's hit.
    p = (-0.8, 0.0)  # on the shadow side, away from the light
    t_top = (0.9 - p[1]) / light[1]  # where the ray reaches the caster's top
    hit = (p[0] + light[0] * t_top, 0.9)
    end = (p[0] + light[0] * 4.4, p[1] + light[1] * 4.4)
    axes.plot([p[0], end[0]], [p[1], end[1]], color=ACCENT, lw=0.9, ls=":")
    axes.plot([p[0]], [p[1]], "o", color=LINE)
    axes.text(p[0] - 0.2, p[1] - 0.35, "P: depth d_P from the light", color=LINE, fontsize=8, ha="center")
    axes.plot([hit[0]], [hit[1]], "o", color=ACCENT)
    axes.text(hit[0] + 0.9, hit[1] + 0.05, "stored there: d_map < d_P,\nso P is in shadow", color=ACCENT, fontsize=8)
    # The camera's frustum, from the left.
    eye = (-3.0, 1.6)
    axes.plot([eye[0]], [eye[1]], "o", color=INK)
    axes.text(eye[0] - 0.1, eye[1] + 0.15, "camera", fontsize=8)
    for target in ((3.4, 0.0), (0.2, 0.0)):
        axes.plot([eye[0], target[0]], [eye[1], target[1]], color=LINE, lw=0.8, ls="--")
    axes.plot([eye[0], p[0]], [eye[1], p[1]], color=LINE, lw=1)
    axes.text(-3.3, 2.2, "pass 2: the camera sees P\nand looks it up in the map", color=LINE, fontsize=8)
    axes.text(2.4, 0.35, "pass 1: depth from the light\n(its orthographic box, dashed)", color=ACCENT, fontsize=8)
    axes.set_xlim(-3.4, 4.8)
    axes.set_ylim(-0.6, 5.0)
    axes.set_aspect("equal")
    axes.axis("off")
    axes.set_title("Shadow mapping in two passes, seen from the side", fontsize=9)
    save(figure, out, "08_two_passes.svg")


def acne(out):
    # The light straight above; a surface tilted under it; map texels of
    # width 1 across the top. Each texel stores the surface's depth at its
    # centre: a staircase. A point between centres lies below its texel's
    # step on one half (deeper: "in shadow") and above it on the other: the
    # stripes of acne. The slope bias lowers every step by the slope times
    # a texel, under the surface everywhere.
    figure, (left, right) = plt.subplots(1, 2, figsize=(8.6, 3.4), sharey=True)
    slope = 0.45
    xs = [i / 20 for i in range(0, 121)]
    for axes, bias, title in ((left, 0.0, "no bias: stripes (acne)"),
                              (right, slope * 1.0, "slope bias: steps lowered by slope × texel")):
        axes.plot(xs, [slope * x for x in xs], color=INK, lw=1.5)
        for i in range(6):
            stored = slope * (i + 0.5) + bias
            axes.plot([i, i + 1], [stored, stored], color=ACCENT, lw=1.6)
            axes.plot([i + 0.5], [slope * (i + 0.5)], "o", color=ACCENT, markersize=3)
        for x in xs:
            texel = min(int(x), 5)
            stored = slope * (texel + 0.5) + bias
            shadowed = slope * x > stored + 1e-9
            if shadowed:
                axes.plot([x], [slope * x], "s", color="#9040a0", markersize=3)
        axes.set_title(title, fontsize=8)
    finish_staircase(figure, left, right, out, "08_acne.svg",
                     "black: the surface; red: the depth each texel stored (at its centre); "
                     "purple: points deeper than their texel's depth, which the test calls shadowed")


def finish_staircase(figure, left, right, out, name, caption):
    """The axes, the caption and the file of a two-panel map-staircase figure."""
    for axes in (left, right):
        axes.set_xlabel("across the map (texels)", fontsize=8)
        axes.tick_params(labelsize=7)
    left.invert_yaxis()  # shared: once for both
    left.set_ylabel("depth from the light (down the page)", fontsize=8)
    figure.text(0.5, 0.01, caption, fontsize=7, ha="center")
    figure.subplots_adjust(bottom=0.22)
    save(figure, out, name)


def bare(axes, xlim, ylim):
    """Axes for a drawing, not a plot: these limits, square units, no frame or ticks."""
    axes.set_xlim(*xlim)
    axes.set_ylim(*ylim)
    axes.set_aspect("equal")
    axes.axis("off")


def light_box_fit(out):
    # Side view, the light straight above (its box's sides vertical, its map
    # along the top). A long floor with a crate; the camera low at the left,
    # seeing only part of the floor. Scene fit: the box spans the whole floor;
    # view fit: the box spans what the camera sees, its top still pushed over
    # the scene. The same 8 texels on each.
    figure, axes_pair = plt.subplots(1, 2, figsize=(8.6, 3.6), sharey=True)
    floor = (-4.0, 4.0)
    seen = (-1.0, 2.0)
    for axes, (x0, x1), title in ((axes_pair[0], floor, "--fit scene: the whole scene's box"),
                                  (axes_pair[1], seen, "--fit view: the box around what the camera sees")):
        axes.plot(list(floor), [0, 0], color=INK, lw=1.5)
        axes.add_patch(Rectangle((1.0, 0), 0.8, 0.8, color="#c08040", alpha=0.8))
        eye = (-2.2, 1.0)
        axes.plot([eye[0]], [eye[1]], "o", color=LINE)
        axes.text(eye[0], eye[1] + 0.2, "camera", fontsize=7, ha="center", color=LINE)
        for target in seen:
            axes.plot([eye[0], target], [eye[1], 0], color=LINE, lw=0.8, ls="--")
        top = 2.6
        axes.add_patch(Rectangle((x0, -0.2), x1 - x0, top + 0.2, fill=False, ec=ACCENT, lw=1.2, ls="--"))
        texels = 8
        width = (x1 - x0) / texels
        for i in range(texels + 1):
            axes.plot([x0 + i * width] * 2, [top - 0.12, top + 0.12], color=ACCENT, lw=1)
        axes.plot([x0, x1], [top, top], color=ACCENT, lw=2)
        unit = "unit" if width == 1 else "units"
        axes.text((x0 + x1) / 2, top + 0.3, f"8 texels, {width:.2g} {unit} each", color=ACCENT,
                  fontsize=8, ha="center")
        axes.annotate("", xy=(3.6, 2.0), xytext=(3.6, 3.2),
                      arrowprops=dict(arrowstyle="->", color=INK, lw=1))
        axes.text(3.7, 2.9, "light", fontsize=7)
        axes.set_title(title, fontsize=8)
        bare(axes, (-4.3, 4.3), (-0.5, 3.4))
    figure.text(0.5, 0.04, "The same 8 texels: fitted to what the camera sees (between the dashed blue "
                "lines), each covers 0.38 units instead of 1.\nThe box's side towards the light is "
                "still pushed out over the whole scene, so that a caster outside the view still casts.",
                fontsize=7, ha="center")
    save(figure, out, "08_light_box_fit.svg")


def normal_offset(out):
    # The acne staircase again (the map's texels store the surface's depth at
    # their centres), the light above. Left: P looked up where it is: deeper
    # than its texel's step on half of each texel. Right: P moved along its
    # normal by one texel before the lookup: the point looked up lies above
    # every step, so nothing on the surface is shadowed by itself.
    figure, (left, right) = plt.subplots(1, 2, figsize=(8.6, 3.4), sharey=True)
    slope = 0.45
    length = math.hypot(1, slope)
    normal = (-slope / length, -1 / length)  # towards the light (up the page: depth shrinks)
    xs = [i / 20 for i in range(0, 121)]
    for axes, offset, title in ((left, 0.0, "no offset: P below its step half the time"),
                                (right, 1.0, "normal offset, 1 texel: the lookup moves off the surface")):
        axes.plot(xs, [slope * x for x in xs], color=INK, lw=1.5)
        for i in range(6):
            stored = slope * (i + 0.5)
            axes.plot([i, i + 1], [stored, stored], color=ACCENT, lw=1.6)
        for x in xs[::2]:
            px, pz = x + normal[0] * offset, slope * x + normal[1] * offset
            if not 0 <= px < 6:
                continue
            texel = min(int(px), 5)
            shadowed = pz > slope * (texel + 0.5) + 1e-9
            axes.plot([px], [pz], "s" if shadowed else "o", color="#9040a0" if shadowed else LINE,
                      markersize=3)
        if offset:
            x = 2.3
            axes.annotate("", xy=(x + normal[0] * offset, slope * x + normal[1] * offset),
                          xytext=(x, slope * x), arrowprops=dict(arrowstyle="->", color=LINE, lw=1))
            axes.text(x + 0.15, slope * x + 0.05, "P", fontsize=8)
            axes.text(4.4, 1.0, "each point P looked up\none texel along its normal", fontsize=7,
                      color=LINE, ha="center", bbox=dict(fc="white", ec="none", pad=1))
        axes.set_title(title, fontsize=8)
    finish_staircase(figure, left, right, out, "08_normal_offset.svg",
                     "black: the surface; red: the depth each texel stored; blue: the points "
                     "looked up, lit; purple: looked up deeper than their texel's depth (acne)")


def pcf_kernel(out):
    # Left: the map's texels around the lookup (u, v), a shadow edge running
    # through them; each texel of the 3x3 kernel answers lit (1) or shadowed
    # (0) for P's depth, and the answers average. Right: visibility along a
    # line across the edge: the hard test's step, and 3x3 PCF's ramp three
    # texels wide.
    figure, (grid, ramp) = plt.subplots(1, 2, figsize=(8.6, 3.6),
                                        gridspec_kw={"width_ratios": [1, 1.3]})
    u, v = 2.35, 2.6  # the lookup, in texels
    edge = lambda x: 0.6 * x + 1.05  # noqa: E731  the caster's edge: shadowed above it
    lit = 0
    ci, cj = int(u), int(v)
    for i in range(5):
        for j in range(5):
            shadowed = j + 0.5 > edge(i + 0.5)
            in_kernel = abs(i - ci) <= 1 and abs(j - cj) <= 1
            colour = "#b8b8b8" if shadowed else "#fff4c8"
            grid.add_patch(Rectangle((i, j), 1, 1, fc=colour, ec="#888888", lw=0.6))
            if in_kernel:
                lit += 0 if shadowed else 1
                grid.text(i + 0.5, j + 0.5, "0" if shadowed else "1", ha="center", va="center",
                          fontsize=10, color=INK)
    grid.add_patch(Rectangle((ci - 1, cj - 1), 3, 3, fill=False, ec=ACCENT, lw=2))
    grid.plot([0, 5], [edge(0), edge(5)], color=INK, lw=1, ls="--")
    grid.plot([u], [v], "o", color=LINE)
    grid.text(u - 0.08, v + 0.1, "(u, v)", fontsize=8, color=LINE, ha="right",
              bbox=dict(fc="white", ec="none", pad=0.5))
    grid.set_title(f"3x3 PCF at (u, v): {lit} of 9 texels say lit -> {lit / 9:.2f}", fontsize=8)
    grid.text(2.5, -0.3, "grey: the map's depth is nearer than P\n(a caster: shadowed); dashed: its edge",
              fontsize=7, ha="center", va="top")
    bare(grid, (-0.1, 5.1), (-1.3, 5.1))
    xs = [i / 50 for i in range(-150, 151)]
    hard = [1.0 if x < 0 else 0.0 for x in xs]
    pcf3 = []
    for x in xs:  # the mean of the hard answers at three texel centres around x
        answers = [1.0 if (math.floor(x + d) + 0.5) < 0 else 0.0 for d in (-1, 0, 1)]
        pcf3.append(sum(answers) / 3)
    ramp.plot(xs, hard, color=INK, lw=1.5, label="hard test: 0 or 1")
    ramp.plot(xs, pcf3, color=ACCENT, lw=1.5, label="3x3 PCF: 1, 2/3, 1/3, 0 across the edge")
    ramp.set_xlabel("across the shadow's edge (map texels)", fontsize=8)
    ramp.set_ylabel("visibility (1: lit)", fontsize=8)
    ramp.tick_params(labelsize=7)
    ramp.legend(fontsize=7, loc="lower left")
    ramp.set_title("The answers are averaged, never the depths", fontsize=8)
    figure.tight_layout()
    save(figure, out, "08_pcf_kernel.svg")


def edge_inside(tri, px, py):
    """Whether (px, py) is inside the counter-clockwise triangle (float, for the figures)."""
    for k in range(3):
        (ax, ay), (bx, by) = tri[(k + 1) % 3], tri[(k + 2) % 3]
        if (bx - ax) * (py - ay) - (by - ay) * (px - ax) < 0:
            return False
    return True


def tiles_and_bins(out):
    # A 16 x 12 frame in tiles of 4: three triangles, each binned into the
    # tiles its bounding box touches; tiles shaded by the thread that took
    # them in one run (which thread takes which varies from run to run).
    figure, axes = plt.subplots(figsize=(7.6, 4.4))
    width, height, tile = 16, 12, 4
    triangles = [((1, 1), (7, 2), (3, 6)), ((6, 5), (14, 3), (11, 10)), ((2, 8), (8, 7), (5, 11.5))]
    colours = ["#d04020", "#2060c0", "#30a050"]
    bins = {}
    for index, tri in enumerate(triangles):
        xs, ys = [v[0] for v in tri], [v[1] for v in tri]
        for ty in range(int(min(ys)) // tile, int(max(ys)) // tile + 1):
            for tx in range(int(min(xs)) // tile, int(max(xs)) // tile + 1):
                bins.setdefault((tx, ty), []).append(index)
    for ty in range(height // tile):
        for tx in range(width // tile):
            n = ty * (width // tile) + tx
            axes.add_patch(Rectangle((tx * tile, ty * tile), tile, tile,
                                     color="#f4f4f4" if n % 2 == 0 else "#e4e8f0", ec="#888888", lw=0.8))
            names = ",".join(str(i) for i in bins.get((tx, ty), [])) or "-"
            axes.text(tx * tile + 0.2, ty * tile + tile - 0.5, f"bin: {names}", fontsize=7, color=INK)
            axes.text(tx * tile + tile - 0.2, ty * tile + 0.3, f"thread {n % 2}", fontsize=6,
                      color="#777777", ha="right")
    for index, (tri, colour) in enumerate(zip(triangles, colours)):
        axes.add_patch(Polygon(tri, closed=True, color=colour, alpha=0.45))
        xs, ys = [v[0] for v in tri], [v[1] for v in tri]
        axes.add_patch(Rectangle((min(xs), min(ys)), max(xs) - min(xs), max(ys) - min(ys), fill=False,
                                 ec=colour, lw=0.8, ls="--"))
        axes.text(sum(xs) / 3, sum(ys) / 3, str(index), color="white", fontsize=10, ha="center", va="center",
                  weight="bold")
    axes.set_xlim(-0.2, width + 0.2)
    axes.set_ylim(-0.2, height + 0.2)
    axes.set_aspect("equal")
    axes.axis("off")
    axes.set_title("Binning: each triangle goes to every tile its box (dashed) touches, in drawing order;\n"
                   "a tile is then drawn from its bin alone by whichever thread takes it, sharing nothing", fontsize=9)
    save(figure, out, "12_tiles_and_bins.svg")


def blocks(out):
    # A 32 x 24 tile of 8 x 8 blocks and one triangle; each block decided from
    # its corner centres as the kernel decides it: outside one edge at all four
    # (rejected), inside all three at all four (accepted whole), else per pixel.
    figure, axes = plt.subplots(figsize=(6.8, 5.0))
    tri = ((2.3, 1.6), (29.5, 6.2), (9.4, 22.7))
    size_x, size_y, block = 32, 24, 8
    counts = {"rejected": 0, "whole": 0, "per pixel": 0}
    for by in range(size_y // block):
        for bx in range(size_x // block):
            corners = [(bx * block + cx + 0.5, by * block + cy + 0.5) for cx in (0, 7) for cy in (0, 7)]
            rejected = False
            inside = True
            for k in range(3):
                (ax, ay), (bx2, by2) = tri[(k + 1) % 3], tri[(k + 2) % 3]
                values = [(bx2 - ax) * (py - ay) - (by2 - ay) * (px - ax) for px, py in corners]
                rejected |= max(values) < 0
                inside &= min(values) > 0
            kind = "rejected" if rejected else "whole" if inside else "per pixel"
            counts[kind] += 1
            colour = {"rejected": "#f4f4f4", "whole": "#b8e0b8", "per pixel": "#f8d8a8"}[kind]
            axes.add_patch(Rectangle((bx * block, by * block), block, block, color=colour, ec="#666666", lw=1))
            if kind == "per pixel":
                for y in range(by * block, by * block + block):
                    for x in range(bx * block, bx * block + block):
                        if edge_inside(tri, x + 0.5, y + 0.5):
                            axes.plot(x + 0.5, y + 0.5, "s", color="#c07010", ms=3)
    axes.add_patch(Polygon(tri, closed=True, fill=False, ec=INK, lw=1.4))
    axes.set_xlim(-0.3, size_x + 0.3)
    axes.set_ylim(-0.3, size_y + 0.3)
    axes.set_aspect("equal")
    axes.axis("off")
    axes.set_title(f"8x8 blocks: {counts['rejected']} rejected and {counts['whole']} accepted from their corners "
                   f"(grey, green),\n{counts['per pixel']} tested pixel by pixel (orange: the centres inside)",
                   fontsize=9)
    save(figure, out, "12_blocks.svg")


def visibility_buffer(out):
    # Three overlapping triangles drawn far to near on a 16 x 12 grid. Left:
    # shaded at every pixel that passes the depth test (how many times each
    # pixel was shaded). Right: pass 1 keeps the id of the nearest triangle
    # per pixel, pass 2 shades each pixel once, with that triangle.
    width, height = 16, 12
    triangles = [((0.5, 0.5), (15.5, 1.5), (8, 11.5)), ((2, 3), (13, 2.5), (7, 10)), ((4, 5), (11, 4), (8, 9))]
    colours = ["#d04020", "#2060c0", "#30a050"]
    shaded = [[0] * width for _ in range(height)]
    owner = [[-1] * width for _ in range(height)]
    for index, tri in enumerate(triangles):  # far to near: every later one passes
        for y in range(height):
            for x in range(width):
                if edge_inside(tri, x + 0.5, y + 0.5):
                    shaded[y][x] += 1
                    owner[y][x] = index
    figure, (left, right) = plt.subplots(1, 2, figsize=(8.4, 3.6))
    total_left = sum(map(sum, shaded))
    total_right = sum(1 for row in owner for o in row if o >= 0)
    for y in range(height):
        for x in range(width):
            n = shaded[y][x]
            left.add_patch(Rectangle((x, y), 1, 1, color=["#ffffff", "#f8e0c0", "#f0b070", "#d07020"][n],
                                     ec="#cccccc", lw=0.4))
            if n:
                left.text(x + 0.5, y + 0.5, str(n), fontsize=6, ha="center", va="center")
            o = owner[y][x]
            right.add_patch(Rectangle((x, y), 1, 1, color=colours[o] if o >= 0 else "#ffffff", alpha=0.55,
                                      ec="#cccccc", lw=0.4))
    for axes in (left, right):
        for tri in triangles:
            axes.add_patch(Polygon(tri, closed=True, fill=False, ec=INK, lw=0.8))
        axes.set_xlim(0, width)
        axes.set_ylim(0, height)
        axes.set_aspect("equal")
        axes.axis("off")
    left.set_title(f"shaded where the depth test passes:\n{total_left} shader runs (the number: runs per pixel)",
                   fontsize=8)
    right.set_title(f"depth and triangle id first, then shade:\n{total_right} shader runs, one per covered pixel",
                    fontsize=8)
    save(figure, out, "12_visibility_buffer.svg")


def lane_queue(out):
    # One triangle's pixels in four 8x8 blocks (one row of vectors of 16
    # lanes each, two block rows): shaded vector by vector, most lanes idle;
    # queued and compressed, every vector but the last is full.
    tri = ((1.2, 0.6), (30.5, 3.1), (3.4, 7.4))
    pixels = [(x, y) for y in range(8) for x in range(32) if edge_inside(tri, x + 0.5, y + 0.5)]
    lanes = 16
    chunks = []  # per block, per pair of rows: the pixels of the triangle there
    for bx in range(4):
        for pair in range(4):
            chunk = [(x, y) for (x, y) in pixels if bx * 8 <= x < bx * 8 + 8 and 2 * pair <= y < 2 * pair + 2]
            if chunk:
                chunks.append(chunk)
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(8.2, 3.8))
    for i, chunk in enumerate(chunks):
        for lane in range(lanes):
            top.add_patch(Rectangle((lane, -i), 1, 0.8, color=ACCENT if lane < len(chunk) else "#eeeeee",
                                    ec="#999999", lw=0.3))
    queued = len(pixels)
    full = (queued + lanes - 1) // lanes
    for i in range(full):
        for lane in range(lanes):
            used = i * lanes + lane < queued
            bottom.add_patch(Rectangle((lane, -i), 1, 0.8, color=LINE if used else "#eeeeee", ec="#999999", lw=0.3))
    used_top = 100 * queued / (len(chunks) * lanes)
    used_bottom = 100 * queued / (full * lanes)
    for axes, rows, title in (
            (top, len(chunks), f"vector by vector of each block: {len(chunks)} shader runs, {used_top:.0f}% of lanes used"),
            (bottom, full, f"queued and compressed: {full} shader runs, {used_bottom:.0f}% of lanes used")):
        axes.set_xlim(-0.2, lanes + 0.2)
        axes.set_ylim(-rows + 0.6, 1.0)
        axes.set_aspect("equal")
        axes.axis("off")
        axes.set_title(title, fontsize=8)
    figure.suptitle(f"A sliver's {queued} pixels across four 8x8 blocks, 16 lanes a vector (AVX-512 floats)",
                    fontsize=9)
    save(figure, out, "12_lane_queue.svg")


def fragment_queue(out):
    # Eleven tiny triangles, eight of one model and three of the next, each
    # covering a few pixels of a tile: shaded at each triangle's end, or
    # queued as fragments until a vector is full or the model changes.
    lanes = 16
    models = (("the globe", [3, 5, 2, 6, 4, 1, 3, 7]), ("the crate", [4, 6, 2]))
    shades = {0: ("#d04020", "#f0a080"), 1: ("#2060c0", "#90b8f0")}
    figure, (top, bottom) = plt.subplots(1, 2, figsize=(9.0, 3.0),
                                         gridspec_kw={"width_ratios": [1, 1]})

    def lane_row(axes, row, colours):
        for lane in range(lanes):
            colour = colours[lane] if lane < len(colours) else "#eeeeee"
            axes.add_patch(Rectangle((lane, -row), 1, 0.8, color=colour, ec="#999999", lw=0.3))

    # Each triangle alone: one shader run per triangle.
    row = 0
    for m, (_, counts) in enumerate(models):
        for k, count in enumerate(counts):
            lane_row(top, row, [shades[m][k % 2]] * count)
            row += 1
    runs_alone, pixels = row, sum(sum(c) for _, c in models)
    # Carried across triangles: full vectors, flushed at the model change.
    row = 0
    for m, (name, counts) in enumerate(models):
        colours = [shades[m][k % 2] for k, count in enumerate(counts) for _ in range(count)]
        for first in range(0, len(colours), lanes):
            lane_row(bottom, row, colours[first:first + lanes])
            row += 1
        bottom.text(lanes + 0.4, -row + 1.4, "< the model changes" if m == 0 else "< the bin ends",
                    fontsize=7, va="center")
    runs_carried = row
    for axes, rows, title in (
            (top, runs_alone, f"each triangle's last vector shaded at its end:\n"
                              f"{runs_alone} shader runs, {100 * pixels / (runs_alone * lanes):.0f}% of lanes used"),
            (bottom, max(runs_alone, runs_carried), f"fragments carried across the model's triangles:\n"
                                                    f"{runs_carried} shader runs, "
                                                    f"{100 * pixels / (runs_carried * lanes):.0f}% of lanes used")):
        axes.set_xlim(-0.2, lanes + 6.5)
        axes.set_ylim(-rows + 0.6, 1.0)
        axes.set_aspect("equal")
        axes.axis("off")
        axes.set_title(title, fontsize=8)
    figure.suptitle(f"{pixels} pixels of eleven tiny triangles (two models, shades alternate by triangle), "
                    f"{lanes} lanes a vector", fontsize=9)
    save(figure, out, "12_fragment_queue.svg")


def block_rows(out):
    # One 8x8 block and a triangle of a few pixels (8 lanes a vector, AVX2's
    # floats: a vector is one row of the block). Every row tested and walked,
    # or only the rows its box of pixel centres reaches.
    tri = ((2.2, 2.3), (5.9, 2.6), (3.1, 4.4))
    block = 8
    xs = [x for x in range(block) if min(v[0] for v in tri) <= x + 0.5 <= max(v[0] for v in tri)]
    ys = [y for y in range(block) if min(v[1] for v in tri) <= y + 0.5 <= max(v[1] for v in tri)]
    first, last = ys[0], ys[-1]
    figure, panels = plt.subplots(1, 2, figsize=(7.6, 3.9))
    for axes, rows, label in ((panels[0], range(block), "every row"),
                              (panels[1], range(first, last + 1), "only the rows its box reaches")):
        covered = 0
        for y in range(block):
            for x in range(block):
                tested = y in rows
                axes.add_patch(Rectangle((x, y), 1, 1, color=SOFT if tested else "#ffffff", ec="#bbbbbb", lw=0.5))
                if not tested:
                    continue
                inside = edge_inside(tri, x + 0.5, y + 0.5)
                covered += inside
                axes.plot(x + 0.5, y + 0.5, "s" if inside else ".", color=ACCENT if inside else "#888888",
                          ms=5 if inside else 3)
        axes.add_patch(Rectangle((xs[0] + 0.5, first + 0.5), xs[-1] - xs[0], last - first, fill=False, ec=LINE,
                                 lw=1.0, ls="--"))
        axes.add_patch(Polygon(tri, closed=True, fill=False, ec=INK, lw=1.2))
        tests = 3 * block * len(rows)
        axes.set_title(f"{label}: {len(rows)} of 8 rows,\n{tests} edge tests, {len(rows)} vectors of 8 lanes walked "
                       f"({covered} pixels)", fontsize=8)
        axes.set_xlim(-0.2, block + 0.2)
        axes.set_ylim(-0.2, block + 0.2)
        axes.set_aspect("equal")
        axes.axis("off")
    figure.suptitle("A triangle of a few pixels in one 8x8 block (dashed: the box of pixel centres it can cover)",
                    fontsize=9)
    save(figure, out, "12_block_rows.svg")


def shadow_pass(out):
    # One 8-texel block of a shadow map, depth upwards (farther up). A was
    # drawn first and stored its depth plus a negative bias; B, drawn next,
    # lies just in front of A. The block is skipped when B's nearest depth
    # is not nearer than the block's farthest stored depth: compared
    # unbiased, B is skipped though its biased depth would pass; compared
    # with the bias, B is tested and stored.
    a_depth, b_depth, bias = 0.50, 0.48, -0.04
    far = a_depth + bias
    figure, (left, right) = plt.subplots(1, 2, figsize=(8.6, 3.4), sharey=True)
    for axes, bound, title in ((left, b_depth, "bound = B's nearest depth, unbiased:\n"
                                               f"{b_depth:.2f} >= {far:.2f}: block skipped, B lost"),
                               (right, b_depth + bias, "bound = B's nearest depth plus the bias:\n"
                                                       f"{b_depth + bias:.2f} < {far:.2f}: tested, B stored")):
        axes.add_patch(Rectangle((0, 0.40), 8, 0.14, color=SOFT, lw=0))
        axes.plot([0, 8], [a_depth, a_depth], color=INK, lw=1.2, ls=":")
        axes.plot([0, 8], [far, far], color=INK, lw=1.8, label="A + bias: stored (the block's farthest)")
        axes.plot([0, 8], [b_depth, b_depth], color=LINE, lw=1.2, ls=":")
        axes.plot([0, 8], [b_depth + bias, b_depth + bias], color=LINE, lw=1.8, label="B + bias: what B would store")
        axes.plot([4], [bound], "o", color=ACCENT, markersize=6, label="the bound the skip test compares")
        axes.text(8.1, a_depth, "A", fontsize=8, va="center")
        axes.text(8.1, b_depth, "B", fontsize=8, va="center", color=LINE)
        axes.set_xlim(0, 9)
        axes.set_ylim(0.40, 0.54)
        axes.set_xlabel("texels of one 8x8 block's row", fontsize=8)
        axes.set_title(title, fontsize=8)
        axes.tick_params(labelsize=7)
    left.set_ylabel("window depth from the light (farther up)", fontsize=8)
    right.legend(fontsize=6.5, loc="upper left")
    figure.suptitle(f"A shadow map's block with a bias of {bias}: dotted, the unbiased depths", fontsize=9)
    save(figure, out, "12_shadow_pass.svg")


def texel_words(out):
    # Left: the two maps' words of one texel, and the one word that holds
    # both. Right: the gathers one vector of pixels makes when its lanes
    # need two mip levels (trilinear), per texture, before and after.
    figure, (left, right) = plt.subplots(1, 2, figsize=(8.6, 3.4),
                                         gridspec_kw={"width_ratios": [1.3, 1]})
    rows = [(2.4, "normal map", ["R: n.x", "G: n.y", "B: n.z", "A: unused"], [SOFT] * 3 + ["#eeeeee"]),
            (1.4, "specular map", ["R: shine", "G", "B", "A"], ["#fff4c8"] + ["#eeeeee"] * 3),
            (0.0, "packed", ["R: n.x", "G: n.y", "B: n.z", "A: shine"], [SOFT] * 3 + ["#fff4c8"])]
    for y, name, cells, colours in rows:
        left.text(-0.2, y + 0.3, name, ha="right", va="center", fontsize=8)
        for i, (text, colour) in enumerate(zip(cells, colours)):
            left.add_patch(Rectangle((i * 1.4, y), 1.4, 0.6, fc=colour, ec=INK, lw=0.8))
            left.text(i * 1.4 + 0.7, y + 0.3, text, ha="center", va="center", fontsize=7.5)
    left.annotate("", xy=(4.9, 0.6), xytext=(0.7, 1.4), arrowprops=dict(arrowstyle="->", color=ACCENT, lw=1))
    left.text(2.8, -0.45, "bits 0-7, 8-15, 16-23, 24-31 of one 32-bit word", ha="center", fontsize=7.5,
              color=LINE)
    left.set_xlim(-2.0, 5.8)
    left.set_ylim(-0.7, 3.2)
    left.axis("off")
    left.set_title("one texel, as the gathers load it", fontsize=9)
    textures = ["albedo\n(decoded: 2 words)", "normal map", "specular map"]
    before, after = [16, 8, 8], [16, 8, 0]
    x = range(len(textures))
    right.bar([i - 0.18 for i in x], before, width=0.36, color="#bbbbbb", label="before")
    right.bar([i + 0.18 for i in x], after, width=0.36, color=LINE, label="specular in the alpha")
    right.set_xticks(list(x))
    right.set_xticklabels(textures, fontsize=7.5)
    right.set_ylabel("gather instructions per vector of pixels", fontsize=8)
    right.tick_params(labelsize=7)
    right.legend(fontsize=7)
    right.set_title("trilinear, two levels: 32 gathers -> 24", fontsize=9)
    figure.suptitle("The specular map in the normal map's alpha byte: one lookup reads both",
                    fontsize=10)
    save(figure, out, "12_texel_words.svg")


def srgb_entry(out):
    # Left: the two gathers of lesson 06's search (the second waits for the
    # first), and the one gather of a folded entry. Right: one slice of
    # [0, 1) with its step, the worked example of docs/12_fast.md.
    # One above the other: side by side, at the page's width, the boxes were
    # too narrow for their names at a readable size.
    figure, (left, right) = plt.subplots(2, 1, figsize=(7.2, 5.8),
                                         gridspec_kw={"height_ratios": [1.25, 1]})

    def box(x, y, w, text, colour=SOFT):
        left.add_patch(Rectangle((x, y), w, 0.55, fc=colour, ec=INK, lw=0.8))
        left.text(x + w / 2, y + 0.275, text, ha="center", va="center", fontsize=7.5)

    def arrow(x0, x1, y):
        left.annotate("", xy=(x1, y), xytext=(x0, y), arrowprops=dict(arrowstyle="->", color=ACCENT, lw=1))

    left.text(0, 3.05, "before: two gathers, the second waits for the first", fontsize=8, color=LINE)
    box(0, 2.2, 1.3, "slice = 4096 v")
    arrow(1.3, 1.7, 2.475)
    box(1.7, 2.2, 1.5, "gather first[slice]\n(4096 bytes)", "#fff4c8")
    arrow(3.2, 3.6, 2.475)
    box(3.6, 2.2, 1.5, "gather steps[b]\n(256 floats)", "#fff4c8")
    arrow(5.1, 5.4, 2.475)
    box(5.4, 2.2, 0.9, "v >= step?")
    left.text(0, 1.45, "after: one gather of a 32-bit entry per slice", fontsize=8, color=LINE)
    box(0, 0.6, 1.3, "slice = 4096 v")
    arrow(1.3, 1.7, 0.875)
    box(1.7, 0.6, 1.5, "gather entry[slice]", "#fff4c8")
    arrow(3.2, 3.6, 0.875)
    left.add_patch(Rectangle((3.6, 0.6), 0.8, 0.55, fc=SOFT, ec=INK, lw=0.8))
    left.add_patch(Rectangle((4.4, 0.6), 1.9, 0.55, fc="#eeeeee", ec=INK, lw=0.8))
    left.text(4.0, 0.875, "byte", ha="center", va="center", fontsize=7.5)
    left.text(5.35, 0.875, "step within the slice", ha="center", va="center", fontsize=7.5)
    left.text(4.0, 0.38, "bits 24-31", ha="center", fontsize=7, color=LINE)
    left.text(5.35, 0.38, "bits 0-23: fraction x 2^24", ha="center", fontsize=7, color=LINE)
    left.text(3.15, -0.1, "then: (4096 v - slice) >= fraction? (both exact)", ha="center", fontsize=7.5)
    left.set_xlim(-0.1, 6.4)
    left.set_ylim(-0.3, 3.3)
    left.axis("off")
    left.set_title("lesson 06's search for a channel's byte, in vectors", fontsize=9)

    # The worked example: slice 876 holds the step from byte 127 to 128 at
    # 0.7125 of its width.
    step = 0.7125244140625
    right.add_patch(Rectangle((0, 0), step, 0.5, fc=SOFT, ec=INK, lw=0.8))
    right.add_patch(Rectangle((step, 0), 1 - step, 0.5, fc="#fff4c8", ec=INK, lw=0.8))
    right.text(step / 2, 0.25, "byte 127", ha="center", va="center", fontsize=8)
    right.text((1 + step) / 2, 0.25, "128", ha="center", va="center", fontsize=8)
    right.plot([step, step], [-0.15, 0.65], color=ACCENT, lw=1.5)
    right.text(step, 0.72, "step: 0.7125244140625\n(11 954 176 / 2^24)", ha="center", fontsize=7.5,
               color=ACCENT)
    right.text(0, -0.3, "876/4096", ha="center", fontsize=7.5)
    right.text(1, -0.3, "877/4096", ha="center", fontsize=7.5)
    within = 0.7078247
    right.plot([within], [0], marker="^", color=INK)
    right.text(0.42, -0.95, "v = 0.21404: within the slice at 0.7078,\njust below the step: byte 127",
               ha="center", fontsize=7.5)
    right.annotate("", xy=(within, -0.05), xytext=(0.5, -0.55),
                   arrowprops=dict(arrowstyle="->", color=INK, lw=0.8))
    right.set_xlim(-0.6, 1.6)
    right.set_ylim(-1.1, 1.4)
    right.axis("off")
    right.set_title("slice 876 of [0, 1): one step inside it", fontsize=9)
    figure.suptitle("sRGB encoding: lesson 06's two tables folded into one entry per slice", fontsize=10)
    save(figure, out, "12_srgb_entry.svg")


def albedo_word(out):
    # Left: the two words a decoded albedo texel took, and the one it takes.
    # Right: how far each layout's decoded value lies from lesson 06's, per
    # byte, in output levels (the linear width of that byte's sRGB step).
    figure, (left, right) = plt.subplots(1, 2, figsize=(8.8, 3.5),
                                         gridspec_kw={"width_ratios": [1, 1.15]})
    rows = [(2.3, "two words", [(0, 16, "R: 16 bits"), (16, 32, "G: 16 bits")], SOFT),
            (1.55, "", [(0, 16, "B: 16 bits"), (16, 32, "(unused)")], "#eeeeee"),
            (0.3, "one word", [(0, 11, "sqrt R: 11"), (11, 22, "sqrt G: 11"), (22, 32, "sqrt B: 10")], "#fff4c8")]
    for y, name, cells, colour in rows:
        left.text(-1.0, y + 0.3, name, ha="right", va="center", fontsize=8)
        for lo, hi, text in cells:
            left.add_patch(Rectangle((lo, y), hi - lo, 0.6, fc=colour if text != "(unused)" else "#eeeeee",
                                     ec=INK, lw=0.8))
            left.text((lo + hi) / 2, y + 0.3, text, ha="center", va="center", fontsize=7.5)
    left.text(16, -0.25, "bits 0 to 31 of a 32-bit word; decoded: (bits / 2047)^2, blue / 1023", ha="center",
              fontsize=7, color=LINE)
    left.set_xlim(-9, 33)
    left.set_ylim(-0.5, 3.2)
    left.axis("off")
    left.set_title("a decoded albedo texel, as the gathers load it", fontsize=9)

    values = [srgb_to_linear(i / 255) for i in range(256)]
    steps = [srgb_to_linear((k + 0.5) / 255) for k in range(255)]
    widths = [(steps[i] if i < 255 else 1.0) - (steps[i - 1] if i > 0 else 0.0) for i in range(256)]

    def levels_off(decode):
        return [abs(decode(v) - v) / w for v, w in zip(values, widths)]

    layouts = [("16 bits, linear (two words)", lambda v: round(v * 65535) / 65535, "#999999", "-"),
               ("11 bits, linear", lambda v: round(v * 2047) / 2047, ACCENT, ":"),
               ("11 bits, square root", lambda v: (round(math.sqrt(v) * 2047) / 2047) ** 2, LINE, "-"),
               ("10 bits, square root (blue)", lambda v: (round(math.sqrt(v) * 1023) / 1023) ** 2, LINE, "--")]
    for name, decode, colour, style in layouts:  # the worst of each 8 bytes
        off = levels_off(decode)
        worst = [max(off[i:i + 8]) for i in range(0, 256, 8)]
        right.step(range(0, 256, 8), worst, where="post", color=colour, ls=style, lw=1.2, label=name)
    right.set_yscale("log")
    right.set_ylim(1e-5, 3)
    right.axhline(0.5, color="0.5", lw=0.6)
    right.text(250, 0.6, "half a level", ha="right", fontsize=7, color="0.4")
    right.set_xlabel("texel byte (sRGB)", fontsize=8)
    right.set_ylabel("worst error of 8 bytes (output levels)", fontsize=8)
    right.tick_params(labelsize=7)
    right.legend(fontsize=6.5, loc="lower right")
    right.set_title("how far each layout decodes from lesson 06's value", fontsize=9)
    figure.suptitle("The albedo in one word: square roots, so that the bits go where the levels are narrow",
                    fontsize=10)
    save(figure, out, "12_albedo_word.svg")


def shadow_lookup(out):
    # A vector of 8 lanes: pixels of a triangle on the floor, from the lane
    # queue. Each lands at its own point of the shadow map, along a diagonal
    # the light's view turns and stretches; pcf2 reads the 2x2 texels
    # around each point. The lanes' texels are scattered, not one run of a
    # row that a vector load could fetch: lane by lane, lesson 08's lookup.
    figure, (left, right) = plt.subplots(1, 2, figsize=(8.6, 3.6),
                                         gridspec_kw={"width_ratios": [1, 1.25]})
    for x in range(8):
        left.add_patch(Rectangle((x, 0), 1, 1, fc=SOFT, ec=INK, lw=0.8))
        left.text(x + 0.5, 0.5, str(x), ha="center", va="center", fontsize=8)
    left.text(4, 1.35, "one vector: 8 lanes (AVX2), 8 pixels\nof a triangle, from the lane queue", ha="center",
              fontsize=8)
    left.text(4, -0.6, "per lane: position and normal\n(the interpolated varyings)", ha="center",
              fontsize=8, color=LINE)
    left.set_xlim(-0.3, 8.3)
    left.set_ylim(-1.4, 2.2)
    left.set_aspect("equal")
    left.axis("off")
    size = 10
    for i in range(size + 1):
        right.plot([0, size], [i, i], color="#cccccc", lw=0.6)
        right.plot([i, i], [0, size], color="#cccccc", lw=0.6)
    for lane in range(8):  # the light's view turns the row and stretches it
        u, v = 1.3 + 1.05 * lane, 1.6 + 0.85 * lane + 0.25 * (lane % 2)
        x0, y0 = math.floor(u - 0.5), math.floor(v - 0.5)
        right.add_patch(Rectangle((x0, y0), 2, 2, fc="#fff4c8", ec=ACCENT, lw=0.9, alpha=0.9))
        right.plot([u], [v], "o", color=LINE, markersize=4)
        right.text(u + 0.15, v + 0.15, str(lane), fontsize=7, color=LINE)
    right.set_xlim(0, size)
    right.set_ylim(0, size)
    right.set_aspect("equal")
    right.set_xticks([])
    right.set_yticks([])
    right.set_title("the same 8 lanes in the shadow map (pcf2: the 2x2 texels around each)",
                    fontsize=8)
    figure.suptitle("The second pass's lookup: each lane's texels lie in its own place of the map; "
                    "each lane runs lesson 08's visibility()", fontsize=9)
    save(figure, out, "12_shadow_lookup.svg")


def frame_path(out):
    # The viewer's loop as boxes: the input changes plain state, the state
    # draws a frame in memory (bottom row first), and the frame goes to the
    # window through SDL, its rows mirrored by the copy, not on the CPU.
    figure, axes = plt.subplots(figsize=(8.6, 3.2))
    boxes = [  # (x, y, text, file, colour)
        (0.0, 1.6, "events\n(SDL_PollEvent)", "sdl_window.cpp", SOFT),
        (2.3, 1.6, "keys, drags,\nwheel", "sdl_window.cpp", SOFT),
        (4.6, 1.6, "Settings + Orbit\n(plain data)", "controls.cpp", SOFT),
        (6.9, 1.6, "FrameRenderer:\nfast path, 07 or 08", "frame_renderer.cpp", "#fff4c8"),
        (6.9, 0.0, "upload the frame\n(SDL_UpdateTexture)", "sdl_window.cpp", SOFT),
        (4.6, 0.0, "copy, rows flipped\n(SDL_RenderCopyEx)", "sdl_window.cpp", "#f8dcd4"),
        (2.3, 0.0, "present\n(SDL_RenderPresent)", "sdl_window.cpp", SOFT),
        (0.0, 0.0, "the window\n(top row first)", "", SOFT),
    ]
    width, height = 1.9, 0.9
    for x, y, text, source, colour in boxes:
        axes.add_patch(Rectangle((x, y), width, height, fc=colour, ec=INK, lw=0.8))
        axes.text(x + width / 2, y + height / 2, text, ha="center", va="center", fontsize=9)
        if source:
            axes.text(x + width / 2, y - 0.12, source, ha="center", va="top", fontsize=8,
                      color=LINE)
    arrow = dict(arrowstyle="->", color=INK, lw=1)
    for (x0, y0, *_), (x1, y1, *_) in zip(boxes, boxes[1:]):
        if y0 == y1:  # along a row: from one box's side to the next one's
            start = (x0 + width, y0 + height / 2) if x1 > x0 else (x0, y0 + height / 2)
            end = (x1, y1 + height / 2) if x1 > x0 else (x1 + width, y1 + height / 2)
        else:  # down the right-hand side
            start, end = (x0 + width / 2, y0 - 0.35), (x1 + width / 2, y1 + height)
        axes.annotate("", xy=end, xytext=start, arrowprops=arrow)
    axes.text(7.85, 2.75, "the frame in memory: bottom row first (OpenGL's way)", ha="center",
              fontsize=9, color=ACCENT)
    axes.text(5.55, -0.75, "the one flip: without it the picture is upside down", ha="center",
              fontsize=9, color=ACCENT)
    axes.set_xlim(-0.2, 9.0)
    axes.set_ylim(-1.0, 3.0)
    axes.axis("off")
    axes.set_title("One frame of the viewer, from the keyboard to the window", fontsize=10)
    save(figure, out, "13_frame_path.svg")


def cube_faces(out):
    figure, (left, right) = plt.subplots(1, 2, figsize=(9, 4.2))
    # Left: the cube seen from above (+y), x to the right and so +z down the
    # page: the side faces and the face a direction points into.
    left.add_patch(Rectangle((-1, -1), 2, 2, fill=False, color=INK, lw=1.4))
    for sx, sz in ((1, 1), (1, -1)):
        left.plot([-1.0 * sx, 1.0 * sx], [-1.0 * sz, 1.0 * sz], color="#bbbbbb", lw=0.8, ls="--")
    for label, (x, y) in {"+x": (1.12, 0), "-x": (-1.12, 0), "-z": (0, 1.12), "+z": (0, -1.12)}.items():
        left.text(x, y, label, ha="center", va="center", fontsize=9, color=INK)
    dx, dz = 0.9, 0.45  # a direction whose largest part is x: the +x face, z / x = 0.5 below centre
    hit = (1.0, -dz / dx)
    left.annotate("", hit, (0, 0), arrowprops=dict(arrowstyle="->", color=ACCENT, lw=1.6))
    left.plot(*hit, "o", color=ACCENT, ms=5)
    left.text(0.45, -0.12, "d", color=ACCENT, fontsize=9, va="bottom")
    left.text(1.12, hit[1] - 0.05, "z / x = 0.5\nu = (0.5 + 1) / 2 = 0.75", fontsize=8,
              color=ACCENT, va="top")
    left.text(0, -1.55, "seen from above, d = (0.9, y, 0.45): the largest |component| picks the\n"
              "face, the other two divided by it place the point on it (dashed: the ties)",
              ha="center", fontsize=8)
    bare(left, (-1.8, 2.6), (-1.9, 1.5))
    # Right: the six faces unfolded around -z, each as seen from inside, v up.
    net = {"+y": (1, 2), "-x": (0, 1), "-z": (1, 1), "+x": (2, 1), "+z": (3, 1), "-y": (1, 0)}
    for label, (col, row) in net.items():
        right.add_patch(Rectangle((col, row), 1, 1, facecolor=SOFT, edgecolor=INK, lw=1.0))
        right.text(col + 0.5, row + 0.5, label, ha="center", va="center", fontsize=10)
        right.annotate("", (col + 0.9, row + 0.1), (col + 0.1, row + 0.1),
                       arrowprops=dict(arrowstyle="->", color=LINE, lw=0.9))
        right.annotate("", (col + 0.1, row + 0.9), (col + 0.1, row + 0.1),
                       arrowprops=dict(arrowstyle="->", color=LINE, lw=0.9))
    right.text(1.55, 1.12, "u", color=LINE, fontsize=7)
    right.text(1.13, 1.55, "v", color=LINE, fontsize=7)
    right.text(2.0, -0.35, "unfolded, each face as seen from inside the cube: +z is behind the camera",
               ha="center", fontsize=8)
    bare(right, (-0.2, 4.2), (-0.6, 3.1))
    save(figure, out, "09_cube_faces.svg")


def latlong(out):
    figure, axes = plt.subplots(figsize=(8, 4.4))
    axes.add_patch(Rectangle((0, 0), 2, 1, facecolor=SOFT, edgecolor=INK, lw=1.2))
    for k in range(1, 8):
        axes.plot([k / 4, k / 4], [0, 1], color="#bbbbbb", lw=0.6)
    for k in range(1, 4):
        axes.plot([0, 2], [k / 4, k / 4], color="#bbbbbb", lw=0.6)
    axes.plot([0, 2], [0.5, 0.5], color=INK, lw=0.9)
    for u, label in ((0.0, "+z\n(u = 0)"), (0.5, "-x"), (1.0, "-z\n(u = 0.5)"), (1.5, "+x"), (2.0, "+z\n(u = 1)")):
        axes.text(u, -0.05, label, ha="center", va="top", fontsize=8)
    axes.text(-0.05, 1.0, "up (v = 1)", ha="right", va="center", fontsize=8)
    axes.text(-0.05, 0.5, "horizon", ha="right", va="center", fontsize=8)
    axes.text(-0.05, 0.0, "down (v = 0)", ha="right", va="center", fontsize=8)
    # The top row: all of it is one point of the sphere.
    axes.add_patch(Rectangle((0, 15 / 16), 2, 1 / 16, facecolor="#f3c9bd", edgecolor=ACCENT, lw=0.8))
    axes.text(1.0, 1.08, "the top edge (v = 1) is one point, the zenith, stretched over the full width;\n"
              "the row of texels under it is a thin cap around that point", ha="center", fontsize=8,
              color=ACCENT)
    axes.annotate("", (2.0, 0.3), (1.9, 0.3), arrowprops=dict(arrowstyle="->", color=LINE))
    axes.annotate("", (0.0, 0.3), (0.1, 0.3), arrowprops=dict(arrowstyle="->", color=LINE))
    axes.text(1.0, 0.3, "u = 0 and u = 1 are the same longitude: the seam wraps", ha="center",
              fontsize=8, color=LINE)
    axes.text(1.0, -0.42, "u = 1/2 + atan2(x, -z) / 2 pi          v = 1/2 + asin(y) / pi",
              ha="center", fontsize=9)
    bare(axes, (-0.5, 2.2), (-0.55, 1.3))
    save(figure, out, "09_latlong.svg")


def reflect_refract(out):
    figure, axes = plt.subplots(figsize=(6.5, 4.2))
    axes.add_patch(Rectangle((-2.2, -1.8), 4.4, 1.8, color=SOFT))
    axes.plot([-2.2, 2.2], [0, 0], color=INK, lw=1.5)
    axes.text(-2.1, 0.08, "air, n1 = 1", fontsize=8, va="bottom")
    axes.text(-2.1, -0.1, "glass, n2 = 1.5", fontsize=8, va="top")
    theta_i = math.radians(50)
    theta_t = math.asin(math.sin(theta_i) / 1.5)
    axes.annotate("", (0, 1.5), (0, 0), arrowprops=dict(arrowstyle="->", color=INK, lw=1.4))
    axes.text(0.05, 1.5, "n", fontsize=9)
    eye = (-1.5 * math.sin(theta_i), 1.5 * math.cos(theta_i))
    axes.annotate("", (0, 0), eye, arrowprops=dict(arrowstyle="->", color=LINE, lw=1.6))
    axes.text(eye[0] - 0.05, eye[1], "from the eye: -v", color=LINE, fontsize=8, ha="right")
    r = (1.5 * math.sin(theta_i), 1.5 * math.cos(theta_i))
    axes.annotate("", r, (0, 0), arrowprops=dict(arrowstyle="->", color=ACCENT, lw=1.6, ls="--"))
    axes.text(r[0] + 0.05, r[1], "r = reflect(-v, n)\nshare F (Schlick)", color=ACCENT, fontsize=8)
    t = (1.5 * math.sin(theta_t), -1.5 * math.cos(theta_t))
    axes.annotate("", t, (0, 0), arrowprops=dict(arrowstyle="->", color="#208040", lw=1.6))
    axes.text(t[0] + 0.05, t[1], "t: bent towards n\nshare 1 - F", color="#208040", fontsize=8)
    axes.text(-0.45, 0.55, f"{math.degrees(theta_i):.0f}°", fontsize=8)
    axes.text(0.08, -0.55, f"{math.degrees(theta_t):.1f}°", fontsize=8)
    axes.text(0, -1.95, "Snell: n1 sin 50° = n2 sin 30.7°;   F = F0 + (1 - F0)(1 - cos 50°)^5 = 0.046,"
              "  F0 = ((1.5 - 1) / (1.5 + 1))^2 = 0.04", ha="center", fontsize=7.5)
    bare(axes, (-2.3, 2.4), (-2.1, 1.8))
    save(figure, out, "09_reflect_refract.svg")


def microfacets(out):
    figure, axes = plt.subplots(figsize=(6.5, 3.6))
    # A saw-tooth surface: facet k runs from x[k] to x[k + 1].
    xs = [-2.4 + 0.4 * k for k in range(13)]
    ys = [0.0, 0.28, 0.02, 0.2, -0.05, 0.32, 0.05, 0.12, -0.02, 0.3, 0.0, 0.18, 0.02]
    axes.add_patch(Polygon(list(zip(xs, ys)) + [(xs[-1], -0.6), (xs[0], -0.6)], color=SOFT))
    axes.plot(xs, ys, color=INK, lw=1.2)
    axes.plot([-2.5, 2.5], [0.08, 0.08], color=INK, lw=0.8, ls=":")
    axes.annotate("", (0, 1.55), (0, 0.08), arrowprops=dict(arrowstyle="->", color=INK, lw=1.4))
    axes.text(0.05, 1.5, "n (the surface's)", fontsize=8)
    v = (-math.sin(math.radians(40)), math.cos(math.radians(40)))
    l = (math.sin(math.radians(62)), math.cos(math.radians(62)))
    axes.annotate("", (1.5 * v[0], 0.08 + 1.5 * v[1]), (0, 0.08),
                  arrowprops=dict(arrowstyle="->", color=LINE, lw=1.6))
    axes.text(1.5 * v[0] - 0.05, 0.1 + 1.5 * v[1], "v (to the eye)", color=LINE, fontsize=8, ha="right")
    axes.annotate("", (1.5 * l[0], 0.08 + 1.5 * l[1]), (0, 0.08),
                  arrowprops=dict(arrowstyle="->", color=ACCENT, lw=1.6))
    axes.text(1.5 * l[0] + 0.05, 0.1 + 1.5 * l[1], "l (to the light)", color=ACCENT, fontsize=8)
    hx, hy = v[0] + l[0], v[1] + l[1]
    norm = math.hypot(hx, hy)
    h = (hx / norm, hy / norm)
    axes.annotate("", (1.2 * h[0], 0.08 + 1.2 * h[1]), (0, 0.08),
                  arrowprops=dict(arrowstyle="->", color="#208040", lw=1.4, ls="--"))
    axes.text(1.2 * h[0] + 0.05, 0.1 + 1.2 * h[1], "h", color="#208040", fontsize=9)
    # The facets whose normals are closest to h mirror l into v: drawn green.
    def facing(k):
        dx, dy = xs[k + 1] - xs[k], ys[k + 1] - ys[k]
        return (-dy * h[0] + dx * h[1]) / math.hypot(dx, dy)
    for k in sorted(range(12), key=facing)[-3:]:
        axes.plot(xs[k:k + 2], ys[k:k + 2], color="#208040", lw=3)
    axes.text(-2.45, -0.35, "green: facets facing h (GGX's D counts them)", fontsize=7.5, color="#208040")
    axes.text(-2.45, -0.5, "f = D G F / (4 (n.l)(n.v)): G takes out the facets hidden from l (shadowed) "
              "or from v (masked);\nF is each facet's mirror share (Schlick)", fontsize=7.5, va="top")
    axes.annotate("shadowed: a ridge\nblocks the light", (1.15, 0.1), (1.75, 0.45), fontsize=7.5,
                  arrowprops=dict(arrowstyle="->", color=INK, lw=0.8))
    axes.annotate("masked: the eye\ncannot see it", (-1.4, 0.12), (-2.3, 0.75), fontsize=7.5,
                  arrowprops=dict(arrowstyle="->", color=INK, lw=0.8))
    bare(axes, (-2.55, 2.55), (-0.85, 1.7))
    save(figure, out, "09_microfacets.svg")


def ggx_one_bounce(v_angle, l_angle, alpha):
    """f(v, l) n.l for a white metal (F = 1) in the plane of v, n and l."""
    if abs(l_angle) >= math.pi / 2:
        return 0.0
    nv, nl = math.cos(v_angle), math.cos(l_angle)
    h_angle = 0.5 * (v_angle + l_angle)
    nh = math.cos(h_angle)
    a2 = alpha * alpha
    d = a2 / (math.pi * (nh * nh * (a2 - 1) + 1) ** 2)

    def lam(c):
        return 0.5 * (math.sqrt(1 + a2 * (1 - c * c) / (c * c)) - 1)

    g = 1 / (1 + lam(nv) + lam(nl))
    return d * g / (4 * nv)


def lobe_lean(out):
    figure, panels = plt.subplots(1, 2, figsize=(6.5, 3.2))
    for axes, view_degrees in zip(panels, (0, 75)):
        v_angle = math.radians(-view_degrees)  # the eye on the left
        alpha = 0.6 ** 2
        angles = [math.radians(-89.5 + 0.5 * k) for k in range(359)]
        values = [ggx_one_bounce(v_angle, a, alpha) for a in angles]
        peak = max(values)
        xs = [math.sin(a) * f / peak for a, f in zip(angles, values)]
        ys = [math.cos(a) * f / peak for a, f in zip(angles, values)]
        axes.fill(xs + [0], ys + [0], color=SOFT)
        axes.plot(xs, ys, color=LINE, lw=1.4, label="the true lobe")
        # The lobe's mean direction, each direction weighted by its value.
        mean_x = sum(math.sin(a) * f for a, f in zip(angles, values))
        mean_y = sum(math.cos(a) * f for a, f in zip(angles, values))
        best = math.atan2(mean_x, mean_y)
        r_angle = -v_angle
        axes.plot([-1.1, 1.1], [0, 0], color=INK, lw=1.2)
        axes.annotate("", (0, 1.05), (0, 0), arrowprops=dict(arrowstyle="->", color=INK, lw=1))
        axes.annotate("", (math.sin(v_angle), math.cos(v_angle)), (0, 0),
                      arrowprops=dict(arrowstyle="->", color=INK, lw=1))
        axes.annotate("", (math.sin(r_angle), math.cos(r_angle)), (0, 0),
                      arrowprops=dict(arrowstyle="->", color=ACCENT, lw=1.4, ls="--"))
        if view_degrees == 0:  # v, n and r are one arrow: one name
            axes.text(0.05, 1.0, "n = v = r", fontsize=8)
        else:
            axes.text(0.03, 1.0, "n", fontsize=8)
            axes.text(math.sin(v_angle) - 0.02, math.cos(v_angle) + 0.03, "v", fontsize=8, ha="right")
            axes.text(math.sin(r_angle) + 0.02, math.cos(r_angle), "r", fontsize=8, color=ACCENT)
        axes.plot([0, 0.95 * math.sin(best)], [0, 0.95 * math.cos(best)], color=LINE, lw=1, ls=":")
        axes.set_title(f"seen {view_degrees}° from n: r is {abs(math.degrees(r_angle)):.0f}° from n,\n"
                       f"the lobe's mean {abs(math.degrees(best)):.0f}° (dotted)", fontsize=8)
        bare(axes, (-1.15, 1.15), (-0.1, 1.15))
    figure.text(0.5, 0.02, "roughness 0.6, white metal: f(v, l) n.l in the plane of v and n (blue).\n"
                "The prefilter centres its lobe on r: right head-on, wrong at a slant.", ha="center", fontsize=7.5)
    save(figure, out, "09_lobe_lean.svg")


def one_bounce_albedo(n_dot_v, roughness, count=512):
    """The BRDF's half of the split sum for F = 1, by importance sampling GGX's
    facet normals (angles from the normal stratified, turns by the golden
    ratio): each ray weighs G (v.h) / ((n.h)(n.v)), as in the program's table."""
    alpha = roughness * roughness
    a2 = alpha * alpha
    v = (math.sqrt(1 - n_dot_v * n_dot_v), 0.0, n_dot_v)

    def lam(c):
        return 0.5 * (math.sqrt(1 + a2 * (1 - c * c) / (c * c)) - 1)

    total = 0.0
    for k in range(count):
        u = (k + 0.5) / count
        cos_t = math.sqrt((1 - u) / (1 + (a2 - 1) * u))
        sin_t = math.sqrt(max(0.0, 1 - cos_t * cos_t))
        phi = 2 * math.pi * ((k * 0.6180339887) % 1.0)
        h = (sin_t * math.cos(phi), sin_t * math.sin(phi), cos_t)
        v_dot_h = v[0] * h[0] + v[1] * h[1] + v[2] * h[2]
        l_z = 2 * v_dot_h * h[2] - v[2]
        if l_z <= 0 or v_dot_h <= 0:
            continue
        g = 1 / (1 + lam(n_dot_v) + lam(l_z))
        total += g * v_dot_h / (h[2] * n_dot_v)
    return total / count


def split_sum(out):
    figure, (left, right) = plt.subplots(1, 2, figsize=(6.5, 3.2), gridspec_kw={"width_ratios": [1, 1.15]})
    steps = 16
    grid = [[one_bounce_albedo((i + 0.5) / steps, (j + 0.5) / steps) for i in range(steps)]
            for j in range(steps)]
    image = left.imshow(grid, origin="lower", extent=(0, 1, 0, 1), cmap="viridis", vmin=0, vmax=1)
    left.set_xlabel("n.v", fontsize=8)
    left.set_ylabel("roughness", fontsize=8)
    left.tick_params(labelsize=7)
    left.set_title("the BRDF's half: one bounce's albedo\n(A + B; F0 A + B for a metal), a table", fontsize=8)
    figure.colorbar(image, ax=left, fraction=0.046, pad=0.04).ax.tick_params(labelsize=7)
    # The light's half: the prefilter's kernel around r (n = v = r), D(h) n.l
    # in the plane, for each blurred level's roughness.
    for roughness, colour in ((0.2, "#1b9e77"), (0.4, "#d95f02"), (0.6, "#7570b3"), (0.8, "#e7298a"),
                              (1.0, "#66a61e")):
        alpha = roughness * roughness
        a2 = alpha * alpha
        angles = [math.radians(-89.5 + 0.5 * k) for k in range(359)]
        values = []
        for a in angles:
            n_dot_h = math.cos(a / 2)
            values.append(a2 / (math.pi * (n_dot_h * n_dot_h * (a2 - 1) + 1) ** 2) * math.cos(a))
        peak = max(values)
        xs = [math.sin(a) * f / peak for a, f in zip(angles, values)]
        ys = [math.cos(a) * f / peak for a, f in zip(angles, values)]
        right.plot(xs, ys, color=colour, lw=1.3, label=f"roughness {roughness:g}")
    right.annotate("", (0, 1.08), (0, 0), arrowprops=dict(arrowstyle="->", color=INK, lw=1))
    right.text(0.03, 1.05, "r (= n = v)", fontsize=7.5)
    right.plot([-1.1, 1.1], [0, 0], color=INK, lw=0.8)
    right.legend(fontsize=6.5, loc="upper right", frameon=False, bbox_to_anchor=(1.12, 1.0))
    right.set_title("the light's half: the environment blurred by\neach level's lobe around r (peaks scaled to 1)",
                    fontsize=8)
    bare(right, (-1.15, 1.15), (-0.05, 1.15))
    save(figure, out, "09_split_sum.svg")


def gbuffer_passes(out):
    # Lesson 10's frame as data flow: the triangles are drawn once into four
    # images (the G-buffer); the occlusion pass reads only depth and normal,
    # the blur reads the occlusion and the same two, and the picture reads
    # direct light, albedo and the blurred occlusion. Each image's bytes a
    # pixel under its name (float colours: 12, depth: 4).
    figure, axes = plt.subplots(figsize=(7.4, 3.3))
    width, height = 1.7, 0.62
    def box(x, y, text, colour=SOFT, note=""):
        axes.add_patch(Rectangle((x, y), width, height, fc=colour, ec=INK, lw=0.8))
        axes.text(x + width / 2, y + height / 2, text, ha="center", va="center", fontsize=9)
        if note:
            axes.text(x + width / 2, y - 0.08, note, ha="center", va="top", fontsize=7.5, color=LINE)
    def arrow(start, end, colour=INK):
        axes.annotate("", xy=end, xytext=start, arrowprops=dict(arrowstyle="->", color=colour, lw=0.9))
    box(0.0, 1.5, "triangles\n+ shadow map", SOFT, "lesson 08's models and light")
    images = [("direct light", 3.0, "12 bytes"), ("albedo", 2.15, "12 bytes"),
              ("normal", 1.3, "12 bytes"), ("depth", 0.45, "4 bytes")]
    for name, y, size in images:
        box(2.6, y, name, "#fff4c8", size)
        arrow((1.7, 1.81), (2.6, y + height / 2))
    axes.text(3.45, 3.85, "the G-buffer: one pass, four images", ha="center", fontsize=9, color=ACCENT)
    box(5.0, 0.85, "occlusion\n(a method)", SOFT, "depth + normal only")
    arrow((4.3, 1.3 + height / 2), (5.0, 0.85 + height * 0.65))
    arrow((4.3, 0.45 + height / 2), (5.0, 0.85 + height * 0.35))
    box(7.3, 0.85, "blur within\none surface", SOFT, "occlusion, depth, normal")
    arrow((6.7, 0.85 + height / 2), (7.3, 0.85 + height / 2))
    box(7.3, 2.6, "picture", "#f8dcd4", "")
    axes.text(7.3 + width / 2, 2.6 + height + 0.08, "direct + ambient x albedo x A", ha="center",
              va="bottom", fontsize=7.5, color=LINE)
    arrow((8.15, 0.85 + height), (8.15, 2.6))
    arrow((4.3, 3.0 + height / 2), (7.3, 2.6 + height * 0.75))
    arrow((4.3, 2.15 + height / 2), (7.3, 2.6 + height * 0.3))
    axes.set_xlim(-0.1, 9.1)
    axes.set_ylim(0.2, 4.0)
    axes.axis("off")
    axes.set_title("Lesson 10's frame: the scene drawn once, then passes over images", fontsize=10)
    save(figure, out, "10_gbuffer.svg")


# Lesson 11's sample patterns, offsets from the pixel's centre in pixels,
# window y up: the ordered grid, the rotated grid, and Direct3D's standard
# 8 and 16 (published in sixteenths, y down; the same tables as
# lessons/11_antialiasing/sample_pattern.cpp).
AA_PATTERNS = [
    ("ordered grid, 4", [((i + 0.5) / 2 - 0.5, (j + 0.5) / 2 - 0.5) for j in range(2) for i in range(2)]),
    ("rotated grid, 4", [(0.125, 0.375), (-0.375, 0.125), (-0.125, -0.375), (0.375, -0.125)]),
    ("standard, 8", [(x / 16, -y / 16) for x, y in ((1, -3), (-1, 3), (5, 1), (-3, -5), (-5, 5), (-7, -1),
                                                     (3, 7), (7, -7))]),
    ("standard, 16", [(x / 16, -y / 16) for x, y in ((1, 1), (-1, -3), (-3, 2), (4, -1), (-5, -2), (2, 5), (5, 3),
                                                      (3, -5), (-2, 6), (0, -7), (-4, -6), (-6, 4), (-8, 0),
                                                      (7, -4), (6, 7), (-7, -8))]),
]


def aa_patterns(out):
    # Each pattern in one pixel, and the rows its samples stand on (dotted):
    # a nearly horizontal edge moving up through the pixel covers the
    # samples one row at a time, so the pixel takes as many shades as the
    # pattern has rows (+1).
    figure, panels = plt.subplots(1, 4, figsize=(8.4, 2.6))
    for axes, (title, points) in zip(panels, AA_PATTERNS):
        axes.add_patch(Rectangle((-0.5, -0.5), 1, 1, fill=False, ec=INK, lw=1))
        for y in sorted({round(p[1], 4) for p in points}):
            axes.plot([-0.5, 0.5], [y, y], color=LINE, lw=0.5, ls=":")
        axes.plot([p[0] for p in points], [p[1] for p in points], "o", color=ACCENT, ms=4)
        axes.plot([0], [0], "+", color=INK, ms=6)
        rows = len({round(p[1], 4) for p in points})
        axes.set_title(f"{title}\n{rows} rows: {rows + 1} shades", fontsize=8.5)
        axes.set_xlim(-0.6, 0.6)
        axes.set_ylim(-0.6, 0.6)
        axes.set_aspect("equal")
        axes.axis("off")
    figure.suptitle("Where a pixel's samples lie (+: the centre)", fontsize=10)
    save(figure, out, "11_patterns.svg")


def aa_shading_rate(out):
    # One pixel, a triangle's edge crossing it (the triangle to the lower
    # left). Supersampling shades every covered sample; multisampling tests
    # every sample but shades once: at the centre (here outside the
    # triangle: its values extrapolated) or at the covered samples' centroid.
    points = AA_PATTERNS[2][1]
    inside = [p for p in points if p[0] + p[1] < -0.15]  # below the line x + y = -0.15
    centroid = (sum(p[0] for p in inside) / len(inside), sum(p[1] for p in inside) / len(inside))
    figure, panels = plt.subplots(1, 2, figsize=(6.4, 3.0))
    for axes, title in zip(panels, ("supersampling: each covered sample shaded",
                                    "multisampling: coverage per sample, one shading")):
        axes.add_patch(Polygon([(-0.5, 0.35), (-0.5, -0.5), (0.35, -0.5)], closed=True, fc="#fff4c8", ec="none"))
        axes.plot([-0.5, 0.35], [0.35, -0.5], color=INK, lw=1)
        axes.add_patch(Rectangle((-0.5, -0.5), 1, 1, fill=False, ec=INK, lw=1))
        outside = [p for p in points if p not in inside]
        axes.plot([p[0] for p in outside], [p[1] for p in outside], "o", mfc="white", mec=LINE, ms=5)
        if title.startswith("super"):
            axes.plot([p[0] for p in inside], [p[1] for p in inside], "o", color=ACCENT, ms=5)
            axes.text(0, -0.62, f"{len(inside)} fragment runs, each at its sample", ha="center", fontsize=8)
        else:
            axes.plot([p[0] for p in inside], [p[1] for p in inside], "s", mfc="white", mec=ACCENT, ms=5)
            axes.plot([0], [0], "*", color=LINE, ms=9)
            axes.text(0.03, 0.06, "centre", fontsize=7.5, color=LINE)
            axes.plot([centroid[0]], [centroid[1]], "*", color=ACCENT, ms=9)
            axes.text(centroid[0] + 0.03, centroid[1] + 0.05, "centroid", fontsize=7.5, color=ACCENT)
            axes.text(0, -0.62, "1 fragment run, stored in the covered samples", ha="center", fontsize=8)
        axes.set_title(title, fontsize=8.5)
        axes.set_xlim(-0.6, 0.6)
        axes.set_ylim(-0.7, 0.6)
        axes.set_aspect("equal")
        axes.axis("off")
    save(figure, out, "11_shading_rate.svg")


def ao_kernel_panel(axes, title, half):
    """A floor point p beside a box, seen from the side; the eye up and to the left."""
    axes.add_patch(Rectangle((-1.6, -0.3), 3.4, 0.3, color=SOFT))
    axes.plot([-1.6, 1.8], [0, 0], color=INK, lw=1.2)
    axes.add_patch(Rectangle((0.55, 0), 0.9, 0.9, facecolor="#d8d8d8", edgecolor=INK, lw=1.2))
    axes.add_patch(plt.Circle((0, 0), 1.0, fill=False, ls="--", color=INK, lw=0.8))
    points = [(math.cos(a) * r, math.sin(a) * r)
              for a, r in [(0.3, 0.8), (1.0, 0.55), (2.0, 0.7), (2.6, 0.4), (0.15, 0.35),
                           (-0.5, 0.6), (-1.9, 0.5), (-2.7, 0.8), (-1.2, 0.3), (1.5, 0.9)]]
    hidden = 0
    for x, y in points:
        if half and y < 0:
            continue
        inside_box = 0.55 <= x <= 1.45 and 0 <= y <= 0.9
        below = y < 0
        closed = inside_box or below
        hidden += closed
        axes.plot(x, y, "o", ms=5, color=ACCENT if closed else LINE)
    axes.plot(0, 0, "o", ms=6, color=INK)
    axes.text(0, -0.15, "p", ha="center", va="top", fontsize=9)
    shown = sum(1 for x, y in points if not half or y >= 0)
    axes.set_title(f"{title}\n{hidden} of {shown} samples hidden", fontsize=9)
    axes.set_xlim(-1.7, 1.9)
    axes.set_ylim(-1.1, 1.2)
    axes.set_aspect("equal")
    axes.axis("off")


def ao_kernels(out):
    figure, (left, middle, right) = plt.subplots(1, 3, figsize=(10, 3.6))
    ao_kernel_panel(left, "Crytek: a ball, no normal", half=False)
    ao_kernel_panel(middle, "hemisphere: the half ball above n", half=True)
    # The range check: a near object's edge in front of p on screen.
    right.add_patch(Rectangle((-1.6, -0.3), 3.4, 0.3, color=SOFT))
    right.plot([-1.6, 1.8], [0, 0], color=INK, lw=1.2)
    right.add_patch(Rectangle((-0.9, 1.6), 0.7, 0.5, facecolor="#d8d8d8", edgecolor=INK, lw=1.2))
    eye = (-1.5, 2.9)
    right.plot(*eye, "s", color=INK)
    right.text(eye[0] + 0.1, eye[1], "eye", fontsize=8, va="center")
    sample = (0.35, 0.35)
    right.plot([eye[0], sample[0]], [eye[1], sample[1]], color=LINE, lw=0.8, ls=":")
    right.plot(*sample, "o", ms=5, color=ACCENT)
    right.plot(0, 0, "o", ms=6, color=INK)
    right.text(0, -0.15, "p", ha="center", va="top", fontsize=9)
    right.add_patch(plt.Circle((0, 0), 0.6, fill=False, ls="--", color=INK, lw=0.8))
    right.annotate("the depth buffer here holds the box:\nnearer than the sample, so 'hidden';\n"
                   "but the box is far from p (gap > radius):\nthe range check lets it count ~0",
                   (-0.45, 1.6), (0.1, 1.25), fontsize=7.5, arrowprops=dict(arrowstyle="->", lw=0.8))
    right.set_title("the range check: no halo from a far edge", fontsize=9)
    right.set_xlim(-1.7, 1.9)
    right.set_ylim(-0.75, 3.2)  # the whole of the dashed ball
    right.set_aspect("equal")
    right.axis("off")
    save(figure, out, "10_kernels.svg")


def ao_horizon(out):
    figure, axes = plt.subplots(figsize=(6.4, 3.9))
    # The slice: the plane through the eye direction v (up) and a screen direction t (across).
    ground = [(-2.2, 0.0), (-0.9, 0.0), (-0.6, 0.0), (0.0, 0.0), (0.8, 0.0), (1.0, 0.0), (1.0, 0.9), (1.6, 0.9), (1.6, 0.0), (2.3, 0.0)]
    ground = [(x, y - 0.15 * x) for x, y in ground]  # a slope: the normal leans
    axes.add_patch(Polygon(ground + [(2.3, -0.8), (-2.2, -0.8)], color=SOFT))
    axes.plot([x for x, _ in ground], [y for _, y in ground], color=INK, lw=1.4)
    slope = math.atan(-0.15)
    n = (-math.sin(slope), math.cos(slope))
    gamma = math.atan2(n[0], n[1])
    corner = ground[6]
    h2 = math.atan2(corner[0], corner[1])  # from v (up), towards +t
    h1 = gamma - math.pi / 2  # nothing on the left: the tangent plane bounds it
    r = 1.7
    for angle, label, colour in [(h1, "h1 (the tangent plane)", LINE), (h2, "h2 (the box's corner)", ACCENT)]:
        axes.plot([0, r * math.sin(angle)], [0, r * math.cos(angle)], color=colour, lw=1.3)
        axes.text(r * math.sin(angle) * 1.04, r * math.cos(angle) * 1.04 + 0.15, label, color=colour,
                  fontsize=8, ha="left" if angle > 0 else "right")
    arc = [h1 + (h2 - h1) * i / 60 for i in range(61)]
    axes.fill([0] + [0.7 * math.sin(a) for a in arc], [0] + [0.7 * math.cos(a) for a in arc],
              color="#c8dcf4", zorder=0)
    axes.annotate("", (0, 1.5), (0, 0), arrowprops=dict(arrowstyle="->", color=INK, lw=1.4))
    axes.text(0.05, 1.55, "v (to the eye)", fontsize=8)
    axes.annotate("", (1.2 * n[0], 1.2 * n[1]), (0, 0), arrowprops=dict(arrowstyle="->", color="#208040", lw=1.4))
    axes.text(1.2 * n[0] + 0.05, 1.2 * n[1] - 0.1, "n", color="#208040", fontsize=9)
    axes.text(-0.1, 0.38, "open", fontsize=8, ha="right")
    axes.text(0, -1.0, "open share of the slice = the cosine-weighted integral from h1 to h2\n"
              "(closed form in gamma, the angle from v to n); averaged over slices turned about v",
              ha="center", fontsize=7.5)
    axes.plot(0, 0, "o", color=INK, ms=5)
    axes.set_xlim(-2.3, 2.4)
    axes.set_ylim(-1.2, 2.0)
    axes.set_aspect("equal")
    axes.axis("off")
    save(figure, out, "10_horizon.svg")


def cosine_sampling(out):
    """Malley's method: points spread evenly over the unit disc (r = sqrt(u),
    phi = 2 pi v), lifted straight up onto the hemisphere, are directions
    whose density is cos(theta) / pi: crowded about the normal, sparse at
    the horizon. The same sampling as irradiance_monte_carlo."""
    figure, (disc, side) = plt.subplots(1, 2, figsize=(7.2, 3.4))
    count, band = 256, 0.07
    points = []
    for i in range(count):
        u, v = (i + 0.5) / count, int(format(i, "08b")[::-1], 2) / 256  # a Hammersley set
        r, phi = math.sqrt(u), 2 * math.pi * v
        points.append((r * math.cos(phi), r * math.sin(phi)))
    disc.add_patch(plt.Circle((0, 0), 1, fill=False, color=INK, lw=1))
    disc.plot([p[0] for p in points], [p[1] for p in points], "o", ms=2.5, color=LINE)
    sliced = [p for p in points if abs(p[1]) < band]
    disc.plot([p[0] for p in sliced], [p[1] for p in sliced], "o", ms=3.5, color=ACCENT)
    for y in (-band, band):
        disc.plot([-1, 1], [y, y], color=ACCENT, lw=0.6, ls="--")
    disc.set_title("seen from above: even over the disc\nr = sqrt(u), phi = 2 pi v; the slice in red", fontsize=9)
    disc.set_xlim(-1.15, 1.15)
    disc.set_ylim(-1.15, 1.15)
    disc.set_aspect("equal")
    disc.axis("off")
    # Side view: the points with y near 0 (a slice), lifted to z = sqrt(1 - r^2).
    side.add_patch(matplotlib.patches.Arc((0, 0), 2, 2, theta1=0, theta2=180, color=INK, lw=1))
    side.plot([-1.15, 1.15], [0, 0], color=INK, lw=1.2)
    for x, y in points:
        if abs(y) < band:
            z = math.sqrt(max(0.0, 1 - x * x - y * y))
            side.plot([x, x], [0, z], color="#bbbbbb", lw=0.6, ls=":")
            side.plot([0, x], [0, z], color=LINE, lw=0.8)
    side.annotate("", (0, 1.2), (0, 0), arrowprops=dict(arrowstyle="->", color=ACCENT, lw=1.2))
    side.text(0.05, 1.15, "n", color=ACCENT, fontsize=9)
    side.set_title("the slice from the side, lifted onto the hemisphere:\ncrowded near n, sparse at the horizon",
                   fontsize=9)
    side.set_xlim(-1.2, 1.2)
    side.set_ylim(-0.1, 1.35)
    side.set_aspect("equal")
    side.axis("off")
    save(figure, out, "09_cosine_sampling.svg")


def main():
    out = pathlib.Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    plt.rcParams["svg.hashsalt"] = "rasterlab"  # the same SVG on every run
    for draw in (tga_layout, bresenham_midpoint, edge_functions, barycentric_areas, painter_cycle, depth_mapping,
                 mip_footprint, frustum_ndc, clip_fan, perspective_edge, reflection_vectors, srgb_curve, normal_matrix,
                 mirrored_seam, tbn_frame, two_passes, acne, light_box_fit, normal_offset, pcf_kernel, tiles_and_bins, blocks, visibility_buffer,
                 lane_queue, fragment_queue, block_rows, texel_words, srgb_entry, albedo_word, shadow_pass, shadow_lookup, frame_path, cube_faces, latlong, reflect_refract, cosine_sampling, microfacets, lobe_lean, split_sum, ao_kernels, ao_horizon, gbuffer_passes, aa_patterns, aa_shading_rate):
        draw(out)


if __name__ == "__main__":
    main()

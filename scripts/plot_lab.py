#!/usr/bin/env python3
"""Draws a lab's chart (error against time) as SVG and its numbers as a Markdown table.

One point per row of the lab's CSV, labelled by --label, coloured by --group
if given. The best trade-offs are marked: the points that no other point beats
on both time and error (the Pareto front), joined by a dashed line.
"""
import argparse
import csv
import math
import pathlib
import sys


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def pareto_front(points):
    """Indices of the points not dominated in (x, y), both smaller-is-better."""
    front = []
    for i, (xi, yi) in enumerate(points):
        dominated = any(
            (xj <= xi and yj <= yi) and (xj < xi or yj < yi) for j, (xj, yj) in enumerate(points) if j != i
        )
        if not dominated:
            front.append(i)
    return sorted(front, key=lambda i: points[i][0])


def format_cell(text):
    value = number(text)
    if value is None or text.strip() == "":
        return text
    if math.isinf(value) or math.isnan(value):
        return text
    if value == int(value) and abs(value) < 1e9 and "." not in text and "e" not in text:
        return str(int(value))
    return f"{value:.3g}"


def write_table(rows, columns, path, front_labels, label):
    lines = ["| " + " | ".join(columns) + " | best trade-off |",
             "|" + "---|" * (len(columns) + 1)]
    for row in rows:
        mark = "yes" if row_key(row, label) in front_labels else ""
        lines.append("| " + " | ".join(format_cell(row[c]) for c in columns) + f" | {mark} |")
    path.write_text("\n".join(lines) + "\n")


def row_key(row, label):
    return tuple(row[c] for c in label)


def finish(figure, axes, options, rows):
    if options.logx:
        axes.set_xscale("log")
    if options.logy:
        ys = [number(r[options.y]) for r in rows]
        positive = [y for y in ys if y and y > 0]
        if any(y == 0 for y in ys):
            # Zero is a result here (an exact method): a linear stretch near 0, log above.
            smallest = min(positive) if positive else 1.0
            axes.set_yscale("symlog", linthresh=smallest / 2, linscale=0.5)
            axes.set_ylim(bottom=0, top=max(positive, default=1.0) * 5)
        else:
            axes.set_yscale("log")
    axes.set_xlabel(options.xlabel or options.x)
    axes.set_ylabel(options.ylabel or options.y)
    axes.grid(True, which="both", alpha=0.3)
    figure.tight_layout()
    options.svg.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(options.svg, metadata={"Date": None})
    print(f"wrote {options.svg}")


def draw_lines(plt, rows, options):
    """One line per series value (colour), and per style value (dash pattern)."""
    figure, axes = plt.subplots(figsize=(7.5, 5))
    series = list(dict.fromkeys(r[options.series] for r in rows))
    styles = list(dict.fromkeys(r[options.style] for r in rows)) if options.style else [None]
    dashes = ["-", "--", ":", "-."]
    for i, name in enumerate(series):
        for j, style in enumerate(styles):
            members = [r for r in rows if r[options.series] == name and (style is None or r[options.style] == style)]
            points = sorted((number(r[options.x]), number(r[options.y])) for r in members)
            label = name if style is None else f"{name}, {style}"
            axes.plot([p[0] for p in points], [p[1] for p in points], dashes[j % len(dashes)], color=f"C{i}",
                      marker="o", markersize=3, label=label)
    axes.set_title(options.title, fontsize=10)
    axes.legend(fontsize=7, ncol=2)
    finish(figure, axes, options, rows)
    if options.table:
        columns = options.columns.split(",") if options.columns else list(rows[0].keys())
        lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
        for row in rows:
            lines.append("| " + " | ".join(format_cell(row[c]) for c in columns) + " |")
        options.table.write_text("\n".join(lines) + "\n")
        print(f"wrote {options.table}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", type=pathlib.Path)
    parser.add_argument("--x", required=True, help="time column")
    parser.add_argument("--y", required=True, help="error column")
    parser.add_argument("--label", help="column(s) naming a point, comma-separated (scatter)")
    parser.add_argument("--series", help="draw lines instead: one line per value of this column")
    parser.add_argument("--style", help="with --series: line style per value of this column")
    parser.add_argument("--group", help="column whose values get their own colour and front")
    parser.add_argument("--xlabel", default=None)
    parser.add_argument("--ylabel", default=None)
    parser.add_argument("--title", default="")
    parser.add_argument("--logx", action="store_true")
    parser.add_argument("--logy", action="store_true")
    parser.add_argument("--svg", type=pathlib.Path, required=True)
    parser.add_argument("--table", type=pathlib.Path, help="Markdown table of the CSV")
    parser.add_argument("--columns", help="columns of the table (default: all)")
    options = parser.parse_args()

    import matplotlib

    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "rasterlab"  # stable ids: a redraw of the same data is the same file
    import matplotlib.pyplot as plt

    with options.csv.open() as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{options.csv}: no rows")
    if options.series:
        draw_lines(plt, rows, options)
        return
    if not options.label:
        sys.exit("--label or --series is required")
    label = options.label.split(",")
    for column in [options.x, options.y, *label] + ([options.group] if options.group else []):
        if column not in rows[0]:
            sys.exit(f"{options.csv}: no column '{column}'")

    groups = {}
    for row in rows:
        groups.setdefault(row[options.group] if options.group else "", []).append(row)

    figure, axes = plt.subplots(figsize=(7.5, 5))
    front_labels = set()
    for index, (group, members) in enumerate(groups.items()):
        colour = f"C{index}"
        points = [(number(r[options.x]), number(r[options.y])) for r in members]
        axes.scatter([p[0] for p in points], [p[1] for p in points], color=colour, s=36, zorder=3,
                     label=f"{options.group} {group}" if options.group else None)
        for row, (x, y) in zip(members, points):
            axes.annotate(" ".join(row[c] for c in label if c != options.group), (x, y),
                          textcoords="offset points", xytext=(6, 4), fontsize=8)
        front = pareto_front(points)
        front_labels.update(row_key(members[i], label) for i in front)
        axes.plot([points[i][0] for i in front], [points[i][1] for i in front], linestyle="--",
                  color=colour, linewidth=1, zorder=2)
        axes.scatter([points[i][0] for i in front], [points[i][1] for i in front], s=140,
                     facecolors="none", edgecolors=colour, linewidths=1.5, zorder=4)
    axes.set_title(options.title + "\n(circled: best trade-offs — nothing is both faster and more accurate)",
                   fontsize=10)
    if options.group:
        axes.legend(fontsize=8)
    finish(figure, axes, options, rows)

    if options.table:
        columns = options.columns.split(",") if options.columns else list(rows[0].keys())
        write_table(rows, columns, options.table, front_labels, label)
        print(f"wrote {options.table}")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Draws a lab's chart (error against time) as SVG and its numbers as a Markdown table.

One point per row of the lab's CSV, labelled by --label, coloured by --group
if given. The best trade-offs are marked: the points that no other point beats
(the Pareto front), joined by a dashed line. Timings on this shared two-core
machine move from run to run (two runs of lesson 03's lab in one session
differed by 5 to 20% on most rows), so a time within TIME_NOISE (15%) of
another counts as a tie: a point is beaten only by one that is as accurate and
more than 15% faster, or more accurate and not more than 15% slower. A lead
inside the noise is not a best trade-off.
"""
import argparse
import csv
import math
import pathlib
import string
import sys
import textwrap


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


TIME_NOISE = 0.15


def pareto_front(points, spreads=None):
    """Indices of the points not dominated in (x = time, y = error), both
    smaller-is-better, with times within TIME_NOISE of each other tied. With
    spreads (each point's fastest and slowest run), times whose ranges
    overlap are tied too: one is clearly faster only if its slowest run beat
    the other's fastest."""
    def beats(j, i):
        (xj, yj), (xi, yi) = points[j], points[i]
        clearly_faster = xj * (1 + TIME_NOISE) < xi
        not_slower = xj <= xi * (1 + TIME_NOISE)
        if spreads:
            (low_j, high_j), (low_i, high_i) = spreads[j], spreads[i]
            clearly_faster = clearly_faster and high_j < low_i
            not_slower = not_slower or low_j <= high_i
        return (yj <= yi and clearly_faster) or (yj < yi and not_slower)

    front = []
    measured = [i for i, (x, y) in enumerate(points) if not (math.isnan(x) or math.isnan(y))]
    for i in measured:  # a point without an error or a time is nobody's trade-off
        dominated = any(beats(j, i) for j in measured if j != i)
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


def write_table(rows, columns, path, front_keys, key, fronts=True):
    lines = ["| " + " | ".join(columns) + (" | best trade-off |" if fronts else " |"),
             "|" + "---|" * (len(columns) + (1 if fronts else 0))]
    for row in rows:
        mark = (" " + ("yes" if key(row) in front_keys else "") + " |") if fronts else ""
        lines.append("| " + " | ".join(format_cell(row[c]) for c in columns) + " |" + mark)
    path.write_text("\n".join(lines) + "\n")


def read_table(path):
    """The rows of a table this script wrote (its first Markdown table), as a
    CSV's, read as the pages' value markers read it (doc_snippets.py). Its
    best trade-off marks are kept, and the chart marks those rows: found again
    from the table's rounded numbers, they could differ."""
    from doc_snippets import table_rows  # beside this script

    rows = table_rows(path)
    if not rows:
        sys.exit(f"{path}: no table")
    return rows


def front_of(rows, points, spreads):
    """The indices of the best trade-offs among rows, fastest first: as the
    table marks them when the chart is drawn from its table, else found."""
    if rows and MARK in rows[0]:
        return sorted((i for i, r in enumerate(rows) if r[MARK] == "yes"), key=lambda i: points[i][0])
    return pareto_front(points, spreads)


MARK = "best trade-off"


class _NameFormatter(string.Formatter):
    """--label-format's and --series-format's fields are a row's columns; the
    spec `first` keeps a value's text before its first comma ("ssaa, grid,
    +3 stops" as "ssaa"), `bare` its text before a bracket ("one bounce
    (roughness 0.5)" as "one bounce", where each panel is one roughness)."""

    def format_field(self, value, spec):
        if spec == "first":
            return value.split(",")[0].strip()
        if spec == "bare":
            return value.split(" (")[0].strip()
        return super().format_field(value, spec)


def point_name(row, columns, options):
    """A point's (or a bar's) name: its label columns' values, or
    --label-format filled from the row."""
    if options.label_format:
        return _NameFormatter().format(options.label_format, **row)
    return " ".join(row[c] for c in columns)


def row_key(row, label):
    return tuple(row[c] for c in label)


def plain_log_ticks(axis, low, high):
    """Ticks labelled as plain numbers (200, 5000) instead of 10^3: at 1, 2 and 5
    times the powers of ten over up to three decades, at the powers alone beyond."""
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    decades = math.log10(max(high, 1e-300) / max(low, 1e-300))
    axis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0) if decades <= 3 else (1.0,)))
    axis.set_major_formatter(FuncFormatter(lambda value, _: f"{value:g}"))
    axis.set_minor_formatter(NullFormatter())


CLOSE = 24  # points nearer than this on the chart (pixels) share one label


LEADER = dict(arrowstyle="-", color="0.45", lw=0.6, shrinkA=1, shrinkB=4)


def merge_close_labels(axes, labels, marks):
    """Points too close to be told apart on the chart (an exact result shared
    by several methods) get one label listing them from left to right, one
    per line, tied to the middle of the group by a thin line; their own
    labels are hidden. Returns the labels shown, and the marks they name."""
    clusters = []  # lists of indices, joined when any two members are close
    for i, (x, y) in enumerate(marks):
        near = [c for c in clusters
                if any(math.hypot(x - marks[j][0], y - marks[j][1]) < CLOSE for j in c)]
        merged = [i] + [j for c in near for j in c]
        clusters = [c for c in clusters if c not in near] + [sorted(merged)]
    shown, anchors = [], []
    for cluster in sorted(clusters):
        if len(cluster) == 1:
            shown.append(labels[cluster[0]])
            anchors.append(marks[cluster[0]])
            continue
        names = [labels[j].get_text() for j in sorted(cluster, key=lambda j: marks[j][0])]
        middle = (sum(marks[j][0] for j in cluster) / len(cluster),
                  sum(marks[j][1] for j in cluster) / len(cluster))
        for j in cluster:
            labels[j].set_visible(False)
        # One name for all of them (the same method in each group): said once.
        text = names[0] if len(set(names)) == 1 else "left to right:\n" + "\n".join(names)
        shown.append(axes.annotate(text,
                                   axes.transData.inverted().transform(middle),
                                   textcoords="offset points", xytext=(6, 4),
                                   fontsize=labels[cluster[0]].get_fontsize(), arrowprops=LEADER))
        anchors.append(middle)
    return shown, anchors


def spread_labels(figure, axes, labels, points, avoid=()):
    """Moves each point label to the first of a few offsets where it overlaps
    no label placed before it, no point, none of the `avoid` axes (an inset,
    with its ticks) and stays inside the axes."""
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    inside = axes.get_window_extent(renderer)
    marks = [axes.transData.transform(p) for p in points]
    mark_boxes = [(x - 5, y - 5, x + 5, y + 5) for x, y in marks]
    placed = [(b.x0, b.y0, b.x1, b.y1) for b in (other.get_tightbbox(renderer) for other in avoid)]
    labels, anchors = merge_close_labels(axes, labels, marks)
    lists = {id(label) for label in labels if label.get_text().startswith("left to right:")}
    candidates = [(6, 4, "left"), (6, -12, "left"), (-6, 4, "right"), (-6, -12, "right"),
                  (6, 16, "left"), (-6, 16, "right"), (6, -24, "left"), (-6, -24, "right"),
                  (0, 28, "center"), (0, -36, "center"),
                  (18, 30, "left"), (-18, 30, "right"), (18, -42, "left"), (-18, -42, "right"),
                  (30, 4, "left"), (-30, 4, "right"),
                  # farther out, for a list of several points where the near places are taken
                  (40, 40, "left"), (-40, 40, "right"), (40, -56, "left"), (-40, -56, "right"),
                  (64, 12, "left"), (-64, 12, "right"), (0, 64, "center"), (0, -76, "center")]
    NEAR = 10  # the first ten sit beside their point; the others get a leader line

    def overlaps(a, b):
        return not (a[2] <= b[0] or b[2] <= a[0] or a[3] <= b[1] or b[3] <= a[1])

    for label in labels:
        best, best_score = None, None
        # A list of several points goes a little apart, above or below them,
        # where its leader line shows.
        order = candidates[NEAR:] + candidates[:NEAR] if id(label) in lists else candidates
        for dx, dy, align in order:
            label.set_position((dx, dy))
            label.set_horizontalalignment(align)
            extent = label.get_window_extent(renderer)
            box = (extent.x0, extent.y0, extent.x1, extent.y1)
            score = sum(overlaps(box, other) for other in placed + mark_boxes)
            if box[0] < inside.x0 or box[2] > inside.x1 or box[1] < inside.y0 or box[3] > inside.y1:
                score += 100  # a label over the axes' edge sits on the ticks or is cut off
            if best_score is None or score < best_score:
                best, best_score = (dx, dy, align, box), score
            if score == 0:
                break
        dx, dy, align, box = best
        label.set_position((dx, dy))
        label.set_horizontalalignment(align)
        if candidates.index((dx, dy, align)) >= NEAR and label.arrow_patch is not None:
            label.arrow_patch.set_visible(True)  # set apart: tied to its point
        placed.append(box)


def place_point_labels(figure, annotations):
    """Point labels of lines (a sample count by each point) moved apart: each
    to the first of a few offsets where it overlaps no label placed before
    it and stays inside its axes; a label whose text a placed one already
    shows within a few pixels is dropped (two lines' points with the same
    count, side by side, need the number once)."""
    if not annotations:
        return
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    offsets = [(3, 3, "left"), (3, -9, "left"), (-3, 3, "right"), (-3, -9, "right"),
               (0, 8, "center"), (0, -14, "center"), (6, -3, "left"), (-6, -3, "right")]
    placed = []  # (box, text)

    def overlaps(a, b):
        return not (a[2] <= b[0] or b[2] <= a[0] or a[3] <= b[1] or b[3] <= a[1])

    for axes, label in annotations:
        frame = axes.get_window_extent(renderer)
        best = None
        for dx, dy, align in offsets:
            label.set_position((dx, dy))
            label.set_horizontalalignment(align)
            e = label.get_window_extent(renderer)
            box = (e.x0, e.y0, e.x1, e.y1)
            score = sum(overlaps(box, other) for other, _ in placed)
            if box[0] < frame.x0 or box[2] > frame.x1 or box[1] < frame.y0 or box[3] > frame.y1:
                score += 100
            if best is None or score < best[0]:
                best = (score, dx, dy, align, box)
            if score == 0:
                break
        score, dx, dy, align, box = best
        twin = any(text == label.get_text() and overlaps(box, other) for other, text in placed)
        if score and twin:
            label.set_visible(False)
            continue
        label.set_position((dx, dy))
        label.set_horizontalalignment(align)
        placed.append((box, label.get_text()))


def finish(figure, axes, options, rows, before_save=None):
    """Scales, ticks and axis labels of each of `axes` (one or a list: the
    panels, which share their scales), then the SVG."""
    for one in axes if isinstance(axes, list) else [axes]:
        scale_axes(one, options, rows)
    figure.tight_layout()
    for one in axes if isinstance(axes, list) else [axes]:
        fit_notes(figure, one)
    if before_save:
        before_save()
    options.svg.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(options.svg, metadata={"Date": None})
    print(f"wrote {options.svg}")


def fit_notes(figure, axes):
    """Widens a bar chart's x range until the note after each bar ends inside
    the axes (at the right edge it ran over the frame and off the figure)."""
    notes = getattr(axes, "bar_notes", None)
    if not notes:
        return
    for _ in range(12):
        figure.canvas.draw()
        renderer = figure.canvas.get_renderer()
        right = axes.get_window_extent(renderer).x1
        over = max(n.get_window_extent(renderer).x1 for n in notes) - right
        if over <= 0:
            return
        low, high = axes.get_xlim()
        if axes.get_xscale() == "log":
            axes.set_xlim(low, high * 1.15)
        else:
            axes.set_xlim(low, high + (high - low) * 0.08)


def tick_label(value):
    """A tick's text, short enough that neighbours on a log axis do not run
    into each other: 16128 as 16.1k, 1996570 as 2M (below 10 000 as it is)."""
    if abs(value) >= 1e6:
        return f"{value / 1e6:.3g}M"
    if abs(value) >= 1e4:
        return f"{value / 1e3:.3g}k"
    return f"{value:g}"


def scale_axes(axes, options, rows):
    from matplotlib.ticker import NullLocator

    if options.logx:
        axes.set_xscale("log")
        xs = [number(r[options.x]) for r in rows if number(r[options.x])]
        plain_log_ticks(axes.xaxis, min(xs), max(xs))
    if options.xticks_at_data:
        values = sorted({number(r[options.x]) for r in rows})
        axes.set_xticks(values)
        axes.set_xticklabels([tick_label(v) for v in values])
        axes.minorticks_off()
    if options.logy:
        ys = [number(r[y]) for r in rows for y in options.y.split(",")]
        positive = [y for y in ys if y and y > 0]
        if any(y == 0 for y in ys):
            # Zero is a result here (an exact method): a linear stretch near 0, log above.
            smallest = min(positive) if positive else 1.0
            axes.set_yscale("symlog", linthresh=smallest / 2, linscale=0.5)
            top = max(positive, default=1.0) * 5
            axes.set_ylim(bottom=0, top=top)
            # 0, then the powers of ten from the smallest value up: no tick at the
            # edge of the linear stretch, where its label would sit on top of 0's.
            ticks = [0.0] + [10.0 ** k for k in range(math.floor(math.log10(smallest)),
                                                      math.floor(math.log10(top)) + 1)]
            axes.set_yticks(ticks)
            axes.set_yticklabels([f"{t:g}" for t in ticks])
            axes.yaxis.set_minor_locator(NullLocator())
        else:
            axes.set_yscale("log")
            plain_log_ticks(axes.yaxis, min(positive), max(positive))
    # A long axis label in two lines: in one it ran past the figure's edge.
    axes.set_xlabel(textwrap.fill(options.xlabel or options.x, 90), fontsize=8 if options.panel else None)
    if not options.bars:  # (bars are named on the y axis itself)
        axes.set_ylabel(textwrap.fill(options.ylabel or options.y, 70), fontsize=8 if options.panel else None)
    axes.grid(True, which="both", alpha=0.3)


def panel_grid(plt, count, width, height, columns=2):
    """`count` small charts, `columns` to a row, on shared scales: the figure
    and the axes in use (a spare one of an odd count hidden)."""
    columns_n = min(columns, count)
    rows_n = math.ceil(count / columns_n)
    figure, grid = plt.subplots(rows_n, columns_n, figsize=(width * columns_n, height * rows_n + 0.6),
                                sharex=True, sharey=True, squeeze=False)
    all_axes = [a for line in grid for a in line]
    for spare in all_axes[count:]:
        spare.axis("off")  # room for a legend
    for axes in all_axes[:count]:
        axes.xaxis.set_tick_params(labelbottom=True)  # also over an empty slot
    return figure, all_axes[:count], all_axes[count:]


def legend_handle(line):
    """A line's legend entry in its own style, not the short dashes it is
    drawn in where it lies on another line."""
    from matplotlib.lines import Line2D

    return Line2D([], [], color=line.get_color(), marker=line.get_marker(), markersize=3,
                  linestyle=getattr(line, "legend_style", line.get_linestyle()))


def draw_lines(plt, rows, options):
    """One line per series value (colour), and per style value or y column
    (dash pattern): --y a,b draws each column as its own line. With --panel,
    a small chart per value of that column, the same colours in each. A line
    that would pass twice through one x (rows of different scenes, say, in one
    series) is refused: its zig-zag would join points that do not belong
    together."""
    table_rows = rows  # the table keeps the lab's own names
    if options.series and options.series_format:  # the lines named by a format of their rows
        rows = [dict(r, **{options.series: _NameFormatter().format(options.series_format, **r)})
                for r in rows]
    series = list(dict.fromkeys(r[options.series] for r in rows)) if options.series else [None]
    y_columns = options.y.split(",")
    if options.style and len(y_columns) > 1:
        sys.exit("--style and several --y columns both set the dash pattern: choose one")
    styles = list(dict.fromkeys(r[options.style] for r in rows)) if options.style else [None]
    panels = {}
    for row in rows:
        panels.setdefault(row[options.panel] if options.panel else "", []).append(row)
    if options.panel:
        figure, all_axes, spares = panel_grid(plt, len(panels), 5.2, 3.8)
    else:
        figure, single = plt.subplots(figsize=(7.5, 5))
        all_axes, spares = [single], []
    dashes = ["-", (0, (6, 3)), ":", "-."]
    point_labels = []  # (axes, annotation): placed apart once the chart is laid out
    for axes, (panel, panel_rows) in zip(all_axes, panels.items()):
        flat = []  # lines that are zero everywhere: named in a note, not drawn on top of each other
        drawn = {}  # a line's points -> how many lines of this axes have them
        for i, name in enumerate(series):
            for j, (style, y) in enumerate((s, y) for s in styles for y in y_columns):
                members = [r for r in panel_rows if (name is None or r[options.series] == name)
                           and (style is None or r[options.style] == style)]
                points = sorted((number(r[options.x]), number(r[y])) for r in members)
                parts = [p for p in (name, style, y if len(y_columns) > 1 else None) if p is not None]
                label = ", ".join(parts) or y
                xs = [p[0] for p in points]
                if len(set(xs)) != len(xs):
                    where = f" in {options.panel} {panel}" if options.panel else ""
                    sys.exit(f"{options.csv}: the line '{label}'{where} has several points at one "
                             f"{options.x}: its rows differ in a column the chart does not split "
                             "by (give it --panel, --style or --where)")
                if not points:  # e.g. a method measured at one style only: no empty legend entry
                    continue
                if all(p[1] == 0 for p in points):
                    flat.append(label)
                    continue
                # A line with the same points as one drawn before would hide
                # it, though the legend names both: the k-th such line is
                # drawn in short dashes, each its own third of every 9 points
                # of length, so that each colour shows in turn.
                same = drawn.get(tuple(points), 0)
                drawn[tuple(points)] = same + 1
                style_of_line = dashes[j % len(dashes)] if not same else (3 * ((same - 1) % 2), (3, 6))
                (line,) = axes.plot(xs, [p[1] for p in points], linestyle=style_of_line,
                                    color=f"C{i}" if len(series) > 1 or len(y_columns) == 1 else f"C{j}",
                                    marker="o", markersize=3, label=label)
                line.legend_style = dashes[j % len(dashes)]  # the legend shows the line's own style
                if options.point_labels:  # each point named by its value of that column (e.g. segments)
                    for r in members:
                        point_labels.append((axes, axes.annotate(
                            r[options.point_labels], (number(r[options.x]), number(r[y])),
                            textcoords="offset points", xytext=(3, 3), fontsize=6, color=f"C{i}")))
        # Two names a line: a long title would make the legend wider than the chart.
        axes.flat_note = ("zero everywhere (not drawn):\n" + "\n".join(
            ", ".join(flat[k:k + 2]) for k in range(0, len(flat), 2))) if flat else None
        if flat and options.panel:  # (a single chart's legend carries it as its title)
            axes.text(0.01, 0.99, "zero everywhere (not drawn):\n" + "\n".join(flat),
                      transform=axes.transAxes, fontsize=6.5, va="top", ha="left", color="0.3")
        if options.panel:
            axes.set_title(f"{options.panel} {panel}", fontsize=9)
    if options.panel:
        figure.suptitle(options.title, fontsize=10)
        # One legend for every panel, in the empty slot if there is one, else
        # below them: where it covers no line.
        named = {}
        for axes in all_axes:
            for handle, label in zip(*axes.get_legend_handles_labels()):
                named.setdefault(label, legend_handle(handle))
        if spares:
            spares[0].legend(named.values(), named.keys(), fontsize=8, handlelength=4, loc="center")
        else:
            figure.legend(named.values(), named.keys(), fontsize=7, ncol=3, handlelength=4,
                          loc="lower center")
    else:
        all_axes[0].set_title(options.title, fontsize=10)
        handles, names = all_axes[0].get_legend_handles_labels()
        place = dict(loc="upper center", bbox_to_anchor=(0.5, -0.14)) if options.legend_below else {}
        legend = all_axes[0].legend([legend_handle(h) for h in handles], names, fontsize=7, ncol=2,
                                    handlelength=4,  # long enough handles to show the dashes
                                    title=all_axes[0].flat_note, title_fontsize=6.5, **place)
        legend.get_title().set_color("0.3")
    def before_save():
        if options.panel and not spares:
            figure.subplots_adjust(bottom=0.2)
        place_point_labels(figure, point_labels)

    finish(figure, all_axes if options.panel else all_axes[0], options, rows, before_save)
    if options.table:
        columns = options.columns.split(",") if options.columns else list(table_rows[0].keys())
        lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
        for row in table_rows:
            lines.append("| " + " | ".join(format_cell(row[c]) for c in columns) + " |")
        options.table.write_text("\n".join(lines) + "\n")
        print(f"wrote {options.table}")


def points_and_spreads(rows, options):
    """Each row's (time, error), and its (fastest, slowest) run with
    --x-spread (None without)."""
    points = [(number(r[options.x]), number(r[options.y])) for r in rows]
    if not options.x_spread:
        return points, None
    low, high = options.x_spread.split(",")
    return points, [(number(r[low]), number(r[high])) for r in rows]


def scatter_with_fronts(axes, rows, options, label, key, front_keys, labelled=None):
    """The rows as labelled points, coloured by group, each group's best
    trade-offs circled and joined; their keys are added to front_keys. With
    `labelled`, only the rows it accepts get a label."""
    groups = {}
    for row in rows:
        groups.setdefault(row[options.group] if options.group else "", []).append(row)
    labels, all_points = [], []
    for index, (group, members) in enumerate(groups.items()):
        colour = f"C{index}"
        points, spreads = points_and_spreads(members, options)
        axes.scatter([p[0] for p in points], [p[1] for p in points], color=colour, s=36, zorder=3,
                     label=f"{options.group} {group}" if options.group else None)
        shown = [c for c in label if c not in (options.group, options.panel)]
        for row, (x, y) in zip(members, points):
            if labelled and not labelled(row):
                continue
            labels.append(axes.annotate(point_name(row, shown, options), (x, y),
                                        textcoords="offset points", xytext=(6, 4),
                                        fontsize=7 if options.panel else 8, arrowprops=LEADER))
            labels[-1].arrow_patch.set_visible(False)  # shown if the label is set apart
            all_points.append((x, y))
        if spreads:  # each point's fastest and slowest run, drawn as a bar
            axes.errorbar([p[0] for p in points], [p[1] for p in points],
                          xerr=[[max(p[0] - lo, 0) for p, (lo, hi) in zip(points, spreads)],
                                [max(hi - p[0], 0) for p, (lo, hi) in zip(points, spreads)]],
                          fmt="none", ecolor=colour, elinewidth=0.8, alpha=0.6, zorder=2)
        front = front_of(members, points, spreads)
        front_keys.update(key(members[i]) for i in front)
        axes.plot([points[i][0] for i in front], [points[i][1] for i in front], linestyle="--",
                  color=colour, linewidth=1, zorder=2)
        axes.scatter([points[i][0] for i in front], [points[i][1] for i in front], s=140,
                     facecolors="none", edgecolors=colour, linewidths=1.5, zorder=4)
    return labels, all_points


def in_zoom(row, options):
    """Whether a row's point lies in the --zoom box."""
    x0, x1, y0, y1 = options.zoom
    x, y = number(row[options.x]), number(row[options.y])
    return x is not None and y is not None and x0 <= x <= x1 and y0 <= y <= y1


def zoom_inset(axes, rows, options, label, key, front_keys):
    """The --zoom box's points again, in an inset of `axes` at --zoom-at
    (axes fractions) on linear scales, with their labels: a cluster whose
    labels cannot be told apart at the chart's scale. The box is outlined on
    the chart and joined to the inset."""
    inset = axes.inset_axes(options.zoom_at)
    labels, points = scatter_with_fronts(inset, rows, options, label, key, front_keys,
                                         labelled=lambda row: in_zoom(row, options))
    x0, x1, y0, y1 = options.zoom
    inset.set_xlim(x0, x1)
    inset.set_ylim(y0, y1)
    inset.tick_params(labelsize=7)
    inset.grid(True, alpha=0.3)
    axes.indicate_inset_zoom(inset, edgecolor="0.4")
    return inset, labels, points


def bars_with_fronts(axes, rows, options, label, key, front_keys):
    """The rows as horizontal bars of their time, top to bottom in the CSV's
    order, each named by its label and its error written at its end; the best
    trade-offs (found as scatter_with_fronts finds them) drawn dark. For a
    sequence of steps whose errors are mostly equal, where a scatter piles
    every point on one line."""
    groups = {}
    for row in rows:
        groups.setdefault(row[options.group] if options.group else "", []).append(row)
    for members in groups.values() if not options.no_fronts else []:
        front_keys.update(key(members[i]) for i in front_of(members, *points_and_spreads(members, options)))
    shown = [c for c in label if c not in (options.group, options.panel)]
    positions = list(range(len(rows)))[::-1]  # the first row at the top
    times = [number(r[options.x]) for r in rows]
    best = [key(r) in front_keys for r in rows]
    axes.barh(positions, times, color=["C0" if b or options.no_fronts else "#9ab8d8" for b in best],
              height=0.7, zorder=2)
    if options.no_fronts:
        axes.axvline(0, color="0.3", lw=0.8, zorder=3)
    if options.x_spread:
        low, high = options.x_spread.split(",")
        axes.errorbar(times, positions,
                      xerr=[[max(t - number(r[low]), 0) for t, r in zip(times, rows)],
                            [max(number(r[high]) - t, 0) for t, r in zip(times, rows)]],
                      fmt="none", ecolor="0.2", elinewidth=0.8, zorder=3)
    ends = times  # the text goes after the bar, or after its whisker
    if options.x_spread:
        ends = [max(t, number(r[options.x_spread.split(",")[1]])) for t, r in zip(times, rows)]
    notes = [axes.annotate(f"{options.y_short} {number(row[options.y]):g}", (end, position),
                           textcoords="offset points", xytext=(5, -3), fontsize=7, color="0.25")
             for position, end, row in zip(positions, ends, rows)]
    axes.bar_notes = notes  # finish() widens the axes until every note fits inside
    axes.set_yticks(positions)
    axes.set_yticklabels([point_name(r, shown, options) for r in rows], fontsize=7)
    axes.set_ylim(-0.6, len(rows) - 0.4)
    return [], []


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", type=pathlib.Path)
    parser.add_argument("--x", required=True, help="time column")
    parser.add_argument("--y", required=True, help="error column")
    parser.add_argument("--label", help="column(s) naming a point, comma-separated (scatter)")
    parser.add_argument("--series", help="draw lines instead: one line per value of this column")
    parser.add_argument("--series-format", metavar="FORMAT",
                        help="with --series: name each line by this format of its row (as --label-format)")
    parser.add_argument("--style", help="with --series: line style per value of this column")
    parser.add_argument("--legend-below", action="store_true",
                        help="with --series: the legend under the chart, where it hides no line")
    parser.add_argument("--point-labels", help="with --series: name each point by this column's value")
    parser.add_argument("--label-format", metavar="FORMAT",
                        help="name each point by this Python format of its row's columns, e.g. "
                             "'{levels} {size}/{samples}' ({column:first}: its text before a comma)")
    parser.add_argument("--group", help="column whose values get their own colour and front")
    parser.add_argument("--panel", help="column whose values get a small chart each, with its own fronts")
    parser.add_argument("--xlabel", default=None)
    parser.add_argument("--ylabel", default=None)
    parser.add_argument("--title", default="")
    parser.add_argument("--x-spread", metavar="MIN,MAX",
                        help="columns of each point's fastest and slowest run: drawn as a bar, and "
                             "times whose ranges overlap are tied")
    parser.add_argument("--logx", action="store_true")
    parser.add_argument("--logy", action="store_true")
    parser.add_argument("--svg", type=pathlib.Path, required=True)
    parser.add_argument("--table", type=pathlib.Path, help="Markdown table of the CSV")
    parser.add_argument("--columns", help="columns of the table (default: all)")
    parser.add_argument("--where", action="append", default=[], metavar="COLUMN=VALUE",
                        help="draw and tabulate only the rows with this value (repeatable)")
    parser.add_argument("--bars", action="store_true",
                        help="draw each row as a bar of its time, its error written beside it "
                             "(for steps whose errors are mostly equal)")
    parser.add_argument("--y-short", default="error", help="with --bars: the error's name by each bar")
    parser.add_argument("--no-fronts", action="store_true",
                        help="with --bars: bars of a measure that is not a trade-off (no best trade-offs "
                             "marked; the title says what the whiskers are)")
    parser.add_argument("--zoom", metavar="X0,X1,Y0,Y1",
                        help="draw the points in this box again, labelled, in an inset (a cluster)")
    parser.add_argument("--zoom-at", metavar="LEFT,BOTTOM,WIDTH,HEIGHT", default="0.3,0.4,0.45,0.5",
                        help="with --zoom: where the inset goes, in fractions of the chart")
    parser.add_argument("--xticks-at-data", action="store_true",
                        help="one x tick at each value the data has (sizes, distances)")
    options = parser.parse_args()
    for name in ("zoom", "zoom_at"):
        text = getattr(options, name)
        if text:
            values = [number(v) for v in text.split(",")]
            if len(values) != 4 or None in values:
                sys.exit(f"--{name.replace('_', '-')}: four numbers, comma-separated")
            setattr(options, name, values)
    if options.zoom and (options.panel or options.bars or options.series):
        sys.exit("--zoom: only for a single scatter chart")

    import matplotlib

    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "rasterlab"  # stable ids: a redraw of the same data is the same file
    import matplotlib.pyplot as plt

    if options.csv.suffix == ".md":
        # Redrawn from a table (the `replot` target: the chart's own; no lab
        # run). The table holds the rows chosen when it was written, so a
        # --where on a column it leaves out is already applied. A chart drawn
        # from another chart's table may write its own, never over its input.
        all_rows = read_table(options.csv)
        if options.table and options.table.resolve() == options.csv.resolve():
            sys.exit(f"--table {options.table}: the table this chart is drawn from")
    else:
        with options.csv.open() as f:
            all_rows = list(csv.DictReader(f))
    rows = all_rows
    for condition in options.where:  # COLUMN=VALUE, or COLUMN!=VALUE to leave those rows out
        column, _, value = condition.partition("=")
        if rows and column.rstrip("!") not in rows[0] and options.csv.suffix == ".md":
            continue
        if column.endswith("!"):
            rows = [r for r in rows if r.get(column[:-1]) != value]
        else:
            rows = [r for r in rows if r.get(column) == value]
    if not rows:
        sys.exit(f"{options.csv}: no rows" + (f" with {', '.join(options.where)}" if options.where else ""))
    if options.series or "," in options.y:
        draw_lines(plt, rows, options)
        return
    if not options.label:
        sys.exit("--label or --series is required")
    label = options.label.split(",")
    spread_columns = options.x_spread.split(",") if options.x_spread else []
    if options.x_spread and len(spread_columns) != 2:
        sys.exit("--x-spread: two columns, MIN,MAX")
    for column in [options.x, options.y, *label, *spread_columns] + [c for c in (options.group, options.panel) if c]:
        if column not in rows[0]:
            sys.exit(f"{options.csv}: no column '{column}'")

    # A row's identity for the best trade-offs: its panel, its group and its
    # label. (By the label alone, a method best in one group was marked best in all.)
    def key(row):
        return tuple(row[c] if c else "" for c in (options.panel, options.group)) + row_key(row, label)

    panels = {}
    for row in rows:
        panels.setdefault(row[options.panel] if options.panel else "", []).append(row)

    if options.panel and options.bars:  # one chart per value, one above the other
        tallest = max(len(r) for r in panels.values())
        figure, all_axes, _ = panel_grid(plt, len(panels), 9.0, 0.28 * tallest + 1.2, columns=1)
    elif options.panel:  # one small chart per value, side by side, two to a row, on shared scales
        figure, all_axes, _ = panel_grid(plt, len(panels), 5.2, 3.6)
    else:
        figure, single = plt.subplots(figsize=(8.5, 5))
        all_axes = [single]
    front_keys = set()
    placements = []
    for axes, (panel, panel_rows) in zip(all_axes, panels.items()):
        if options.zoom:  # the box's points are labelled in the inset only
            labels, points = scatter_with_fronts(
                axes, panel_rows, options, label, key, front_keys,
                labelled=lambda row: not in_zoom(row, options))
            inset, *inset_labels = zoom_inset(axes, panel_rows, options, label, key, front_keys)
            placements.append((inset, *inset_labels, []))
            placements.append((axes, labels, points, [inset]))
        else:
            draw = bars_with_fronts if options.bars else scatter_with_fronts
            labels, points = draw(axes, panel_rows, options, label, key, front_keys)
            placements.append((axes, labels, points, []))
        if options.panel:
            axes.set_title(f"{options.panel} {panel}", fontsize=9)
    if options.no_fronts:
        title = options.title
    elif options.bars:
        title = options.title + ("\n(dark: best trade-offs; whiskers: fastest to slowest run; "
                                 "times within 15% or with overlapping runs are ties)")
    else:
        title = options.title + ("\n(circled: best trade-offs; bars: fastest to slowest run;\n"
                                 "times within 15% or with overlapping runs are ties)" if options.x_spread else
                                 "\n(circled: best trade-offs; times within 15% count as ties)")
    if options.panel:
        figure.suptitle(title, fontsize=10)
    else:
        all_axes[0].set_title(title, fontsize=10)
    if options.group:  # beside the plot, where it cannot cover a point or a label
        all_axes[0].legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)

    def place_labels():
        for axes, labels, points, avoid in placements:
            spread_labels(figure, axes, labels, points, avoid)

    finish(figure, all_axes if options.panel else all_axes[0], options, rows, place_labels)

    if options.table:
        columns = options.columns.split(",") if options.columns else list(rows[0].keys())
        write_table(rows, columns, options.table, front_keys, key, fronts=not options.no_fronts)
        print(f"wrote {options.table}")


if __name__ == "__main__":
    main()

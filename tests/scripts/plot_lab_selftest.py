#!/usr/bin/env python3
"""plot_lab.py marks the best trade-offs within each --group: a method that
is the best trade-off in one group is not marked in another where a faster,
more accurate point beats it (issue 18: the marks were keyed on the label
alone, and "affine, 8x8 cells" was marked best at every tilt). And a line
chart refuses a line that passes twice through one x (issue 34: lesson 12's
sizes joined three scenes into one zig-zag line when --panel was ignored),
and draws one per panel when --panel splits them. A cluster given to --zoom
is labelled in its inset, once; points too close to tell apart share one
label that lists them left to right."""
import pathlib
import subprocess
import sys
import tempfile

plot = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "plot_lab.py"
with tempfile.TemporaryDirectory() as folder:
    folder = pathlib.Path(folder)
    csv = folder / "lab.csv"
    # Group "flat": fine is best (fastest and most accurate). Group "tilted":
    # coarse beats fine on time and error, so fine is not a best trade-off there.
    csv.write_text("tilt,method,ns,error\n"
                   "flat,fine,10,1\n"
                   "flat,coarse,30,5\n"
                   "tilted,fine,30,5\n"
                   "tilted,coarse,10,1\n")
    # The same within each --panel (a small chart per value), and drawn as bars.
    for split in (["--group"], ["--panel"], ["--bars", "--panel"]):
        table = folder / "lab.md"
        subprocess.run([sys.executable, str(plot), str(csv), "--x", "ns", "--y", "error",
                        "--label", "method", *split, "tilt", "--svg", str(folder / "lab.svg"),
                        "--table", str(table)], check=True)
        marks = {tuple(cell.strip() for cell in line.strip("|").split("|")[:2]):
                 line.strip("|").split("|")[-1].strip()
                 for line in table.read_text().splitlines()[2:]}
        expected = {("flat", "fine"): "yes", ("flat", "coarse"): "",
                    ("tilted", "fine"): "", ("tilted", "coarse"): "yes"}
        if marks != expected:
            sys.exit(f"{split}: best trade-offs {marks}, expected {expected}")
    # With --x-spread, a faster median whose runs overlap the other's is a tie:
    # the more accurate point then wins alone.
    csv.write_text("method,ns,low,high,error\n"
                   "exact,15,12,17,0.01\n"
                   "rough,12,11,14,0.5\n")
    subprocess.run([sys.executable, str(plot), str(csv), "--x", "ns", "--y", "error",
                    "--label", "method", "--x-spread", "low,high", "--svg", str(folder / "lab.svg"),
                    "--table", str(table)], check=True)
    marks = {line.strip("|").split("|")[0].strip(): line.strip("|").split("|")[-1].strip()
             for line in table.read_text().splitlines()[2:]}
    if marks != {"exact": "yes", "rough": ""}:
        sys.exit(f"--x-spread: best trade-offs {marks}, expected only exact")
    # Lines: two scenes in one series without --panel is a zig-zag, refused,
    # naming the line; with --panel each scene gets its own line.
    csv.write_text("scene,size,renderer,ms\n"
                   "a,512,ours,1\n" "a,1024,ours,4\n"
                   "b,512,ours,9\n" "b,1024,ours,30\n")
    lines = [sys.executable, str(plot), str(csv), "--x", "size", "--y", "ms", "--series", "renderer",
             "--svg", str(folder / "lines.svg")]
    mixed = subprocess.run(lines, capture_output=True, text=True)
    if mixed.returncode == 0 or "the line 'ours' has several points at one size" not in mixed.stderr:
        sys.exit(f"a line through two scenes was drawn: {mixed.returncode} {mixed.stderr}")
    subprocess.run(lines + ["--panel", "scene"], check=True)
    svg = (folder / "lines.svg").read_text()
    if svg.count("scene a") != 1 or svg.count("scene b") != 1:
        sys.exit("--panel with --series: expected one small chart per scene")
    # A cluster too tight to label at the chart's scale (issue 34: lesson 08's
    # filters could not be matched to their dots): with --zoom its points are
    # drawn again in an inset and labelled there only, once each; a point
    # outside the box keeps its label on the chart.
    csv.write_text("method,ms,error\n"
                   "alpha,100,0.06\n" "beta,101,0.061\n" "gamma,102,0.059\n" "delta,103,0.062\n"
                   "far away,500,5\n")
    zoom = [sys.executable, str(plot), str(csv), "--x", "ms", "--y", "error", "--label", "method",
            "--logy", "--svg", str(folder / "zoom.svg")]
    subprocess.run(zoom + ["--zoom", "95,110,0.055,0.065"], check=True)
    svg = (folder / "zoom.svg").read_text()
    counts = {name: svg.count(f"<!-- {name} -->") for name in
              ("alpha", "beta", "gamma", "delta", "far away")}
    axes = svg.count('id="axes_')
    if set(counts.values()) != {1} or axes != 2:
        sys.exit(f"--zoom: labels {counts} (each once), {axes} axes (2)")
    bad = subprocess.run(zoom + ["--zoom", "95,110,0.055"], capture_output=True, text=True)
    if bad.returncode == 0 or "--zoom: four numbers" not in bad.stderr:
        sys.exit(f"--zoom with three numbers was taken: {bad.returncode} {bad.stderr}")
    # Points too close to tell apart on the chart (issue 34: lesson 05's tilt 0,
    # seven exact methods on one spot) share one label listing them left to
    # right, tied to them by a line; a point apart keeps its own.
    csv.write_text("method,ms,error\n"
                   "one,10,1\n" "two,10.1,1.01\n" "three,10.05,0.99\n" "apart,80,30\n")
    subprocess.run([sys.executable, str(plot), str(csv), "--x", "ms", "--y", "error", "--label",
                    "method", "--logx", "--logy", "--svg", str(folder / "close.svg")], check=True)
    svg = (folder / "close.svg").read_text()
    lines = [line.strip() for line in svg.splitlines() if line.strip().startswith("<!-- ")]
    listed = lines[lines.index("<!-- left to right: -->") + 1:][:3] if "<!-- left to right: -->" in lines else []
    if listed != ["<!-- one -->", "<!-- three -->", "<!-- two -->"] or svg.count("<!-- apart -->") != 1:
        sys.exit(f"close points: expected one list 'one, three, two' (left to right) and 'apart' "
                 f"alone, got {listed}")
print("best trade-offs marked within each group and each panel, overlapping runs tied; "
      "a line never joins two panels' rows; a zoomed cluster is labelled once, in its inset")

"""The arrays: their layout, that they are views of the result (no copy),
that they outlive it; the GIL released while rendering; memory flat over
many renders."""

import pathlib
import threading
import time

import numpy as np

import rasterlab

OBJ = pathlib.Path(__file__).resolve().parents[2] / "obj"


def test_image_layout_is_top_row_first():
    card = rasterlab.lesson00.test_card(width=64, height=48)
    image = card.image
    assert image.shape == (48, 64, 3) and image.dtype == np.uint8
    # The test card's white square sits at pixel (0, 0), the bottom-left one:
    # in a top-first array that is the last row.
    assert (image[-1, 0] == 255).all()
    assert not (image[0, 0] == 255).all()


def test_arrays_are_views_without_a_copy():
    r = rasterlab.lesson03.render(width=40, height=30)
    assert np.shares_memory(r.image, r.rgba)
    assert r.image.strides[0] == -40 * 4 and r.image.strides[1:] == (4, 1)
    assert r.depth.shape == (30, 40) and r.depth.dtype == np.float32
    assert r.depth.strides == (-40 * 4, 4)
    assert not r.image.flags.writeable


def test_arrays_keep_their_result_alive():
    image = rasterlab.lesson02.draw(width=32, height=32).image
    copy = image.copy()
    for _ in range(20):  # other results take the freed memory, if it was freed
        rasterlab.lesson02.draw(width=32, height=32, raster="bbox", light=(1, 0, 0))
    assert np.array_equal(image, copy)


def test_depth_is_window_depth():
    r = rasterlab.lesson05.render(width=80, height=60)
    assert r.depth.min() >= 0 and r.depth.max() <= 1
    drawn = r.depth < 1
    assert 0.05 < drawn.mean() < 0.95


def test_counts_and_png():
    r = rasterlab.lesson07.render(width=64, height=64)
    assert r.counts["faces"] > 0 and r.counts["fragments"] > 0
    assert r._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_gil_is_released_while_rendering():
    def render():
        return rasterlab.lesson07.render(width=500, height=500)

    start = time.perf_counter()
    render()
    alone = time.perf_counter() - start
    # The main thread ticks while another renders. Were the GIL held for the
    # whole render, one gap between ticks would last about the render itself.
    worker = threading.Thread(target=render)
    last, longest = time.perf_counter(), 0.0
    worker.start()  # (which waits for the thread to start: a held GIL would stop it here)
    while worker.is_alive():
        now = time.perf_counter()
        longest = max(longest, now - last)
        last = now
    longest = max(longest, time.perf_counter() - last)  # (the wait that ended the loop)
    worker.join()
    assert longest < alone / 2, f"the main thread stood still {longest:.3f} s of {alone:.3f} s"


def resident_kib():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("no VmRSS")


def test_memory_stays_flat_over_many_renders():
    crate = str(OBJ / "crate.obj")

    def renders(n):
        for i in range(n):
            r = rasterlab.lesson03.render(scene="sticks", width=64, height=64)
            _ = r.image, r.rgba, r.depth, r.counts, r._repr_png_()
            rasterlab.lesson00.test_card(width=64, height=64).image.copy()
            rasterlab.lesson02.draw(test_image=True, raster=("edge", "bbox")[i % 2])
            if i % 10 == 0:  # a model loaded, textures and all
                rasterlab.lesson07.render([crate], width=32, height=32).image.sum()
            try:
                rasterlab.lesson02.draw(raster="none")
            except ValueError:
                pass

    renders(30)  # warm up: caches, allocator pools
    before = resident_kib()
    renders(300)
    grown = resident_kib() - before
    assert grown < 2 * 1024, f"resident memory grew by {grown} KiB over 300 renders"


def test_a_mesh_still_finds_its_file_after_a_chdir(tmp_path, monkeypatch):
    monkeypatch.chdir(OBJ.parent)
    crate = rasterlab.load_mesh("obj/crate.obj")
    monkeypatch.chdir(tmp_path)
    assert rasterlab.lesson05.render([crate], width=16, height=16).counts["faces"] > 0


def test_warnings_hold_only_what_the_program_prints(tmp_path):
    assert rasterlab.lesson07.render(width=16, height=16).warnings == []
    bare = tmp_path / "bare.obj"
    bare.write_text((OBJ / "crate.obj").read_text().replace("mtllib", "# mtllib"))
    warned = rasterlab.lesson05.render([bare], width=16, height=16).warnings
    assert warned and all(warned) and "texture" in " ".join(warned)


def test_counts_hold_the_framed_camera():
    counts = rasterlab.lesson06.render(width=16, height=16).counts
    assert len(counts["eye"]) == 3 and len(counts["target"]) == 3
    assert 0 < counts["near"] < counts["far"]

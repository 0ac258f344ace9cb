"""Threads: saves from several threads at once (Result.save releases the
GIL) each write their whole file, with no temporary left behind; renders
from several threads at once (each releases the GIL, and lessons 09, 10 and
12 run their own threads inside) give the pictures they give one at a time.
The tsan preset runs this file under ThreadSanitizer (scripts/test.sh tsan)."""

import threading

import numpy

import rasterlab

THREADS = 8
SAVES = 12


def test_saves_from_threads_at_once_each_write_a_whole_file(tmp_path):
    results = [rasterlab.lesson00.test_card(width=64 + 8 * t, height=48) for t in range(THREADS)]
    expected_png = [r._repr_png_() for r in results]  # the encoder save() uses for .png
    reference, out = tmp_path / "reference", tmp_path / "out"
    reference.mkdir()
    out.mkdir()
    for t, r in enumerate(results):  # one at a time
        r.save(reference / f"{t}.tga")
    expected_tga = [(reference / f"{t}.tga").read_bytes() for t in range(THREADS)]
    errors = []
    start = threading.Barrier(THREADS)

    def saves(t):
        try:
            start.wait()
            for i in range(SAVES):
                results[t].save(out / f"t{t}_{i}.png")
                results[t].save(out / f"t{t}_{i}.tga")
                results[t].save(out / "shared.png")  # every thread, one file
        except Exception as e:  # noqa: BLE001 (reported below, by thread)
            errors.append(f"thread {t}: {e!r}")

    threads = [threading.Thread(target=saves, args=(t,)) for t in range(THREADS)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert errors == []
    for t in range(THREADS):
        for i in range(SAVES):
            assert (out / f"t{t}_{i}.png").read_bytes() == expected_png[t], (t, i)
            assert (out / f"t{t}_{i}.tga").read_bytes() == expected_tga[t], (t, i)
    assert (out / "shared.png").read_bytes() in expected_png  # one save's, whole
    assert len(list(out.iterdir())) == THREADS * SAVES * 2 + 1  # no temporary left


# Small renders of the threaded lessons: lesson 09's maps, irradiance and
# blurred maps, lesson 10's occlusion and bake, lesson 12's tiles.
RENDERS = [
    lambda: rasterlab.lesson09.render(width=48, height=32, map_size=16, glossy_size=8,
                                      glossy_samples=4),
    lambda: rasterlab.lesson10.render(width=48, height=32, ao="baked", samples=4),
    lambda: rasterlab.lesson10.render(width=48, height=32, ao="horizon"),
    lambda: rasterlab.lesson12.render(width=48, height=32, frames=2),
]


def test_renders_from_threads_at_once_give_their_pictures():
    expected = [numpy.array(render().image) for render in RENDERS]  # one at a time
    got = [None] * len(RENDERS)
    errors = []
    start = threading.Barrier(len(RENDERS))

    def renders(i):
        try:
            start.wait()
            got[i] = numpy.array(RENDERS[i]().image)
        except Exception as e:  # noqa: BLE001 (reported below, by render)
            errors.append(f"render {i}: {e!r}")

    threads = [threading.Thread(target=renders, args=(i,)) for i in range(len(RENDERS))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert errors == []
    for i, (a, b) in enumerate(zip(expected, got)):
        assert numpy.array_equal(a, b), f"render {i} differs when drawn beside the others"

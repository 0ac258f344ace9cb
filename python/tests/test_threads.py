"""Threads: saves from several threads at once (Result.save releases the
GIL) each write their whole file, with no temporary left behind."""

import threading

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

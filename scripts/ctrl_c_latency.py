#!/usr/bin/env python3
"""How soon Ctrl-C stops a render from Python: each call runs in a child
process of the built module (build/python), is sent SIGINT some seconds in,
and the seconds from the signal to its KeyboardInterrupt are printed, three
runs each. The table of docs/python.md#ctrl-c comes from this. Run it on an
idle machine: `/usr/bin/python3 scripts/ctrl_c_latency.py [build]`."""

import os
import pathlib
import signal
import subprocess
import sys
import time

# The child: runs one call, and says whether it finished or was interrupted,
# and when (python/tests/test_interrupts.py runs it too).
CHILD = r"""
import sys, time, rasterlab
call = eval("lambda: " + sys.argv[1])
print("started", flush=True)
try:
    call()
    print("finished", time.monotonic(), flush=True)
except KeyboardInterrupt:
    print("interrupted", time.monotonic(), flush=True)
"""

# (the call, seconds after its start to send the signal: inside its drawing)
CALLS = [("rasterlab.lesson12.render(frames=1000)", 0.5),
         ("rasterlab.lesson12.render(width=16384, height=16384, frames=1)", 3.0),
         ("rasterlab.lesson05.render(width=4096, height=4096)", 0.5),
         ("rasterlab.lesson07.render(width=4096, height=4096)", 0.5),
         ("rasterlab.lesson08.render(width=4096, height=4096)", 0.5),
         ("rasterlab.lesson07.render(width=16384, height=16384)", 5.0),
         ("rasterlab.lesson08.render(width=16384, height=16384)", 5.0),
         ("rasterlab.lesson04.draw(width=16384, height=16384)", 6.0),
         ("rasterlab.lesson09.render(map_size=2048, width=64, height=64)", 2.0),
         ("rasterlab.lesson10.render(['obj/torus.obj', 'obj/globe.obj', 'obj/rock.obj'] * 2, "
          "ao='baked', samples=1024, width=64, height=64)", 2.0)]


def latency(module_dir, expression, after):
    child = subprocess.Popen([sys.executable, "-c", CHILD, expression],
                             env=dict(os.environ, PYTHONPATH=module_dir), stdout=subprocess.PIPE,
                             text=True)
    if child.stdout.readline().strip() != "started":
        raise SystemExit(f"{expression}: the child did not start")
    time.sleep(after)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=600)
    word, when = out.split()
    return f"{float(when) - sent:.2f}" if word == "interrupted" else "finished first"


def main():
    build = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "build")
    module_dir = str((build / "python").resolve())
    for expression, after in CALLS:
        runs = [latency(module_dir, expression, after) for _ in range(3)]
        print(f"{expression} (signal after {after} s): {', '.join(runs)} s", flush=True)


if __name__ == "__main__":
    main()

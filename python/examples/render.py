"""Renders lesson 07's scene from Python and saves it as a PNG.

    build/python/python3 python/examples/render.py [out.png]     # or a venv's python after pip install

The same picture as `07_normal_mapping -o out.png`, byte for byte; then the
same scene without its normal maps, and how many pixels that changes.
"""

import sys

import numpy as np

import rasterlab

output = sys.argv[1] if len(sys.argv) > 1 else "render.png"

mapped = rasterlab.lesson07.render()  # every option at the program's default
mapped.save(output)
print(f"lesson 07: {mapped.width}x{mapped.height}, {mapped.counts['faces']} faces, "
      f"{mapped.counts['fragments']} fragments shaded; wrote {output}")

plain = rasterlab.lesson07.render(normal_map="none")
changed = np.any(mapped.image != plain.image, axis=2)
print(f"without normal maps, {changed.mean():.1%} of the pixels change")

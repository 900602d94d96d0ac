#!/usr/bin/python3
"""Independent oracle for the force-induced error model
y = b0 + b1 a + b2 f + b12 a f + b11 a^2 + b22 f^2:
numpy.linalg.lstsq on the raw (unscaled) design, no code of this project.

Reads calibration records as JSON Lines with a, f, y on stdin (blank lines
skipped); prints one JSON object {"b0", "b1", "b2", "b12", "b11", "b22",
"r2"}. r2 = 1 - SSE/SST about the mean of y, and 1 when SST == 0 (every y
equal), the library's convention."""
import json
import sys

import numpy as np

rows = [json.loads(line) for line in sys.stdin if line.strip()]
a = np.array([r["a"] for r in rows], dtype=float)
f = np.array([r["f"] for r in rows], dtype=float)
y = np.array([r["y"] for r in rows], dtype=float)
design = np.column_stack([np.ones_like(a), a, f, a * f, a * a, f * f])
beta = np.linalg.lstsq(design, y, rcond=None)[0]
sse = float(np.sum((y - design @ beta) ** 2))
sst = float(np.sum((y - y.mean()) ** 2))
out = dict(zip(["b0", "b1", "b2", "b12", "b11", "b22"], map(float, beta)))
out["r2"] = 1 - sse / sst if sst > 0 else 1.0
print(json.dumps(out))

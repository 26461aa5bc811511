r"""Region ``polygon``: a flat polygon in space, given point by point (a surface, e.g. for walls).

The first three points fix the normal,

.. math::

    \mathbf{n} = \frac{(\mathbf{p}_2-\mathbf{p}_1)\times(\mathbf{p}_3-\mathbf{p}_1)}
                      {\lvert(\mathbf{p}_2-\mathbf{p}_1)\times(\mathbf{p}_3-\mathbf{p}_1)\rvert}

(PDPS manual). All points must lie in that plane. A polygon has no inside: it cannot hold particles or
make a box; wall styles use its ``points`` and ``normal``.

Syntax::

    region ID polygon p1 x y z p2 x y z p3 x y z [p4 x y z ...]

Example::

    region wall1 polygon p1 15 0 0 p2 15 10 0 p3 10 10 0 p4 10 0 0
"""

import numpy as np
from pydantic import model_validator

from pdps_core.api import Region, ScriptError, StyleArgs


class RegionPolygon(Region):
    name = "polygon"
    usage = "region ID polygon p1 x y z p2 x y z p3 x y z ..."

    class Args(StyleArgs):
        words: list[str]

        @model_validator(mode="after")
        def _points(self):
            w = self.words
            if len(w) % 4 or len(w) < 12:
                raise ValueError("expected at least 3 points, each a label and x y z")
            for k in range(0, len(w), 4):
                for value in w[k + 1:k + 4]:
                    try:
                        float(value)
                    except ValueError:
                        raise ValueError(f"point {w[k]}: coordinate must be a number (got {value})") from None
            return self

    def __init__(self, sim, id, args):
        super().__init__(sim, id, args)
        w = args.words
        self.labels = w[0::4]
        self.points = np.array([[float(c) for c in w[k + 1:k + 4]] for k in range(0, len(w), 4)])
        normal = np.cross(self.points[1] - self.points[0], self.points[2] - self.points[0])
        length = np.linalg.norm(normal)
        if length == 0:
            raise ScriptError(f"region {id}: the first three points are on one line")
        self.normal = normal / length
        off_plane = np.abs((self.points - self.points[0]) @ self.normal)
        if off_plane.max() > 1e-9 * max(1.0, np.abs(self.points).max()):
            k = int(off_plane.argmax())
            raise ScriptError(f"region {id}: point {self.labels[k]} is not in the plane of the first three")

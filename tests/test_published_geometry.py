#!/usr/bin/env python3
"""validation/published/high_pressure.py's ring geometry on hand-made rings with known answers:
a cell's extent along x or y over the box length, also for a ring longer than half the box whose
vertices are wrapped into the box, and the shortest segment over its preferred length, with the
cell (numbered from 1) each belongs to. Exit 77 (skip) only if numpy is missing."""
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import viz_helpers as vh  # noqa: E402

vh.require(["numpy"])
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(HERE), "validation", "published"))
import frames  # noqa: E402
import high_pressure  # noqa: E402

L = 10.0


def rectangle(x0, y0, width, height, per_side, l0_scale=1.0):
    """Counter-clockwise ring of a width x height rectangle from corner (x0, y0), per_side
    vertices along each side, wrapped into the box; l0 = l0_scale times each segment's length."""
    corners = np.array([[0, 0], [width, 0], [width, height], [0, height], [0, 0]], float)
    points = np.concatenate([a + (b - a) * t[:, None] for a, b in zip(corners, corners[1:])
                             for t in [np.arange(per_side) / per_side]])
    x, y = (x0 + points[:, 0]) % L, (y0 + points[:, 1]) % L
    lengths = np.hypot(*(np.roll(points, -1, axis=0) - points).T)
    n = len(x)
    return frames.Cell(x, y, np.full(n, 0.05), l0_scale * lengths, np.zeros(n), width * height)


class RingGeometry(unittest.TestCase):
    def test_small_cells(self):
        tissue = frames.Tissue(L, [rectangle(1, 1, 2, 1, 4), rectangle(5, 5, 1, 3, 4)], [])
        span, span_cell, short, short_cell = high_pressure.ring_geometry(tissue)
        self.assertAlmostEqual(span, 0.3, places=12)
        self.assertEqual(span_cell, 2)
        self.assertAlmostEqual(short, 1.0, places=12)

    def test_cell_longer_than_half_the_box_across_its_edge(self):
        # 7 along x from x = 6: its vertices wrap to x < 3; read coordinate by coordinate the
        # ring would span nearly the whole box
        long_cell = rectangle(6, 2, 7, 0.5, 14)
        self.assertGreater(np.ptp(long_cell.x), 0.9 * L)
        tissue = frames.Tissue(L, [rectangle(1, 5, 1, 1, 4), long_cell], [])
        span, span_cell, _, _ = high_pressure.ring_geometry(tissue)
        self.assertAlmostEqual(span, 0.7, places=12)
        self.assertEqual(span_cell, 2)

    def test_shortest_segment_over_its_preferred_length(self):
        collapsed = rectangle(3, 3, 1, 1, 4)
        x, y = collapsed.x.copy(), collapsed.y.copy()
        x[1] = x[0] + 0.01    # segment 0-1: 0.01 long, l0 0.25 (as before the move)
        collapsed = collapsed._replace(x=x, y=y)
        tissue = frames.Tissue(L, [rectangle(6, 6, 1, 1, 4, l0_scale=2.0), collapsed], [])
        _, _, short, short_cell = high_pressure.ring_geometry(tissue)
        self.assertAlmostEqual(short, 0.04, places=12)
        self.assertEqual(short_cell, 2)
        # the stretched cell alone: every segment at half its preferred length
        stretched = tissue._replace(cells=tissue.cells[:1])
        _, _, short, short_cell = high_pressure.ring_geometry(stretched)
        self.assertAlmostEqual(short, 0.5, places=12)
        self.assertEqual(short_cell, 1)


if __name__ == "__main__":
    unittest.main()

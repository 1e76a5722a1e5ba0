"""The pictures' depth buffer against a pixel-by-pixel reference: every pixel shows the nearest
triangle whose inside holds its centre, whatever the triangles' sizes."""
import unittest

import numpy as np

from aeronc.reports import picture


def reference(px, py, pz, size):
    """One pixel at a time, one triangle at a time: the definition, slowly."""
    zbuf = np.full(size * size, -np.inf)
    owner = np.full(size * size, -1)
    for t in range(len(px)):
        xs, ys, zs = px[t], py[t], pz[t]
        d = (ys[1] - ys[2]) * (xs[0] - xs[2]) + (xs[2] - xs[1]) * (ys[0] - ys[2])
        if abs(d) < 1e-12:
            continue
        for j in range(size):
            for i in range(size):
                cx, cy = i + 0.5, j + 0.5
                w0 = ((ys[1] - ys[2]) * (cx - xs[2]) + (xs[2] - xs[1]) * (cy - ys[2])) / d
                w1 = ((ys[2] - ys[0]) * (cx - xs[2]) + (xs[0] - xs[2]) * (cy - ys[2])) / d
                w2 = 1 - w0 - w1
                if min(w0, w1, w2) < -1e-6:
                    continue
                z = w0 * zs[0] + w1 * zs[1] + w2 * zs[2]
                if z > zbuf[j * size + i]:
                    zbuf[j * size + i], owner[j * size + i] = z, t
    return zbuf, owner


class DepthBufferTest(unittest.TestCase):
    def test_matches_the_reference_for_small_and_large_triangles(self):
        rng = np.random.default_rng(7)
        size = 40
        small = rng.uniform(0, size, (60, 1, 2)) + rng.uniform(-2, 2, (60, 3, 2))
        large = rng.uniform(-10, size + 10, (6, 3, 2))  # larger than the picture, partly outside
        xy = np.concatenate([small, large])
        px, py = xy[:, :, 0], xy[:, :, 1]
        pz = rng.uniform(-5, 5, (len(xy), 3))
        zbuf, owner = picture._zbuffer(px, py, pz, size, budget=500)  # small groups: the chunking too
        want_z, want_owner = reference(px, py, pz, size)
        self.assertTrue((owner >= 0).sum() > size * size // 2)
        np.testing.assert_array_equal(owner, want_owner)
        np.testing.assert_allclose(zbuf[owner >= 0], want_z[owner >= 0])


if __name__ == "__main__":
    unittest.main()

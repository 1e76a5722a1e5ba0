"""The toolpath binding: JSON units in, moves out, ToolpathError on bad input, and the batch
form computing without the GIL."""
import json
import threading
import time
import unittest

from aeronc import _core


def _pocket(size=60.0, name=None):
    unit = {"operation": "pocket", "contour": [[0, 0], [size, 0], [size, 40], [0, 40]],
            "islands": [[[20, 15], [30, 15], [30, 25], [20, 25]]], "top": 0, "bottom": -6, "stepDown": 3,
            "stepOver": 4, "radialAllowance": 0.2, "cutter": {"diameter": 8}}
    if name:
        unit["name"] = name
    return json.dumps(unit)


class ToolpathBindingTest(unittest.TestCase):
    def test_pocket_reaches_its_floor_inside_its_walls(self):
        out = json.loads(_core.toolpath(_pocket()))
        moves = out["moves"]
        self.assertGreater(len(moves), 100)
        self.assertEqual({m[0] for m in moves} - {0, 1, 2}, set())
        self.assertAlmostEqual(min(m[3] for m in moves), -6.0, places=9)
        for kind, u, v, h in moves:
            if h < 0:  # below the top: inside the walls by the cutter radius and the allowance
                self.assertGreaterEqual(min(u, v, 60 - u, 40 - v), 4.2 - 1e-6)
        self.assertGreater(out["cutLength"], 0)
        self.assertGreater(out["rapidLength"], 0)

    def test_bad_unit_raises_toolpath_error_naming_it(self):
        bad = json.loads(_pocket(name="P9"))
        bad["cutter"]["diameter"] = 100
        with self.assertRaises(_core.ToolpathError) as ctx:
            _core.toolpath(json.dumps(bad))
        self.assertIn("unit 'P9'", str(ctx.exception))
        self.assertIn("does not fit", str(ctx.exception))
        self.assertTrue(issubclass(_core.ToolpathError, RuntimeError))
        with self.assertRaises(_core.ToolpathError) as ctx:
            _core.toolpaths([_pocket(), "{}"])
        self.assertIn("unit 1", str(ctx.exception))
        # Computed side by side, the first unit that fails is the one named.
        with self.assertRaises(_core.ToolpathError) as ctx:
            _core.toolpaths([_pocket(), _pocket(), "{}", _pocket(), "[]"] + [_pocket()] * 20)
        self.assertIn("unit 2", str(ctx.exception))

    def test_batch_matches_single_units(self):
        units = [_pocket(50 + i) for i in range(25)]
        self.assertEqual(_core.toolpaths(units), [_core.toolpath(u) for u in units])

    def test_batch_lets_other_threads_run(self):
        units = [_pocket(60 + i % 40) for i in range(400)]
        window = {}

        def work():
            window["start"] = time.perf_counter()
            _core.toolpaths(units)
            window["end"] = time.perf_counter()

        ticks = []
        worker = threading.Thread(target=work)
        worker.start()
        while worker.is_alive():
            ticks.append(time.perf_counter())
        worker.join()
        start, end = window["start"], window["end"]
        self.assertGreater(end - start, 0.05)
        # The main thread ran while the batch was inside the core: the GIL was released.
        inside = [t for t in ticks if start + 0.2 * (end - start) < t < end - 0.2 * (end - start)]
        self.assertGreater(len(inside), 10)


if __name__ == "__main__":
    unittest.main()

"""The gate's dependents: what a left-out operation takes with it. An element's later operations
go with it, and, when it is a roughing, those of the elements inside it; a roughing that stops short of its element's
floor (deeper than every end mill reaches) takes nothing with it, and left out alone it leaves
the programs incomplete, not unready."""
import json
import unittest

from aeronc.pipeline import gate


class _Op:
    def __init__(self, label, element, unit=None):
        self.Label = label
        self.ElementId = element
        self.Unit = json.dumps(unit or {})


# Element 1 holds element 2; element 3 stands apart.
RESULT = {"elements": [{"id": 1, "parent": -1}, {"id": 2, "parent": 1}, {"id": 3, "parent": -1}]}


class DependentsTest(unittest.TestCase):
    def ops(self, short_of_floor):
        return [_Op("Pocket E1 r U0", 1, {"step": "r", "shortOfFloor": True} if short_of_floor else {"step": "r"}),
                _Op("Pocket E2 r U1", 2), _Op("Profile E2 fs U2", 2), _Op("Pocket E3 r U3", 3)]

    def test_a_left_out_roughing_takes_the_elements_inside_with_it(self):
        out = gate.dependents(self.ops(False), {"Pocket E1 r U0": "gouges"}, RESULT)
        self.assertEqual(sorted(out), ["Pocket E2 r U1", "Profile E2 fs U2"])
        self.assertIn("left out with Pocket E1 r U0", out["Pocket E2 r U1"])

    def test_a_roughing_short_of_its_floor_takes_nothing_with_it(self):
        self.assertEqual(gate.dependents(self.ops(True), {"Pocket E1 r U0": "gouges"}, RESULT), {})

    def test_a_left_out_finishing_takes_its_own_elements_later_operations_only(self):
        ops = [_Op("Pocket E1 r U0", 1, {"step": "r"}), _Op("Profile E1 sf U1", 1, {"step": "sf"}),
               _Op("Pocket E2 r U2", 2, {"step": "r"}), _Op("Profile E1 ff U3", 1, {"step": "ff"}),
               _Op("Profile E2 fs U4", 2, {"step": "fs"})]
        out = gate.dependents(ops, {"Profile E1 sf U1": "no toolpath"}, RESULT)
        self.assertEqual(sorted(out), ["Profile E1 ff U3"])
        # The roughing left out takes the element inside, and that element's later operations.
        out = gate.dependents(ops, {"Pocket E1 r U0": "gouges"}, RESULT)
        self.assertEqual(sorted(out), ["Pocket E2 r U2", "Profile E1 ff U3", "Profile E1 sf U1", "Profile E2 fs U4"])

    def test_an_element_apart_is_not_taken(self):
        out = gate.dependents(self.ops(False), {"Pocket E2 r U1": "gouges"}, RESULT)
        self.assertEqual(sorted(out), ["Profile E2 fs U2"])


class VerdictTest(unittest.TestCase):
    """A roughing short of its floor left out alone leaves the programs incomplete, not unready;
    any other operation left out makes them not ready."""

    def data(self, kinds):
        return {"part": "p", "programs": [{"path": "p.mpf"}],
                "leftOut": [{"label": "Pocket E{} r U{}".format(k, k), "kind": kind, "reason": "gouges"}
                            for k, kind in enumerate(kinds)],
                "materialLeft": [{"element": 0, "faces": [3], "area": 100.0, "maxLeft": 30.0, "reason": "x"}]}

    def test_short_of_floor_alone_is_incomplete(self):
        from aeronc.runs.main_job import SHORT_OF_FLOOR, verdict_of
        v = verdict_of(self.data([SHORT_OF_FLOOR]))
        self.assertEqual(v["status"], "INCOMPLETE")
        self.assertIn("1 operation left out of the programs (1 is a roughing short of its floor)", v["text"])
        self.assertIn("the programs neither gouge nor rapid through material", v["text"])

    def test_any_other_left_out_is_not_ready(self):
        from aeronc.runs.main_job import SHORT_OF_FLOOR, verdict_of
        self.assertEqual(verdict_of(self.data([SHORT_OF_FLOOR, "gouge"]))["status"], "NOT READY")
        self.assertEqual(verdict_of(self.data(["dependent"]))["status"], "NOT READY")


if __name__ == "__main__":
    unittest.main()

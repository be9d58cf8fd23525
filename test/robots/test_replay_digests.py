"""Every shipped configuration replays its shipped bag to the CSV recorded in
replay_digests.txt, to the bit (tools/eval/replay_digests.py): a change that moves an estimate
of any node shows here, node by node, and is either a fault or a deliberate change that
rewrites the file with its reason in the commit (doc/evaluation.md, "Replay digests")."""

import os
import sys
import unittest

from replay_helpers import REPO, built_lib_dir

sys.path.insert(0, os.path.join(REPO, "tools", "eval"))
import replay_digests  # noqa: E402

TABLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "replay_digests.txt")


class ReplayDigestsTest(unittest.TestCase):
    def test_every_shipped_replay_is_the_recorded_one(self):
        expected = replay_digests.read_table(TABLE)
        self.assertEqual(sorted(expected), sorted(replay_digests.PAIRS),
                         "replay_digests.txt and replay_digests.PAIRS list different replays")
        lib_dir = built_lib_dir(replay_digests.PAIRS[0][0])
        for node, bag in replay_digests.PAIRS:
            with self.subTest(node=node, bag=bag):
                sha = replay_digests.digest(lib_dir, node, bag)
                if sha is None:
                    self.skipTest("%s not built" % node)
                self.assertEqual(sha, expected[(node, bag)],
                                 "%s --replay %s gives another CSV than recorded" % (node, bag))


if __name__ == "__main__":
    unittest.main()

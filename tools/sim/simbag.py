"""Shared helpers of the bag simulators in tools/sim/ (pioneer_sim.py, soccer_sim.py,
diff_drive_sim.py).

Time is kept as integer nanoseconds since the start of the run, so that sample times
such as k/32 s are exact and a run is reproducible bit for bit. A message's bag time
and its header stamp are both the simulated sample time (plus an optional transport
delay for the bag time), offset by a fixed start epoch, so `rosbag play --clock`
replays the simulated clock.

Random numbers come from Python's `random.Random`, seeded with a string naming the run
and the noise source ("pioneer/1/accel", ...). String seeding and the Mersenne Twister
stream of `random.Random` are stable across Python 3 versions, and every noise source
has its own stream, so changing one source (or the length of the run) does not shift
the noise of the others.
"""

import os
import random
import sys

import genpy
import rosbag

NS_PER_S = 1000000000

# Start of the simulated clock: 2023-11-14 22:13:20 UTC. Any fixed value works; a
# wall-clock-like epoch avoids ROS treating time 0 as "unset".
DEFAULT_START_S = 1700000000

COMPRESSIONS = ("bz2", "lz4", "none")


def rng(*names):
    """Independent, reproducible random stream for the noise source named by *names*."""
    return random.Random("/".join(str(n) for n in names))


def to_time(ns):
    """genpy.Time from integer nanoseconds (exact, no float rounding)."""
    return genpy.Time(ns // NS_PER_S, ns % NS_PER_S)


def quantise(value, step):
    """Round *value* to a multiple of *step*, as a sensor's ADC/counter does."""
    return round(value / step) * step


class BagBuilder:
    """Collects messages and writes them in time order into a bag.

    Messages are sorted by (bag time, topic rank, insertion order), so that the
    bag's content does not depend on the order in which the simulator produced them.
    """

    def __init__(self, start_s=DEFAULT_START_S):
        self.start_ns = int(start_s) * NS_PER_S
        self._items = []
        self._rank = {}
        self._seq = {}
        self._latched = set()

    def stamp(self, t_ns):
        """Header stamp for the simulated time t_ns (ns since the run's start)."""
        return to_time(self.start_ns + t_ns)

    def next_seq(self, topic):
        seq = self._seq.get(topic, 0)
        self._seq[topic] = seq + 1
        return seq

    def skip_seq(self, topic):
        """A sample that was taken but lost: the publisher's sequence number still advances."""
        self.next_seq(topic)

    def add(self, topic, msg, t_ns):
        rank = self._rank.setdefault(topic, len(self._rank))
        self._items.append((t_ns, rank, len(self._items), topic, msg))

    def latch(self, topic):
        """Record *topic* as latched (connection header latching=1, as rosbag record stores
        /tf_static), so that rosbag play republishes it latched."""
        self._latched.add(topic)

    def counts(self):
        out = {}
        for item in self._items:
            out[item[3]] = out.get(item[3], 0) + 1
        return out

    def write(self, path, compression="bz2"):
        """Write the bag to *path* (atomically: a temporary file is renamed at the end)."""
        if compression not in COMPRESSIONS:
            raise ValueError("compression must be one of %s" % (COMPRESSIONS,))
        directory = os.path.dirname(os.path.abspath(path))
        os.makedirs(directory, exist_ok=True)
        tmp = path + ".tmp"
        self._items.sort(key=lambda item: item[:3])
        with rosbag.Bag(tmp, "w", compression=compression) as bag:
            for t_ns, _, _, topic, msg in self._items:
                header = None
                if topic in self._latched:
                    header = {"topic": topic, "type": msg._type, "md5sum": msg._md5sum,
                              "message_definition": msg._full_text, "latching": "1"}
                bag.write(topic, msg, to_time(self.start_ns + t_ns), connection_header=header)
        os.replace(tmp, path)


def log(*args):
    print(*args, file=sys.stderr)

#!/usr/bin/python3
"""rosbag play for the shipped launch files: plays the bag and, with --end-launch, ends the
roslaunch that started it once the bag is over, the way Ctrl-C would.

A rosbag play node marked required="true" ends a launch too, but roslaunch reports every
exit of a required node as a red "REQUIRED process [player] has died!", also the normal end
of a bag. Here the player asks roslaunch to shut down (SIGINT to its parent roslaunch
process) and exits 0: the nodes stop, rosbag record closes its bag, and the launch prints
no error. A bag that cannot be played still ends the launch, with rosbag's exit code.

  <node pkg="sf_pkg" type="play_bag.py" name="player" args="--end-launch --clock bag.bag"/>

Every argument but --end-launch goes to `rosbag play` unchanged (also roslaunch's
__name:=player, so the player keeps its node name). Without --end-launch, or when the parent
is not roslaunch (rostest, a shell), it only plays the bag.

--uncompressed: plays an uncompressed copy of the bag, written to a temporary directory
before the player starts (and removed after it), of the bag's first `-u SEC` seconds plus one
when -u is given. rosbag play decompresses a compressed bag chunk by chunk while it plays,
and on a busy machine it then stalls for up to a second at each chunk and sends the backlog
at once (doc/reliability.md, "The player's chunk stalls"): a node that aligns by arrival time
puts that backlog into one period. The copy costs a second or two of CPU before the start.
"""

import os
import signal
import subprocess
import sys

END_FLAG = "--end-launch"
UNCOMPRESSED_FLAG = "--uncompressed"


def option_value(args, short, long):
    """The float value of a rosbag play option among `args` (-u 10, --duration 10,
    --duration=10), or None."""
    for k, a in enumerate(args):
        if a in (short, long) and k + 1 < len(args):
            return float(args[k + 1])
        if a.startswith(long + "="):
            return float(a.split("=", 1)[1])
    return None


def played_seconds(args):
    """How far into the bag rosbag play will play (-s start plus -u duration), or None."""
    duration = option_value(args, "-u", "--duration")
    if duration is None:
        return None
    return (option_value(args, "-s", "--start") or 0.0) + duration


def uncompressed_copy(bag_path, out_dir, seconds=None):
    """Writes the messages of `bag_path` (its first `seconds` + 1 s if given) uncompressed to
    out_dir and returns the copy's path. Messages are copied raw (serialized), with their
    connection headers, so the copy plays exactly as the original."""
    import rosbag  # only with --uncompressed: the plain player needs no ROS Python
    out_path = os.path.join(out_dir, os.path.basename(bag_path))
    with rosbag.Bag(bag_path) as src, rosbag.Bag(out_path, "w") as dst:
        end = None
        if seconds is not None:
            import genpy
            end = genpy.Time.from_sec(src.get_start_time() + seconds + 1.0)
        for topic, raw, t, header in src.read_messages(raw=True, end_time=end,
                                                          return_connection_header=True):
            dst.write(topic, raw, t, raw=True, connection_header=header)
    return out_path


def parent_is_roslaunch(ppid):
    """True when process ppid runs roslaunch (python3 /usr/bin/roslaunch ...)."""
    try:
        with open("/proc/%d/cmdline" % ppid, "rb") as f:
            argv = [a.decode(errors="replace") for a in f.read().split(b"\0") if a]
    except OSError:
        return False
    return any(os.path.basename(a) == "roslaunch" for a in argv[:2])


def main(argv=None):
    args = list(sys.argv[1:] if argv is None else argv)
    end_launch = END_FLAG in args
    uncompressed = UNCOMPRESSED_FLAG in args
    args = [a for a in args if a not in (END_FLAG, UNCOMPRESSED_FLAG)]
    launcher = os.getppid()
    if uncompressed:
        import tempfile
        copy_dir = tempfile.TemporaryDirectory(prefix="sf_play_bag_")
        bags = [k for k, a in enumerate(args) if a.endswith(".bag") and os.path.isfile(a)]
        if not bags:
            print("play_bag.py: --uncompressed: no bag file among the arguments", file=sys.stderr)
            return 1
        for k in bags:
            args[k] = uncompressed_copy(args[k], copy_dir.name, played_seconds(args))
    try:
        player = subprocess.Popen(["rosbag", "play"] + args)
    except OSError as e:
        print("play_bag.py: cannot start rosbag play: %s" % e, file=sys.stderr)
        return 1
    try:
        code = player.wait()
    except KeyboardInterrupt:
        # roslaunch is shutting down: it sends SIGINT to the process group, rosbag included
        try:
            player.wait(timeout=10)
        except (KeyboardInterrupt, subprocess.TimeoutExpired):
            player.kill()
        return 0
    if end_launch and parent_is_roslaunch(launcher):
        if code == 0:
            print("play_bag.py: the bag has been played, ending the launch", flush=True)
        # SIGINT is roslaunch's Ctrl-C: it stops every node it started and exits.
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        os.kill(launcher, signal.SIGINT)
    return code


if __name__ == "__main__":
    sys.exit(main())

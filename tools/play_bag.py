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
"""

import os
import signal
import subprocess
import sys

END_FLAG = "--end-launch"


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
    args = [a for a in args if a != END_FLAG]
    launcher = os.getppid()
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

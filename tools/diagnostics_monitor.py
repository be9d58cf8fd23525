#!/usr/bin/python3
"""Watch /diagnostics in a terminal: the latest status of every name as a compact table.

Debian 12 packages neither rqt_runtime_monitor nor rqt_robot_monitor, and
`rostopic echo /diagnostics` prints every array in full. This prints one line per status
name: level, name, message and how long ago it was last refreshed; a status that has not
been refreshed for --stale seconds is shown as STALE, the way the robot monitor does.

  rosrun sf_pkg diagnostics_monitor.py                  # redraws every second
  rosrun sf_pkg diagnostics_monitor.py --once           # one table of the first array, then exit
  rosrun sf_pkg diagnostics_monitor.py --filter estimation --keys

Needs python3-rospy and python3-diagnostic-msgs (both in the set-up's package list).
"""

import argparse
import re
import sys
import time

LEVEL_NAMES = {0: "OK", 1: "WARN", 2: "ERROR", 3: "STALE"}


def level_of(status):
    """The level of a diagnostic_msgs/DiagnosticStatus as an int (genpy gives a byte field as
    an int, a hand-made message may hold bytes)."""
    level = status.level
    if isinstance(level, (bytes, bytearray)):
        level = level[0] if level else 0
    return int(level)


def update(latest, array, received):
    """Keeps the newest status of every name: latest maps name -> (status, received time)."""
    for status in array.status:
        latest[status.name] = (status, received)
    return latest


def format_table(latest, now, stale_after=5.0, name_filter=None, keys=False, width=None):
    """The table of the statuses in latest (name -> (status, received time [s])) at time now.

    Columns: level (STALE when not refreshed for stale_after seconds), name, message and
    refreshed (seconds since the status last arrived). Sorted by name; name_filter (a regular
    expression) keeps the matching names; keys adds each status's key/value pairs below it.
    width (characters) shortens long messages to fit."""
    rows = []
    for name in sorted(latest):
        if name_filter and not re.search(name_filter, name):
            continue
        status, received = latest[name]
        age = max(0.0, now - received)
        level = LEVEL_NAMES.get(level_of(status), str(level_of(status)))
        if stale_after and age > stale_after:
            level = "STALE"
        rows.append((level, name, status.message, "%.1f s ago" % age, status.values))
    if not rows:
        return "no diagnostics received yet" if not latest else "no status matches the filter"
    level_w = max(len("LEVEL"), max(len(r[0]) for r in rows))
    name_w = max(len("NAME"), max(len(r[1]) for r in rows))
    age_w = max(len("REFRESHED"), max(len(r[3]) for r in rows))
    message_w = None
    if width:
        message_w = max(10, width - level_w - name_w - age_w - 6)
    lines = ["%-*s  %-*s  %-*s  %s" % (level_w, "LEVEL", name_w, "NAME", age_w, "REFRESHED",
                                       "MESSAGE")]
    for level, name, message, age, values in rows:
        if message_w and len(message) > message_w:
            message = message[:message_w - 3] + "..."
        lines.append("%-*s  %-*s  %-*s  %s" % (level_w, level, name_w, name, age_w, age, message))
        if keys:
            for kv in values:
                lines.append("%*s%s: %s" % (level_w + 4, "", kv.key, kv.value))
    counts = {}
    for row in rows:
        counts[row[0]] = counts.get(row[0], 0) + 1
    summary = ", ".join("%d %s" % (counts[k], k) for k in ("ERROR", "STALE", "WARN", "OK")
                        if k in counts)
    lines.append("%d statuses: %s" % (len(rows), summary))
    return "\n".join(lines)


def parse_args(argv):
    parser = argparse.ArgumentParser(
        description="Show the latest /diagnostics statuses as a table (Debian 12 has no rqt "
                    "robot monitor).")
    parser.add_argument("--topic", default="/diagnostics", help="default: /diagnostics")
    parser.add_argument("--period", type=float, default=1.0,
                        help="seconds between redraws (default 1)")
    parser.add_argument("--stale", type=float, default=5.0,
                        help="seconds without a refresh after which a status shows as STALE "
                             "(default 5; 0: never)")
    parser.add_argument("--filter", help="regular expression: only the names that match")
    parser.add_argument("--keys", action="store_true", help="also print each status's keys")
    parser.add_argument("--once", action="store_true",
                        help="print the table of the first array received and exit")
    parser.add_argument("--timeout", type=float, default=10.0,
                        help="with --once: seconds to wait for an array (default 10)")
    return parser.parse_args(argv)


def main(argv=None):
    import rospy
    from diagnostic_msgs.msg import DiagnosticArray

    args = parse_args(rospy.myargv(sys.argv if argv is None else argv)[1:])
    rospy.init_node("diagnostics_monitor", anonymous=True, disable_signals=False)
    if args.once:
        try:
            array = rospy.wait_for_message(args.topic, DiagnosticArray, timeout=args.timeout)
        except rospy.ROSException:
            print("no DiagnosticArray on %s within %.0f s" % (args.topic, args.timeout),
                  file=sys.stderr)
            return 1
        except rospy.ROSInterruptException:
            return 0
        now = time.monotonic()
        print(format_table(update({}, array, now), now, args.stale, args.filter, args.keys))
        return 0

    latest = {}
    rospy.Subscriber(args.topic, DiagnosticArray,
                     lambda array: update(latest, array, time.monotonic()), queue_size=50)
    tty = sys.stdout.isatty()
    while not rospy.is_shutdown():
        width = None
        if tty:
            import shutil
            width = shutil.get_terminal_size().columns
        table = format_table(dict(latest), time.monotonic(), args.stale, args.filter,
                             args.keys, width)
        try:
            if tty:
                sys.stdout.write("\x1b[H\x1b[2J")  # clear the terminal, cursor home
            else:
                sys.stdout.write("----- %s\n" % time.strftime("%H:%M:%S"))
            sys.stdout.write(table + "\n")
            sys.stdout.flush()
            time.sleep(args.period)
        except KeyboardInterrupt:
            break
        except BrokenPipeError:  # e.g. piped into head
            sys.stderr.close()
            return 0
    return 0


if __name__ == "__main__":
    sys.exit(main())

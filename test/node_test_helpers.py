"""What the rostests that talk to a running fusion node share (test/*_test.py): waiting for
an event, the node's ~state in the class the node publishes, and /diagnostics. The tests
import it from their own folder (the script's folder is first on Python's path)."""

import time

import rospy
import rostopic
from diagnostic_msgs.msg import DiagnosticArray


def wait_for(predicate, seconds, step=0.02):
    """True once predicate() is, False if it was not within `seconds`."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(step)
    return False


def subscribe_states(topic):
    """A list receiving the node's ~state messages on `topic`. The message class is read from
    the published topic (waits for it), so that the test does not name the package that
    defines it."""
    states = []
    state_class, _, _ = rostopic.get_topic_class(topic, blocking=True)
    rospy.Subscriber(topic, state_class, states.append)
    return states


def subscribe_diagnostics():
    """A list receiving every /diagnostics array from now on."""
    reports = []
    rospy.Subscriber("/diagnostics", DiagnosticArray, reports.append)
    return reports

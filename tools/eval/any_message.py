"""Decoding of messages whose Python module is not installed: a rospy.AnyMsg subscriber
gets the publisher's type name and full definition in its connection header, from which
genpy builds the class. Used by the online tests for /diagnostics (python3-diagnostic-msgs
is not among the packages the build installs) and sf_pkg's own messages (the package
generates no Python)."""

import threading

import genpy.dynamic


class AnyMessageDecoder:
    """Callable: decodes a rospy.AnyMsg by the definition its first publisher sent."""

    def __init__(self):
        self.cls = None
        self.lock = threading.Lock()  # rospy calls back from one thread per publisher

    def __call__(self, raw):
        with self.lock:
            if self.cls is None:
                name = raw._connection_header["type"]
                definition = raw._connection_header["message_definition"]
                self.cls = genpy.dynamic.generate_dynamic(name, definition)[name]
        return self.cls().deserialize(raw._buff)

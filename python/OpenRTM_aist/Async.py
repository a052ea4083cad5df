# SPDX-License-Identifier: MIT
"""OpenRTM_aist.Async_tInvoker: calls func(obj) in a thread of its own, as OpenRTM-aist-Python's
asynchronous invoker does; finished() tells when it returned."""

import threading


class Async_tInvoker(object):
    def __init__(self, obj, func, auto_delete=False):
        self._obj = obj
        self._func = func
        self._done = threading.Event()
        self._thread = None

    def invoke(self):
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self):
        try:
            self._func(self._obj)
        finally:
            self._done.set()

    def finished(self):
        return self._done.is_set()

    def wait(self, timeout=None):
        return self._done.wait(timeout)

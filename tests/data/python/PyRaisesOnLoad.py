# SPDX-License-Identifier: MIT
# A component module whose own code raises when it runs (on purpose): a manager must refuse to load
# it, name the file and the line, and go on serving.

import OpenRTM_aist


def fail_while_loading():
    raise RuntimeError("module fails on purpose")  # refused here


fail_while_loading()


def PyRaisesOnLoadInit(manager):
    manager.createComponent("never")

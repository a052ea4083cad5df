# SPDX-License-Identifier: MIT
# A component module that does not compile (on purpose): a manager must refuse to load it and name
# the file and the line.

import OpenRTM_aist


def PyBadSyntaxInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=[""]), None  # refused here: unclosed call

def unreachable():
    pass

# SPDX-License-Identifier: MIT
# A component module whose init function registers its type and then raises (on purpose): the
# manager refuses the module, names the line, and forgets the type.

import OpenRTM_aist

spec = ["implementation_id", "PyInitRaises", "type_name", "PyInitRaises", "language", "Python", ""]


def PyInitRaisesInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=spec), OpenRTM_aist.DataFlowComponentBase,
                            OpenRTM_aist.Delete)
    raise RuntimeError("init fails on purpose")  # refused here

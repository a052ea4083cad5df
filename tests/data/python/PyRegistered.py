# SPDX-License-Identifier: MIT
# A component module whose init function only registers its type, as the Builder's generated ones:
# a manager asked to create the type loads the module from its load path by the type's name.

import OpenRTM_aist
import RTC

registered_spec = ["implementation_id", "PyRegistered", "type_name", "PyRegistered",
                   "description", "Created by type name", "version", "1.0", "vendor", "RT Studio tests",
                   "category", "test", "activity_type", "DataFlowComponent", "max_instance", "2",
                   "language", "Python", "lang_type", "script", ""]


class PyRegistered(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        print(f"PyRegistered initialized as {self._rtc.getInstanceName()}")
        return RTC.RTC_OK


def PyRegisteredInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=registered_spec), PyRegistered,
                            OpenRTM_aist.Delete)

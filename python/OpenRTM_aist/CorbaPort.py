# SPDX-License-Identifier: MIT
"""OpenRTM_aist.CorbaPort: a service port with provided interfaces (servants of generated
<Module>__POA classes) and required ones (CorbaConsumer objects)."""

import _rtstudio


class CorbaPort(_rtstudio.CorbaPort):
    def __init__(self, name):
        _rtstudio.CorbaPort.__init__(self, name)

    def registerConsumer(self, instance_name, type_name, consumer):
        """Declares the required interface instance_name of type type_name; consumer (a
        CorbaConsumer) receives the provider's reference when the port connects."""
        return self._registerConsumerSlot(instance_name, type_name, consumer._slot)

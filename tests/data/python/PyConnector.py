#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# What OpenRTM-aist-Python's ExtTrigger/Connector.py does, with the name server and the naming
# context given (that program asks localhost's default name server): through the ORB alone it
# resolves ConsoleIn0 and ConsoleOut0, disconnects and activates them through their references,
# connects their first ports with a ConnectorProfile of NVUtil properties, then ticks their
# ExtTrigExecutionContexts on the commands it reads: 0 (ConsoleIn), 1 (ConsoleOut), 2 (both), q.
#
#   PyConnector.py NAME_SERVER CONTEXT [manager options…]

import sys

import RTC  # first: the other IDL modules (OpenRTM) import once RTC has
import OpenRTM
import OpenRTM_aist
from omniORB import CORBA


def resolve(naming, path):
    consumer = OpenRTM_aist.CorbaConsumer()
    consumer.setObject(naming.resolve(path))
    component = consumer.getObject()._narrow(RTC.RTObject)
    return component, component.get_ports()


def main():
    name_server, context = sys.argv[1], sys.argv[2]
    manager = OpenRTM_aist.Manager.init(sys.argv[:1] + sys.argv[3:])
    manager.activateManager()
    manager.runManager(True)
    orb = CORBA.ORB_init(sys.argv)
    naming = OpenRTM_aist.CorbaNaming(orb, name_server)
    contexts = []
    ports = []
    for name in ("ConsoleIn0.rtc", "ConsoleOut0.rtc"):
        component, component_ports = resolve(naming, context + name)
        component_ports[0].disconnect_all()
        owned = component.get_owned_contexts()
        print("connector:", name, "activated", owned[0].activate_component(component))
        trigger = OpenRTM_aist.CorbaConsumer(interfaceType=OpenRTM.ExtTrigExecutionContextService)
        trigger.setObject(owned[0])
        contexts.append(trigger)
        ports.append(component_ports[0])
    profile = RTC.ConnectorProfile("connector0", "", ports, [])
    for key, value in (("dataport.interface_type", "corba_cdr"), ("dataport.dataflow_type", "push"),
                       ("dataport.subscription_type", "flush")):
        OpenRTM_aist.CORBA_SeqUtil.push_back(profile.properties, OpenRTM_aist.NVUtil.newNV(key, value))
    result, connected = ports[0].connect(profile)
    print("connector: connect", result, connected.name, bool(connected.connector_id))
    for command in sys.stdin:
        targets = {"0": contexts[:1], "1": contexts[1:], "2": contexts}.get(command.strip())
        if targets is None:
            break
        for trigger in targets:
            trigger._ptr().tick()
        print("connector: ticked", command.strip())
    manager.shutdown()


if __name__ == "__main__":
    main()

# SPDX-License-Identifier: MIT
# One component with an OutPort and an InPort of every data type listed in types.txt beside this
# module (IDL scoped names, one a line; port names o<N> and i<N> by line number from 0). Each
# type's value, made as the Builder's Python projects make it, is sent on its OutPort until its
# InPort gives back an equal one; then it prints "<type>: crossed the ports". A type it cannot
# make a value or ports of prints "<type>: unsupported: <why>".

import importlib
import os
import sys
import time

import OpenRTM_aist
import RTC

alltypes_spec = ["implementation_id", "PyAllTypes", "type_name", "PyAllTypes",
                 "description", "A port pair per data type", "version", "1.0", "vendor", "RT Studio tests",
                 "category", "test", "activity_type", "DataFlowComponent", "max_instance", "1",
                 "language", "Python", "lang_type", "script", ""]


def data_class(scoped_name):
    """The Python class of IDL type scoped_name (RTC::TimedLong → RTC.TimedLong) as a user imports it."""
    parts = scoped_name.split("::")
    found = importlib.import_module(parts[0])
    for part in parts[1:]:
        found = getattr(found, part)
    return found


def report(line):
    # One write, so that the line stays whole beside other components' output.
    sys.stdout.write(line + "\n")


class PyAllTypes(OpenRTM_aist.DataFlowComponentBase):
    def onInitialize(self):
        with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "types.txt")) as listed:
            names = [line.strip() for line in listed if line.strip()]
        self._pending = []
        self._sent = 0.0
        for number, name in enumerate(names):
            try:
                value = OpenRTM_aist.instantiateDataType(data_class(name))
                outport = OpenRTM_aist.OutPort("o%d" % number, value)
                inport = OpenRTM_aist.InPort("i%d" % number, OpenRTM_aist.instantiateDataType(data_class(name)))
                self.addOutPort("o%d" % number, outport)
                self.addInPort("i%d" % number, inport)
                self._pending.append((name, value, outport, inport))
            except Exception as error:
                report("%s: unsupported: %s" % (name, error))
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        # Ten sends a second of each type still waiting, whatever the execution rate.
        send = time.monotonic() - self._sent >= 0.1
        if send:
            self._sent = time.monotonic()
        for entry in list(self._pending):
            name, value, outport, inport = entry
            if inport.isNew():
                received = inport.read()
                report("%s: %s" % (name, "crossed the ports" if received == value else "changed to %r" % received))
                self._pending.remove(entry)
            elif send:
                outport.write()
        return RTC.RTC_OK


def PyAllTypesInit(manager):
    manager.registerFactory(OpenRTM_aist.Properties(defaults_str=alltypes_spec), PyAllTypes, OpenRTM_aist.Delete)
    manager.createComponent("PyAllTypes")

#!/usr/bin/env python3
# -*- coding: utf-8 -*-

"""SampleService_idl_example.py: servants for the interfaces of SampleService.idl.

The component imports its servant classes from here; write each operation's body where it
says TODO. Run on its own, the module serves every interface and prints its IOR.
"""

import omniORB
from omniORB import CORBA, PortableServer
import Sample, Sample__POA
class Echo_i(Sample__POA.Echo):
    """Implements Sample::Echo."""

    def __init__(self):
        pass

    # <rtc-template block="Echo_operations">
    # string version()
    def _get_version(self):
        # TODO: implement _get_version; it returns result
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # long gain()
    def _get_gain(self):
        # TODO: implement _get_gain; it returns result
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # void gain(in long value)
    def _set_gain(self, value):
        # TODO: implement _set_gain
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # void reset()
    def reset(self):
        # TODO: implement reset
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # string say(in string message)
    def say(self, message):
        # TODO: implement say; it returns result
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # boolean numbers(in short s, out long l, inout double d, in octet o, out char c)
    def numbers(self, s, d, o):
        # TODO: implement numbers; it returns result, l, d, c
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # Sample::Point move(in Sample::Point from, out Sample::Point to, inout Sample::Point via)
    def move(self, _from, via):
        # TODO: implement move; it returns result, to, via
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # Sample::Label tag(in Sample::Label item, out Sample::Label copy, inout Sample::Label edited)
    def tag(self, item, edited):
        # TODO: implement tag; it returns result, copy, edited
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # Sample::NameList names(in Sample::NameList filter, out Sample::PointList points, inout Sample::NameList edited)
    def names(self, filter, edited):
        # TODO: implement names; it returns result, points, edited
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # Sample::Matrix rotate(in Sample::Matrix m, out Sample::Matrix inverse, inout Sample::Matrix scratch)
    def rotate(self, m, scratch):
        # TODO: implement rotate; it returns result, inverse, scratch
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # Sample::Mode switchMode(in Sample::Mode next, out Sample::Mode previous, inout Sample::Mode current)
    def switchMode(self, next, current):
        # TODO: implement switchMode; it returns result, previous, current
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # any convert(in any value, out any result, inout any both)
    def convert(self, value, both):
        # TODO: implement convert; it returns result, result, both
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # Sample::Clock exchange(in Sample::Clock other, out Sample::Clock mine, inout Sample::Clock shared)
    def exchange(self, other, shared):
        # TODO: implement exchange; it returns result, mine, shared
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # Sample::Count tally(in Sample::Count c, out Sample::Count total)
    def tally(self, c):
        # TODO: implement tally; it returns result, total
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # RTC::TimedLong sample(in RTC::Time when, out RTC::TimedLong value)
    def sample(self, when):
        # TODO: implement sample; it returns result, value
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # void notify(in string event)
    def notify(self, event):
        # TODO: implement notify
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # </rtc-template>

if __name__ == "__main__":
    import sys

    orb = CORBA.ORB_init(sys.argv)
    poa = orb.resolve_initial_references("RootPOA")

    # A Sample::Echo object; a client reaches it through the printed IOR.
    servant = Echo_i()
    poa.activate_object(servant)
    objref = servant._this()
    print(orb.object_to_string(objref))

    # Serve calls until the process is stopped.
    poa._get_the_POAManager().activate()
    orb.run()

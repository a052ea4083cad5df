#!/usr/bin/env python3
# -*- coding: utf-8 -*-
# -*- Python -*-

"""
 @file SampleService_idl_example.py
 @brief Servant skeletons of the interfaces in SampleService.idl
"""

import omniORB
from omniORB import CORBA, PortableServer
import Sample, Sample__POA
class Echo_i(Sample__POA.Echo):
    """
    @class Echo_i
    Servant of IDL interface Sample::Echo
    """

    def __init__(self):
        """
        @brief standard constructor
        Initialise member variables here
        """
        pass

    # <rtc-template block="Echo_operations">
    # string version()
    def _get_version(self):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result
    # long gain()
    def _get_gain(self):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result
    # void gain(in long value)
    def _set_gain(self, value):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # void reset()
    def reset(self):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # string say(in string message)
    def say(self, message):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result
    # boolean numbers(in short s, out long l, inout double d, in octet o, out char c)
    def numbers(self, s, d, o):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, l, d, c
    # Sample::Point move(in Sample::Point from, out Sample::Point to, inout Sample::Point via)
    def move(self, _from, via):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, to, via
    # Sample::Label tag(in Sample::Label item, out Sample::Label copy, inout Sample::Label edited)
    def tag(self, item, edited):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, copy, edited
    # Sample::NameList names(in Sample::NameList filter, out Sample::PointList points, inout Sample::NameList edited)
    def names(self, filter, edited):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, points, edited
    # Sample::Matrix rotate(in Sample::Matrix m, out Sample::Matrix inverse, inout Sample::Matrix scratch)
    def rotate(self, m, scratch):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, inverse, scratch
    # Sample::Mode switchMode(in Sample::Mode next, out Sample::Mode previous, inout Sample::Mode current)
    def switchMode(self, next, current):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, previous, current
    # any convert(in any value, out any result, inout any both)
    def convert(self, value, both):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, result, both
    # Sample::Clock exchange(in Sample::Clock other, out Sample::Clock mine, inout Sample::Clock shared)
    def exchange(self, other, shared):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, mine, shared
    # Sample::Count tally(in Sample::Count c, out Sample::Count total)
    def tally(self, c):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, total
    # RTC::TimedLong sample(in RTC::Time when, out RTC::TimedLong value)
    def sample(self, when):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, value
    # void notify(in string event)
    def notify(self, event):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # </rtc-template>

if __name__ == "__main__":
    import sys

    # Initialise the ORB
    orb = CORBA.ORB_init(sys.argv)

    # As an example, we activate an object in the Root POA
    poa = orb.resolve_initial_references("RootPOA")

    # Create an instance of a servant class
    servant = Echo_i()

    # Activate it in the Root POA
    poa.activate_object(servant)

    # Get the object reference to the object
    objref = servant._this()

    # Print a stringified IOR for it
    print(orb.object_to_string(objref))

    # Activate the Root POA's manager
    poa._get_the_POAManager().activate()

    # Run the ORB, blocking this thread
    orb.run()

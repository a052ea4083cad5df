#!/usr/bin/env python3
# -*- coding: utf-8 -*-

"""Robotics_idl_example.py: servants for the interfaces of Robotics.idl.

The component imports its servant classes from here; write each operation's body where it
says TODO. Run on its own, the module serves every interface and prints its IOR.
"""

import omniORB
from omniORB import CORBA, PortableServer
import Robot, Robot__POA.Control
import Nav, Nav__POA
class Motor_i(Robot__POA.Control.Motor):
    """Implements Robot::Control::Motor."""

    def __init__(self):
        pass

    # <rtc-template block="Motor_operations">
    # Robot::Control::Status state()
    def _get_state(self):
        # TODO: implement _get_state; it returns result
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # double speed()
    def _get_speed(self):
        # TODO: implement _get_speed; it returns result
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # void speed(in double value)
    def _set_speed(self, value):
        # TODO: implement _set_speed
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # string name()
    def name(self):
        # TODO: implement name; it returns result
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # void configure(in string key, inout string value, out string previous)
    def configure(self, key, value):
        # TODO: implement configure; it returns value, previous
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # boolean move(in Robot::Geometry::Pose target, out Robot::Geometry::Pose reached, inout Robot::Geometry::Weights gains)
    def move(self, target, gains):
        # TODO: implement move; it returns result, reached, gains
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # Robot::Geometry::PoseList trajectory(in Robot::Geometry::Path path, out Robot::Geometry::Path smoothed, inout Robot::Geometry::PoseList buffer)
    def trajectory(self, path, buffer):
        # TODO: implement trajectory; it returns result, smoothed, buffer
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # void report(out Robot::Control::Status code, out string text, inout Robot::Geometry::Vector3 drift)
    def report(self, drift):
        # TODO: implement report; it returns code, text, drift
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # RTC::TimedDoubleSeq sample(in RTC::Time at, out RTC::TimedString label)
    def sample(self, at):
        # TODO: implement sample; it returns result, label
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # </rtc-template>
class Planner_i(Nav__POA.Planner):
    """Implements Nav::Planner."""

    def __init__(self):
        pass

    # <rtc-template block="Planner_operations">
    # Robot::Control::Status state()
    def _get_state(self):
        # TODO: implement _get_state; it returns result
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # Robot::Geometry::Path plan(in Robot::Geometry::Pose start, in Robot::Geometry::Pose goal, out Robot::Geometry::Weights costs)
    def plan(self, start, goal):
        # TODO: implement plan; it returns result, costs
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # string name()
    def name(self):
        # TODO: implement name; it returns result
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # void configure(in string key, inout string value, out string previous)
    def configure(self, key, value):
        # TODO: implement configure; it returns value, previous
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # Robot::Geometry::Path replan(in Robot::Geometry::Path previous, inout Robot::Geometry::Vector3 offset, out unsigned long count)
    def replan(self, previous, offset):
        # TODO: implement replan; it returns result, offset, count
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # Robot::Control::Motor driver(in Robot::Control::Status wanted)
    def driver(self, wanted):
        # TODO: implement driver; it returns result
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # void cancel(in string reason)
    def cancel(self, reason):
        # TODO: implement cancel
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # </rtc-template>

if __name__ == "__main__":
    import sys

    orb = CORBA.ORB_init(sys.argv)
    poa = orb.resolve_initial_references("RootPOA")

    # A Robot::Control::Motor object; a client reaches it through the printed IOR.
    servant = Motor_i()
    poa.activate_object(servant)
    objref = servant._this()
    print(orb.object_to_string(objref))

    # A Nav::Planner object; a client reaches it through the printed IOR.
    servant = Planner_i()
    poa.activate_object(servant)
    objref = servant._this()
    print(orb.object_to_string(objref))

    # Serve calls until the process is stopped.
    poa._get_the_POAManager().activate()
    orb.run()

#!/usr/bin/env python3
# -*- coding: utf-8 -*-
# -*- Python -*-

"""
 @file Robotics_idl_example.py
 @brief Servant skeletons of the interfaces in Robotics.idl
"""

import omniORB
from omniORB import CORBA, PortableServer
import Robot, Robot__POA.Control
import Nav, Nav__POA
class Motor_i(Robot__POA.Control.Motor):
    """
    @class Motor_i
    Servant of IDL interface Robot::Control::Motor
    """

    def __init__(self):
        """
        @brief standard constructor
        Initialise member variables here
        """
        pass

    # <rtc-template block="Motor_operations">
    # Robot::Control::Status state()
    def _get_state(self):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result
    # double speed()
    def _get_speed(self):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result
    # void speed(in double value)
    def _set_speed(self, value):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # string name()
    def name(self):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result
    # void configure(in string key, inout string value, out string previous)
    def configure(self, key, value):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: value, previous
    # boolean move(in Robot::Geometry::Pose target, out Robot::Geometry::Pose reached, inout Robot::Geometry::Weights gains)
    def move(self, target, gains):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, reached, gains
    # Robot::Geometry::PoseList trajectory(in Robot::Geometry::Path path, out Robot::Geometry::Path smoothed, inout Robot::Geometry::PoseList buffer)
    def trajectory(self, path, buffer):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, smoothed, buffer
    # void report(out Robot::Control::Status code, out string text, inout Robot::Geometry::Vector3 drift)
    def report(self, drift):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: code, text, drift
    # RTC::TimedDoubleSeq sample(in RTC::Time at, out RTC::TimedString label)
    def sample(self, at):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, label
    # </rtc-template>
class Planner_i(Nav__POA.Planner):
    """
    @class Planner_i
    Servant of IDL interface Nav::Planner
    """

    def __init__(self):
        """
        @brief standard constructor
        Initialise member variables here
        """
        pass

    # <rtc-template block="Planner_operations">
    # Robot::Control::Status state()
    def _get_state(self):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result
    # Robot::Geometry::Path plan(in Robot::Geometry::Pose start, in Robot::Geometry::Pose goal, out Robot::Geometry::Weights costs)
    def plan(self, start, goal):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, costs
    # string name()
    def name(self):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result
    # void configure(in string key, inout string value, out string previous)
    def configure(self, key, value):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: value, previous
    # Robot::Geometry::Path replan(in Robot::Geometry::Path previous, inout Robot::Geometry::Vector3 offset, out unsigned long count)
    def replan(self, previous, offset):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result, offset, count
    # Robot::Control::Motor driver(in Robot::Control::Status wanted)
    def driver(self, wanted):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)
        # Must return: result
    # void cancel(in string reason)
    def cancel(self, reason):
        raise CORBA.NO_IMPLEMENT(0, CORBA.COMPLETED_NO)

    # </rtc-template>

if __name__ == "__main__":
    import sys

    # Initialise the ORB
    orb = CORBA.ORB_init(sys.argv)

    # As an example, we activate an object in the Root POA
    poa = orb.resolve_initial_references("RootPOA")

    # Create an instance of a servant class
    servant = Motor_i()

    # Activate it in the Root POA
    poa.activate_object(servant)

    # Get the object reference to the object
    objref = servant._this()

    # Print a stringified IOR for it
    print(orb.object_to_string(objref))

    # Create an instance of a servant class
    servant = Planner_i()

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

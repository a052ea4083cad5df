# SPDX-License-Identifier: MIT
"""OpenRTM_aist.StaticFSM_pyfsm: the same static FSM under the name of OpenRTM-aist-Python's pyfsm-based one."""

from OpenRTM_aist.StaticFSM import *  # noqa: F401,F403
from OpenRTM_aist.StaticFSM import FSM_SUBSTATE, FSM_TOPSTATE, Event, Link, Machine, State, deephistory  # noqa: F401

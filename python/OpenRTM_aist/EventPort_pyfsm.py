# SPDX-License-Identifier: MIT
"""OpenRTM_aist.EventPort_pyfsm: EventInPort under the name of OpenRTM-aist-Python's pyfsm-based one."""

from OpenRTM_aist.EventPort import EventInPort  # noqa: F401

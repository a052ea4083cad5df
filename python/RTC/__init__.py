# SPDX-License-Identifier: MIT
"""IDL module RTC as omniORBpy lays it out: RTC.TimedLong(RTC.Time(0, 0), 0), RTC.RTC_OK, …"""

import _rtstudio_idl

_rtstudio_idl.populate(globals(), "RTC")

import _rtstudio_interfaces

_rtstudio_interfaces.populate(globals(), "RTC")

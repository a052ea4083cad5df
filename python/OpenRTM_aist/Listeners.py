# SPDX-License-Identifier: MIT
"""Connector listeners as OpenRTM-aist-Python names them. A port calls a data listener as
listener(info, data) with the sample decoded, and a connector listener as listener(info)."""


class ConnectorListenerStatus(object):
    NO_CHANGE = 0
    INFO_CHANGED = 1 << 0
    DATA_CHANGED = 1 << 1
    BOTH_CHANGED = INFO_CHANGED | DATA_CHANGED


class ConnectorDataListener(object):
    def __call__(self, info, data):
        return ConnectorListenerStatus.NO_CHANGE, data


class PortType(object):
    """Which side of a connection a typed data listener is on (OpenRTM-aist-Python 2's argument)."""
    OutPortType = 0
    InPortType = 1


class ConnectorDataListenerT(ConnectorDataListener):
    """The base class of typed data listeners: samples arrive already decoded."""

    def __call__(self, info, data, data_type=None, port_type=None):
        # OpenRTM-aist-Python 2's listeners decode through the base: __call__(self, info, cdrdata,
        # RTC.TimedLong(…), PortType.InPortType) returns the sample, which here is decoded already.
        if data_type is not None:
            return data
        return ConnectorListenerStatus.NO_CHANGE, data


class ConnectorListener(object):
    def __call__(self, info):
        return ConnectorListenerStatus.NO_CHANGE

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


class ConnectorDataListenerT(ConnectorDataListener):
    """The base class of typed data listeners: samples arrive already decoded."""


class ConnectorListener(object):
    def __call__(self, info):
        return ConnectorListenerStatus.NO_CHANGE

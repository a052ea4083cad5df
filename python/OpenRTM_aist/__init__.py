# SPDX-License-Identifier: MIT
"""OpenRTM-aist-Python's component API on RT Studio's runtime (no omniORBpy): the manager, data-flow
components, data ports, service ports and connector listeners, with OpenRTM-aist-Python's names."""

import time

import RTC
import _rtstudio
from _rtstudio import ConfigurationParamListenerType, ConfigurationSetListenerType, \
    ConfigurationSetNameListenerType, ConnectorDataListenerType, ConnectorInfo, ConnectorListenerType, InPort, \
    Manager, OutPort, Properties
from OpenRTM_aist import BufferStatus, CORBA_SeqUtil, NVUtil, StringUtil
from OpenRTM_aist.StringUtil import eraseBlank, eraseBothEndsBlank, eraseHeadBlank, eraseTailBlank, normalize, \
    split, stringTo, toBool
from OpenRTM_aist.TimeValue import Time, TimeValue
from OpenRTM_aist.Async import Async_tInvoker
from OpenRTM_aist.ConfigurationListeners import ConfigurationParamListener, ConfigurationSetListener, \
    ConfigurationSetNameListener
from OpenRTM_aist.CorbaConsumer import CorbaConsumer
from OpenRTM_aist.CorbaNaming import CorbaNaming
from OpenRTM_aist.ByteDataStreamBase import ByteDataStreamBase, SerializerFactories
from OpenRTM_aist.CORBA_CdrMemoryStream import CORBA_CdrMemoryStream  # noqa: E402 (the class, as OpenRTM-aist-Python's)
from OpenRTM_aist.CorbaPort import CorbaPort
from OpenRTM_aist.DataFlowComponentBase import DataFlowComponentBase
from OpenRTM_aist.POA import POA
from OpenRTM_aist.RingBuffer import RingBuffer
from OpenRTM_aist.Listeners import ConnectorDataListener, ConnectorDataListenerT, ConnectorListener, \
    ConnectorListenerStatus, PortType
from OpenRTM_aist.CSPPort import CSPInPort, CSPManager, CSPOutPort


# The manager activates every component on one POA of its own.
Manager.getPOA = lambda manager: POA()


def setTimestamp(data):
    """Sets data.tm to the current time."""
    now = time.time()
    data.tm.sec = int(now)
    data.tm.nsec = int((now - int(now)) * 1000000000)


def instantiateDataType(dtype):
    """A new value of the IDL data type dtype (a class such as RTC.TimedLong) with every member zero or empty."""
    return _rtstudio.default_value(dtype._NP_RepositoryId)


def Delete(*args):
    """Kept for registerFactory(profile, Class, OpenRTM_aist.Delete): the runtime deletes components."""

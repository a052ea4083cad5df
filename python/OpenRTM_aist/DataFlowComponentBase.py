# SPDX-License-Identifier: MIT
"""The base class of Python data-flow components. The runtime makes an object of the class with the
manager, attaches the component's runtime side as _rtc and calls the on…() methods from its
execution context; the methods of the runtime side (addInPort, addOutPort, getInstanceName, …)
are reached through the component."""

import RTC
from OpenRTM_aist.POA import POA


class DataFlowComponentBase(object):
    def __init__(self, manager):
        self._manager = manager

    def __getattr__(self, name):
        rtc = self.__dict__.get("_rtc")
        if rtc is None:
            raise AttributeError("%s has no attribute %s (the runtime attaches the component's methods"
                                 " when the manager creates it)" % (type(self).__name__, name))
        return getattr(rtc, name)

    def _default_POA(self):
        """The POA that turns the component into its reference (servant_to_reference)."""
        return POA()

    # Methods a class names itself (Class.exit, as OpenRTM-aist-Python's Throughput example hands
    # to Async_tInvoker), so they are methods of the class rather than reached through _rtc.
    def exit(self):
        """Finalizes the component and leaves its contexts; the manager then forgets it."""
        return self._rtc.exit()

    def addInPort(self, name, inport):
        added = self._rtc.addInPort(name, inport)
        self._configurePort(inport)
        return added

    def addOutPort(self, name, outport):
        added = self._rtc.addOutPort(name, outport)
        self._configurePort(outport)
        return added

    def _configurePort(self, port):
        """Hands a port that reads settings of its own (the CSP ports) the properties it was given when
        added (rtc.conf's port.inport.<name>.*, …) and the component's logger."""
        configure = getattr(port, "_configure", None)
        if configure is not None:
            configure(port.properties(), self._rtc._rtcout)

    def activate(self, ec_id):
        return self._rtc.activate(ec_id)

    def deactivate(self, ec_id):
        return self._rtc.deactivate(ec_id)

    def reset(self, ec_id):
        return self._rtc.reset(ec_id)

    def onInitialize(self):
        return RTC.RTC_OK

    def onFinalize(self):
        return RTC.RTC_OK

    def onStartup(self, ec_id):
        return RTC.RTC_OK

    def onShutdown(self, ec_id):
        return RTC.RTC_OK

    def onActivated(self, ec_id):
        return RTC.RTC_OK

    def onDeactivated(self, ec_id):
        return RTC.RTC_OK

    def onAborting(self, ec_id):
        return RTC.RTC_OK

    def onError(self, ec_id):
        return RTC.RTC_OK

    def onReset(self, ec_id):
        return RTC.RTC_OK

    def onExecute(self, ec_id):
        return RTC.RTC_OK

    def onStateUpdate(self, ec_id):
        return RTC.RTC_OK

    def onRateChanged(self, ec_id):
        return RTC.RTC_OK

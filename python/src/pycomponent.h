// SPDX-License-Identifier: MIT
#pragma once

#include <rtm/DataFlowComponentBase.h>
#include <rtm/Manager.h>

#include <pybind11/pybind11.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace RtPython {

/**
 * The runtime's side of a Python component: an SDK DataFlowComponentBase that calls the on…()
 * methods of the Python object (an OpenRTM_aist.DataFlowComponentBase) from the runtime's
 * threads, with the GIL. A Python exception in a callback is logged with its traceback (and
 * printed on standard error) and the callback fails with RTC_ERROR, which takes the component to
 * the Error state as a failing C++ callback does.
 *
 * The bridge owns the Python object (and through it the component's ports and data); the ORB
 * owns the bridge, as it owns every servant. Python sees the bridge as `component._rtc`.
 */
class PyComponent : public RTC::DataFlowComponentBase
{
public:
    /// Creates an object of the Python class @p cls with @p manager, and its bridge. Takes the GIL.
    static PyComponent *create(RTC::Manager *manager, const pybind11::object &cls);
    ~PyComponent() override;

    /// The Python component object (None when it could not be made).
    pybind11::object pythonObject() const { return m_self ? m_self : pybind11::none(); }

    /// Adds a Python InPort or OutPort and keeps it as long as the component.
    bool addPythonInPort(const std::string &name, pybind11::object port);
    bool addPythonOutPort(const std::string &name, pybind11::object port);
    /// OpenRTM-aist-Python's addPort(): a CorbaPort (service port), InPort or OutPort, kept as long as the component.
    bool addPythonPort(pybind11::object port);
    /**
     * OpenRTM-aist-Python's bindParameter(): binds configuration parameter @p name to
     * @p variable (a list of one element, see PyParameter) with default @p defaultValue, applied
     * at once. False when the name is bound already or the default does not convert.
     */
    bool bindPythonParameter(const std::string &name, pybind11::object variable, const std::string &defaultValue,
                             pybind11::object trans);

    /// The component's logger (OpenRTM-aist-Python's `self._rtcout`).
    RTC::Logger &logger() const { return rtclog; }

    /// Notes that @p made (owned by the configuration) calls Python listener @p listener for @p kind and @p type.
    void rememberListener(int kind, int type, pybind11::handle listener, void *made);
    /// What rememberListener() noted for @p listener, forgotten now; null when nothing was.
    void *takeListener(int kind, int type, pybind11::handle listener);

    RTC::ReturnCode_t onInitialize() override;
    RTC::ReturnCode_t onFinalize() override;
    RTC::ReturnCode_t onStartup(RTC::UniqueId ec_id) override;
    RTC::ReturnCode_t onShutdown(RTC::UniqueId ec_id) override;
    RTC::ReturnCode_t onActivated(RTC::UniqueId ec_id) override;
    RTC::ReturnCode_t onDeactivated(RTC::UniqueId ec_id) override;
    RTC::ReturnCode_t onAborting(RTC::UniqueId ec_id) override;
    RTC::ReturnCode_t onError(RTC::UniqueId ec_id) override;
    RTC::ReturnCode_t onReset(RTC::UniqueId ec_id) override;
    RTC::ReturnCode_t onExecute(RTC::UniqueId ec_id) override;
    RTC::ReturnCode_t onStateUpdate(RTC::UniqueId ec_id) override;
    RTC::ReturnCode_t onRateChanged(RTC::UniqueId ec_id) override;

private:
    explicit PyComponent(RTC::Manager *manager);

    /// Records which on…() callbacks the class implements itself (with the GIL, at creation).
    void findOwnCallbacks();
    /// Calls the Python method @p callback (if the class has one) with @p arguments.
    template <typename... Arguments>
    RTC::ReturnCode_t call(const char *callback, Arguments... arguments);
    RTC::ReturnCode_t fail(const char *callback, pybind11::error_already_set &error);

    pybind11::object m_self;
    std::vector<pybind11::object> m_ports;
    /// The callbacks the class implements; the others are DataFlowComponentBase's, which only return
    /// RTC_OK, so the execution context skips them without taking the GIL.
    std::set<std::string> m_ownCallbacks;
    std::string m_createError; ///< why the Python object could not be made (onInitialize then fails)
    /// The listeners made for Python ones, so that a remove…Listener() finds them; the made
    /// listener holds a reference to the Python object, which keeps the pointer valid.
    struct MadeListener
    {
        int kind;
        int type;
        PyObject *listener;
        void *made;
    };
    std::vector<MadeListener> m_madeListeners;
};

} // namespace RtPython

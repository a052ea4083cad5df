// SPDX-License-Identifier: MIT
/*!
 * @file data_flow_component.h
 * @brief hrtm::DataFlowComponent: the base class of HRTM components.
 *
 * @code
 * class Camera : public hrtm::DataFlowComponent {
 *   hrtm::InPort<RTC::TimedLong> m_in;   // registered in onInitialize() with addInPort()
 *   ...
 * };
 * @endcode
 */
#ifndef HRTM_DATA_FLOW_COMPONENT_H
#define HRTM_DATA_FLOW_COMPONENT_H

#include <rtm/DataFlowComponentBase.h>
// RTC::StatusKind (FSM_STATUS, …): the component observer's enumeration, which OpenRTM-aist's
// header declares again with FSM_STATUS alone; using the IDL's keeps both includable together.
#include <rtm/idl/ComponentObserverSkel.h>

#include <hrtm/component_manager.h>
#include <hrtm/defs.h>
#include <hrtm/in_port.h>
#include <hrtm/logger.h>
#include <hrtm/out_port.h>
#include <hrtm/properties.h>

#include <sys/utsname.h>

/*! A component's type name as a string: COMPONENT_NAME(Camera) is "Camera". */
#define COMPONENT_NAME(comp_name) #comp_name

namespace hrtm {
class ComponentManager;

/*! A data-flow component made by the process's manager (see ComponentManager::regist()). */
class DataFlowComponent : public RTC::DataFlowComponentBase
{
public:
    /*! A component of the process's manager. */
    DataFlowComponent();
    ~DataFlowComponent() override;
    /*! Sets the component up as RTC::RTObject_impl::initialize() does (the manager calls it). */
    RTC::ReturnCode_t initialize() override;
    /*!
     * The older HRTM spelling, still in HRTM examples that call it after create_component():
     * RTC_OK for a component the manager has initialized, otherwise initialize().
     */
    RTC::ReturnCode_t initialize(ComponentManager *manager);
    /*!
     * Reports that the component's state machine is now in @p state (FSM_STATUS): the state
     * becomes the component's FSM state, seen by observers and FSM listeners.
     */
    virtual void updateFsmStatus(RTC::StatusKind status_kind, const char *state);
};
} // namespace hrtm

#endif // HRTM_DATA_FLOW_COMPONENT_H

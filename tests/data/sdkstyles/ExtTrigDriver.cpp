// SPDX-License-Identifier: MIT
// Steps a component whose execution context is an ExtTrigExecutionContext, as OpenRTM-aist's
// ExtTrigger example and many test drivers do: activates it in its own context, then calls
// tick() on the context's OpenRTM::ExtTrigExecutionContextService COUNT times.
// Arguments: NAME_SERVER COMPONENT_PATH COUNT
#include <rtm/idl/OpenRTMSkel.h>
#include <rtm/CorbaConsumer.h>
#include <rtm/CorbaNaming.h>
#include <rtm/RTObject.h>

#include <cstdlib>
#include <iostream>

int main(int argc, char **argv)
{
    if (argc != 4) {
        std::cerr << "usage: ExtTrigDriver NAME_SERVER COMPONENT_PATH COUNT" << std::endl;
        return 2;
    }
    CORBA::ORB_var orb = CORBA::ORB_init(argc, argv);
    RTC::CorbaNaming naming(orb, argv[1]);
    RTC::CorbaConsumer<RTC::RTObject> component;
    component.setObject(naming.resolve(argv[2]));
    RTC::ExecutionContextList_var contexts = component->get_owned_contexts();
    if (contexts->length() == 0) {
        std::cerr << "ExtTrigDriver: the component owns no execution context" << std::endl;
        return 1;
    }
    RTC::CorbaConsumer<OpenRTM::ExtTrigExecutionContextService> context;
    if (!context.setObject(contexts[static_cast<CORBA::ULong>(0)])) {
        std::cerr << "ExtTrigDriver: the context is not an ExtTrigExecutionContextService" << std::endl;
        return 1;
    }
    // Activating runs one cycle of its own, as OpenRTM-aist's ExtTrigExecutionContext does.
    context->activate_component(RTC::RTObject::_duplicate(component._ptr()));
    const int count = std::atoi(argv[3]);
    for (int i = 0; i < count; ++i)
        context->tick();
    std::cout << "ExtTrigDriver ticked " << count << std::endl;
    orb->destroy();
    return 0;
}

// SPDX-License-Identifier: MIT
// The factory profile every style component shares but for its name.
#ifndef SDKSTYLES_STYLEPROFILE_H
#define SDKSTYLES_STYLEPROFILE_H

#include <rtm/Manager.h>

#define SDKSTYLES_SPEC(NAME)                                                                                 \
    static const char *const NAME##_spec[] = {"implementation_id", #NAME, "type_name", #NAME, "description", \
                                              "SDK style test", "version", "1.0.0", "vendor", "RTStudioTests", \
                                              "category", "Test", "activity_type", "PERIODIC", "kind",         \
                                              "DataFlowComponent", "max_instance", "8", "language", "C++",     \
                                              "lang_type", "compile", ""}

/// Registers @p Type as <Name> with the profile above (the body of <Name>Init).
template <class Type>
void registerStyle(RTC::Manager *manager, const char *const *spec)
{
    coil::Properties profile(spec);
    manager->registerFactory(profile, RTC::Create<Type>, RTC::Delete<Type>);
}

#endif

// SPDX-License-Identifier: MIT
// Periodic task implementations by name.
#ifndef RTC_PERIODICTASKFACTORY_H
#define RTC_PERIODICTASKFACTORY_H

#include <coil/PeriodicTaskBase.h>

#include <string>
#include <vector>

namespace RTC
{
/**
 * The periodic task implementations by name (OpenRTM's coil::GlobalFactory of
 * coil::PeriodicTaskBase): `default` is coil::PeriodicTask.
 */
class PeriodicTaskFactory
{
public:
    using Creator = coil::PeriodicTaskBase *(*)();
    using Destructor = void (*)(coil::PeriodicTaskBase *);
    enum ReturnCode
    {
        FACTORY_OK,
        FACTORY_ERROR,
        ALREADY_EXISTS,
        NOT_FOUND,
        INVALID_ARG,
        UNKNOWN_ERROR
    };

    static PeriodicTaskFactory &instance();
    bool hasFactory(const std::string &id);
    std::vector<std::string> getIdentifiers();
    ReturnCode addFactory(const std::string &id, Creator creator, Destructor destructor);
    ReturnCode removeFactory(const std::string &id);
    /// A new task @p id; null (and a message naming the known ones) when unknown.
    coil::PeriodicTaskBase *createObject(const std::string &id);
    /// Finalizes and deletes @p obj.
    ReturnCode deleteObject(coil::PeriodicTaskBase *&obj);

private:
    PeriodicTaskFactory();
    struct Private;
    Private *d;
};
} // namespace RTC

#endif // RTC_PERIODICTASKFACTORY_H

// SPDX-License-Identifier: MIT
// The base of services a manager runs inside its own process.
#ifndef RTM_LOCALSERVICEBASE_H
#define RTM_LOCALSERVICEBASE_H

#include <coil/Factory.h>
#include <coil/Properties.h>

#include <bit>
#include <chrono>
#include <list>
#include <memory>
#include <string>
#include <vector>

namespace RTM {
class LocalServiceBase;

/// A local service as its manager lists it.
class LocalServiceProfile
{
public:
    ~LocalServiceProfile();
    std::string name;
    std::string uuid;
    coil::Properties properties;
    LocalServiceBase *service;
};
using LocalServiceProfileList = std::vector<LocalServiceProfile>;

/// A service of the manager's process, set up from `manager.local_service.*` properties.
class LocalServiceBase
{
public:
    virtual ~LocalServiceBase() = default;
    virtual bool init(const coil::Properties &props) = 0;
    virtual bool reinit(const coil::Properties &props) = 0;
    virtual const LocalServiceProfile &getProfile() const = 0;
    virtual void finalize() = 0;
};

/// Local services by name.
using LocalServiceFactory = ::coil::GlobalFactory<::RTM::LocalServiceBase>;
} // namespace RTM

#endif // RTM_LOCALSERVICEBASE_H

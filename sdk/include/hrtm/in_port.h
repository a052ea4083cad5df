// SPDX-License-Identifier: MIT
/*!
 * @file in_port.h
 * @brief hrtm::InPort: RTC::InPort under HRTM's name.
 */
#ifndef HRTM_IN_PORT_H
#define HRTM_IN_PORT_H

#include <rtm/InPort.h>

#include <sys/utsname.h>

namespace hrtm {
#ifndef CXX11
/*! A data input port bound to @p data (see RTC::InPort). */
template<class DataType> class InPort : public RTC::InPort<DataType>
{
public:
    InPort(const char *name, DataType &data)
        : RTC::InPort<DataType>(name, data)
    { }
    virtual ~InPort() = default;
};
#else
template<class DataType> using InPort = RTC::InPort<DataType>;
#endif
} // namespace hrtm

#endif // HRTM_IN_PORT_H

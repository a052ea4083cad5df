// SPDX-License-Identifier: MIT
/*!
 * @file out_port.h
 * @brief hrtm::OutPort: RTC::OutPort under HRTM's name.
 */
#ifndef HRTM_OUT_PORT_H
#define HRTM_OUT_PORT_H

#include <rtm/OutPort.h>

#include <sys/utsname.h>

namespace hrtm {
#ifndef CXX11
/*! A data output port bound to @p data (see RTC::OutPort). */
template<class DataType> class OutPort : public RTC::OutPort<DataType>
{
public:
    OutPort(const char *name, DataType &data)
        : RTC::OutPort<DataType>(name, data)
    { }
    virtual ~OutPort() = default;
};
#else
template<class DataType> using OutPort = RTC::OutPort<DataType>;
#endif
} // namespace hrtm

#endif // HRTM_OUT_PORT_H

// SPDX-License-Identifier: MIT
// OpenRTM-aist's shared-memory transport of data ports, which RT Studio's runtime does not have.
#ifndef RTC_SHAREDMEMORYPORT_H
#define RTC_SHAREDMEMORYPORT_H

#include <rtm/ByteData.h>
#include <rtm/Manager.h>
#include <rtm/SystemLogger.h>

#include <rtmruntime/inportconnector.h> // OpenRTM::PortStatus

#include <fcntl.h>
#include <string>
#include <sys/mman.h>
#include <sys/stat.h>

namespace RTC {
/**
 * The shared memory area of a `shared_memory` connection. RT Studio's data ports carry
 * corba_cdr only: the class exists so that code naming it builds, and each operation logs an
 * error naming the `shared_memory` interface type (put/get answer PORT_ERROR).
 */
class SharedMemoryPort
{
public:
    SharedMemoryPort();
    virtual ~SharedMemoryPort();
    /// A size such as `2M`, `512k` or `1024` in bytes (0 when it does not read).
    virtual int string_to_MemorySize(std::string size_str);
    virtual void create_memory(::CORBA::ULongLong memory_size, const char *shm_address);
    virtual void open_memory(::CORBA::ULongLong memory_size, const char *shm_address);
    virtual void close_memory(::CORBA::Boolean unlink = false);
    virtual void write(ByteData &data);
    virtual void read(ByteData &data);
    virtual void setEndian(::CORBA::Boolean endian);
    virtual ::OpenRTM::PortStatus put();
    virtual ::OpenRTM::PortStatus get();

protected:
    bool m_endian;
    mutable Logger rtclog;
};
} // namespace RTC

#endif // RTC_SHAREDMEMORYPORT_H

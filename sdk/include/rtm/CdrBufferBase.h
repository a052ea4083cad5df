// SPDX-License-Identifier: MIT
// The buffer type of data connections: marshalled samples.
#ifndef RTC_CDRBUFFERBASE_H
#define RTC_CDRBUFFERBASE_H

#include <coil/Factory.h>
#include <rtm/BufferBase.h>
#include <rtm/ByteData.h>
#include <rtm/RTC.h>

namespace RTC {
/// A buffer of marshalled samples (what connectors, providers and publishers keep).
using CdrBufferBase = BufferBase<ByteData>;
/// The buffers by name (`ring_buffer`, registered by CdrRingBufferInit()).
using CdrBufferFactory = ::coil::GlobalFactory<CdrBufferBase>;
} // namespace RTC

#endif // RTC_CDRBUFFERBASE_H

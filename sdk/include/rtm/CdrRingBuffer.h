// SPDX-License-Identifier: MIT
// The ring buffer of marshalled samples.
#ifndef RTC_CDRRINGBUFFER_H
#define RTC_CDRRINGBUFFER_H

#include <rtm/ByteData.h>
#include <rtm/CdrBufferBase.h>
#include <rtm/RingBuffer.h>

namespace RTC {
/// A RingBuffer of marshalled samples, with the `buffer.*` policies of RingBuffer.
using CdrRingBuffer = RingBuffer<ByteData>;
} // namespace RTC

extern "C" {
/// Registers CdrRingBuffer in CdrBufferFactory as `ring_buffer`.
void CdrRingBufferInit();
}

#endif // RTC_CDRRINGBUFFER_H

// SPDX-License-Identifier: MIT
// CDR samples arriving at an InPort: InPortCdr::put as the ORB calls it (in-process, no network),
// the connection's buffer, and the unmarshalling InPort<T>::read does.
//
// Input: one byte choosing the data type (bits 1…) and the byte order (bit 0), then the bytes
// put. Malformed bytes must make read() return false, never crash or allocate without bound.

#include "dataport.h"
#include "inportconnector.h"

#include <cstdint>
#include <memory>

namespace {

template <typename T>
void receive(const OpenRTM::CdrData &sample, bool littleEndian)
{
    auto buffer = std::make_shared<Runtime::RingBuffer>();
    Runtime::InPortCdrServant servant(buffer, {}, littleEndian);
    servant.put(sample);
    Runtime::CdrBytes bytes;
    if (buffer->read(&bytes) != Runtime::RingBuffer::Status::Ok)
        return;
    T value;
    if (Runtime::unmarshal(bytes, littleEndian, &value))
        Runtime::marshal(value, littleEndian); // what a component that forwards it does
}

using Receiver = void (*)(const OpenRTM::CdrData &, bool);

const Receiver receivers[] = {
    receive<RTC::TimedLong>,        receive<RTC::TimedDouble>,       receive<RTC::TimedString>,
    receive<RTC::TimedWString>,     receive<RTC::TimedBoolean>,      receive<RTC::TimedLongSeq>,
    receive<RTC::TimedDoubleSeq>,   receive<RTC::TimedOctetSeq>,     receive<RTC::TimedStringSeq>,
    receive<RTC::TimedWStringSeq>,  receive<RTC::TimedPose2D>,       receive<RTC::TimedPoint3D>,
    receive<RTC::CameraImage>,      receive<RTC::RangeData>,         receive<RTC::PointCloud>,
    receive<RTC::Path2D>,           receive<RTC::GPSData>,           receive<RTC::ActArrayState>,
};

} // namespace

// Strings and wide strings unmarshal through the code sets ORB_init sets up, as in every process
// that has ports.
extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
    int argc = 1;
    char name[] = "fuzz_inport";
    char *argv[] = {name, nullptr};
    static CORBA::ORB_var orb = CORBA::ORB_init(argc, argv);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    const size_t count = sizeof(receivers) / sizeof(receivers[0]);
    const Receiver receiver = receivers[(data[0] >> 1) % count];
    const bool littleEndian = data[0] & 1;
    // The bytes as the ORB hands them to put(): a sequence over memory it owns.
    const OpenRTM::CdrData sample(CORBA::ULong(size - 1), CORBA::ULong(size - 1),
                                  const_cast<CORBA::Octet *>(data + 1), false);
    receiver(sample, littleEndian);
    return 0;
}

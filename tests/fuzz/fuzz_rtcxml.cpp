// SPDX-License-Identifier: MIT
// RTC Profile XML reader (RTC.xml), then what is done with a profile that was read: validation, and
// saving as XML and YAML, which must read back.

#include "rtcvalidator.h"
#include "rtcxml.h"
#include "rtcyaml.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray text = QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(size));
    Profile::Diagnostics diagnostics;
    const std::optional<Profile::RtcProfile> profile =
        Profile::readRtcXml(text, QStringLiteral("fuzz.xml"), &diagnostics);
    if (!profile)
        return 0;
    Profile::validateRtcProfile(*profile, QStringLiteral("fuzz.xml"));
    Profile::Diagnostics again;
    if (!Profile::readRtcXml(Profile::writeRtcXml(*profile), QStringLiteral("saved.xml"), &again))
        std::abort(); // a profile we read must survive our own save
    Profile::readRtcYaml(Profile::writeRtcYaml(*profile), QStringLiteral("saved.yaml"), &again);
    return 0;
}

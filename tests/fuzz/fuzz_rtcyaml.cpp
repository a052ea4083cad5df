// SPDX-License-Identifier: MIT
// RTC Profile YAML reader (RTC Builder's dialect), then what is done with a profile that was read:
// validation, and saving as YAML and XML, which must read back.

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
        Profile::readRtcYaml(text, QStringLiteral("fuzz.yaml"), &diagnostics);
    if (!profile)
        return 0;
    Profile::validateRtcProfile(*profile, QStringLiteral("fuzz.yaml"));
    Profile::Diagnostics again;
    if (!Profile::readRtcYaml(Profile::writeRtcYaml(*profile), QStringLiteral("saved.yaml"), &again))
        std::abort(); // a profile we read must survive our own save
    Profile::readRtcXml(Profile::writeRtcXml(*profile), QStringLiteral("saved.xml"), &again);
    return 0;
}

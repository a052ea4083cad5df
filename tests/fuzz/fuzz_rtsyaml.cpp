// SPDX-License-Identifier: MIT
// RTS Profile YAML reader (rtsprofile's dialect), then what is done with a profile that was read:
// validation, and saving as YAML and XML, which must read back.

#include "rtsvalidator.h"
#include "rtsxml.h"
#include "rtsyaml.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QByteArray text = QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(size));
    Profile::Diagnostics diagnostics;
    const std::optional<Profile::RtsProfile> profile =
        Profile::readRtsYaml(text, QStringLiteral("fuzz.yaml"), &diagnostics);
    if (!profile)
        return 0;
    Profile::validateRtsProfile(*profile, QStringLiteral("fuzz.yaml"));
    Profile::Diagnostics again;
    if (!Profile::readRtsYaml(Profile::writeRtsYaml(*profile), QStringLiteral("saved.yaml"), &again))
        std::abort(); // a profile we read must survive our own save
    Profile::readRtsXml(Profile::writeRtsXml(*profile), QStringLiteral("saved.xml"), &again);
    return 0;
}
